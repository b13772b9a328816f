/// @file
/// @brief GrainSet: interpolation at the head's forward direction, refresh clock, noise phase,
/// particle key.
#include "effects/grain_layout.h"

#include <cmath>

#include "effects/grain_random.h"

namespace vdfx::effects {
namespace {
constexpr std::uint64_t kNoiseStream = 0x6e6f697365;  // "noise"
}  // namespace

std::array<Eigen::Vector3d, 2> grain_noise_offsets(std::uint64_t seed, std::int64_t refresh) {
  RandomStream rng(random_key(seed, kNoiseStream, refresh));
  std::array<Eigen::Vector3d, 2> o;
  for (auto& v : o)
    for (int a = 0; a < 3; ++a) v[a] = rng.uniform(0.0, 256.0);
  return o;
}

std::int64_t frame_display_time_ns(std::int64_t frame, double fps) {
  return static_cast<std::int64_t>(std::llround(static_cast<double>(frame) * 1.0e9 / fps));
}

GrainSet::GrainSet(std::vector<GrainEffect> effects, const InterpolationSettings& defaults,
                   double fps, const AnchorSources& anchors) {
  AnchorResolver resolve(anchors);
  for (GrainEffect& e : effects) {
    GrainInterpolator interp(e, defaults, fps);
    auto noise = std::make_shared<const PerlinNoise>(e.seed);
    AnchorFrames anchor = resolve.resolve(e.anchor).frames;
    effects_.push_back({std::move(e), std::move(interp), std::move(noise), std::move(anchor)});
  }
}

GrainParams GrainSet::params(std::size_t i, const Eigen::Vector3d& unit, std::int64_t frame) const {
  const Entry& en = effects_.at(i);
  return en.interp.evaluate(en.anchor.apply(unit, frame), frame);
}

void GrainSet::set_interpolant(std::size_t i, std::shared_ptr<const RbfInterpolator> rbf) {
  effects_.at(i).interp = GrainInterpolator(std::move(rbf));
}

std::vector<GrainFrame> GrainSet::layout(const HeadPose& head, std::int64_t display_time_ns,
                                         std::int64_t video_frame) {
  std::vector<GrainFrame> out;
  const Eigen::Vector3d forward = head.forward().normalized();
  for (std::size_t i = 0; i < effects_.size(); ++i) {
    Entry& en = effects_[i];
    const GrainEffect& e = en.effect;
    GrainFrame f;
    f.params = en.interp.evaluate(en.anchor.apply(forward, video_frame), video_frame);
    if (!(f.params.intensity > 0.0)) continue;  // neutral: no layer, no cost
    f.effect = i;
    f.style = e.style;
    f.head = head;
    f.refresh = grain_refresh_index(display_time_ns, e.settings.get(GrainSetting::RefreshMs));
    if (is_volumetric(e.style)) {
      f.particle_key = grain_particle_key(e.seed, f.refresh);
      f.settings = e.settings;
    } else {
      f.distance_m = e.settings.get(e.style == GrainStyle::Headset ? GrainSetting::PlaneM
                                                                   : GrainSetting::SphereM);
      f.cell_m = kGrainCellRad * f.distance_m * f.params.size;
      f.noise_offset = grain_noise_offsets(e.seed, f.refresh);
      f.noise = en.noise;
    }
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace vdfx::effects
