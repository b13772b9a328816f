/// @file
/// @brief Writes the data of docs/figures/time_hold.png (docs/interpolation.md, "Time"): the
/// value over the clip, seen at azimuth -120 altitude 10 (between keyframes), of sets of 1, 2,
/// 3, 4 and 10
/// exposure keyframes all placed at frame 0 (alternating +1.4 and -1.4 stops at spread-out
/// directions), before (the paper: c = 1, no hold) and after (vdfx's author time scale and the
/// hold outside the keyframes' span). A second block: two sets of two keyframes at frames 0 and
/// 100, the second set turned by 90 degrees, seen at azimuth 90 and at azimuth -90. A third:
/// that value half way at azimuth 90 against the time scale (docs/interpolation.md's table).
///
/// Usage: vdfx_time_hold_figure > time_hold.csv; gnuplot docs/figures/time_hold.gp
#include <cstdio>
#include <vector>

#include "effects/rbf_interpolator.h"

using namespace vdfx::effects;

namespace {

InterpolationSettings paper() {
  InterpolationSettings s;
  s.time_scale = 1.0;
  s.outside = TimeOutside::Extrapolate;
  return s;
}

InterpolationSettings author() {
  InterpolationSettings s;
  s.time_scale = kAuthorTimeScale;
  return s;
}

std::vector<Keyframe> at_frame_zero(int n) {
  std::vector<Keyframe> ks;
  for (int i = 0; i < n; ++i) {
    // Spread over azimuth and a little in altitude; signs alternate.
    const double az = -150.0 + 300.0 * (n == 1 ? 0.5 : static_cast<double>(i) / (n - 1));
    const double alt = (i % 3 - 1) * 20.0;
    ks.push_back({{az, alt}, 0, {i % 2 == 0 ? 1.4 : -1.4}});
  }
  return ks;
}

}  // namespace

int main() {
  constexpr double kFps = 30.0;
  std::printf("# block 0: frame");
  const int counts[] = {1, 2, 3, 4, 10};
  for (const int n : counts) std::printf(",before_%d,after_%d", n, n);
  std::printf("\n");
  std::vector<RbfInterpolator> before, after;
  for (const int n : counts) {
    before.emplace_back(at_frame_zero(n), 1, paper(), kFps);
    after.emplace_back(at_frame_zero(n), 1, author(), kFps);
  }
  for (int f = 0; f < 120; ++f) {
    std::printf("%d", f);
    for (std::size_t i = 0; i < before.size(); ++i) {
      const Direction d{-120.0, 10.0};
      std::printf(",%.6f,%.6f", before[i].evaluate(d, f)[0], after[i].evaluate(d, f)[0]);
    }
    std::printf("\n");
  }
  std::printf("\n\n# block 1: frame,before_az90,after_az90,before_az-90,after_az-90\n");
  const std::vector<Keyframe> sets = {{{0.0, 0.0}, 0, {1.4}},
                                      {{180.0, 0.0}, 0, {-1.4}},
                                      {{90.0, 0.0}, 100, {1.4}},
                                      {{-90.0, 0.0}, 100, {-1.4}}};
  const RbfInterpolator b(sets, 1, paper(), kFps), a(sets, 1, author(), kFps);
  for (int f = -20; f <= 140; ++f) {
    const Direction d90{90.0, 0.0}, d0{-90.0, 0.0};
    std::printf("%d,%.6f,%.6f,%.6f,%.6f\n", f, b.evaluate(d90, f)[0], a.evaluate(d90, f)[0],
                b.evaluate(d0, f)[0], a.evaluate(d0, f)[0]);
  }
  std::printf("\n\n# block 2: deg_per_s,value_at_frame_50_azimuth_90\n");
  for (const double deg : {0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, deg_per_s_from_time_scale(1.0)}) {
    InterpolationSettings s;
    s.time_scale = time_scale_from_deg_per_s(deg);
    const RbfInterpolator r(sets, 1, s, kFps);
    std::printf("%.1f,%.3f\n", deg, r.evaluate(Direction{90.0, 0.0}, 50)[0]);
  }
  return 0;
}
