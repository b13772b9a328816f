/// @file
/// @brief Local interpolation in time (effects/rbf_windows.h): every keyframe reproduced, one
/// window is the global solve, the automatic choice, continuity across window boundaries (value
/// and slope), agreement with the global solve as the reach grows, keyframes all in one window,
/// empty windows in a gap, a still.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "effects/rbf_interpolator.h"
#include "effects/rbf_windows.h"
#include "tests/effects/rbf_test_util.h"

namespace vdfx::effects {
namespace {

using test::random_direction;
using test::random_keyframe;

constexpr double kFps = 30.0;

std::vector<Keyframe> random_set(int n, std::uint64_t seed, std::int64_t lo, std::int64_t hi,
                                 int dimension = 1) {
  std::mt19937_64 rng(seed);
  std::vector<Keyframe> k;
  for (int i = 0; i < n; ++i) k.push_back(random_keyframe(rng, dimension, lo, hi));
  return k;
}

InterpolationSettings reach(double seconds, double time_scale = 1.0) {
  InterpolationSettings s;
  s.time_scale = time_scale;
  s.reach_s = seconds;
  return s;
}

double largest_value(const std::vector<Keyframe>& k) {
  double m = 0.0;
  for (const Keyframe& kf : k)
    for (double v : kf.params) m = std::max(m, std::abs(v));
  return m;
}

void expect_reproduces(const RbfInterpolator& rbf, const std::vector<Keyframe>& k,
                       double tolerance = 1e-9) {
  const double scale = largest_value(k);
  for (std::size_t i = 0; i < k.size(); ++i) {
    const Eigen::VectorXd got = rbf.evaluate(k[i].direction, k[i].frame);
    const Eigen::VectorXd want = test::expected_value(k, i);
    ASSERT_LE((got - want).cwiseAbs().maxCoeff(), tolerance * scale)
        << "keyframe " << i << " at frame " << k[i].frame;
  }
}

/// Largest |a - b| over random views at frames [lo, hi].
double max_difference(const RbfInterpolator& a, const RbfInterpolator& b, std::int64_t lo,
                      std::int64_t hi, int views = 300, double* rms = nullptr) {
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<std::int64_t> f(lo, hi);
  double most = 0.0, sum = 0.0;
  for (int i = 0; i < views; ++i) {
    const Eigen::Vector3d n = to_unit(random_direction(rng));
    const std::int64_t frame = f(rng);
    const double d = (a.evaluate(n, frame) - b.evaluate(n, frame)).cwiseAbs().maxCoeff();
    most = std::max(most, d);
    sum += d * d;
  }
  if (rms) *rms = std::sqrt(sum / views);
  return most;
}

TEST(RbfLocal, EveryKeyframeIsReproduced) {
  const auto k = random_set(800, 1, 0, 2999, 2);
  const RbfInterpolator rbf(k, 2, reach(2.0), kFps);
  ASSERT_TRUE(rbf.local());
  EXPECT_EQ(rbf.layout().width, 60.0);
  EXPECT_FALSE(rbf.layout().automatic);
  std::int64_t lo = k.front().frame, hi = lo;
  for (const Keyframe& kf : k) lo = std::min(lo, kf.frame), hi = std::max(hi, kf.frame);
  EXPECT_EQ(rbf.layout().first, lo / 60);
  EXPECT_EQ(rbf.layout().count, hi / 60 - lo / 60 + 1);
  EXPECT_EQ(rbf.diagnostics().keyframes, 800);
  EXPECT_EQ(rbf.diagnostics().centres, 800);
  EXPECT_EQ(rbf.centres(), 800);
  EXPECT_LE(rbf.diagnostics().relative_residual, 1e-9);
  expect_reproduces(rbf, k);
}

TEST(RbfLocal, OneWindowIsTheGlobalSolve) {
  const auto k = random_set(200, 2, 0, 99);
  const RbfInterpolator global(k, 1, {}, kFps);
  const RbfInterpolator one(k, 1, reach(100.0), kFps);  // 3000 frames: one window
  ASSERT_TRUE(one.local());
  ASSERT_EQ(one.layout().count, 1);
  EXPECT_LE(max_difference(one, global, -50, 150), 1e-12);
  EXPECT_EQ(one.effective_frame(-50), 0);
  EXPECT_EQ(one.effective_frame(500), global.effective_frame(500));
}

TEST(RbfLocal, WithoutReachSetsUpToTheThresholdStayGlobal) {
  std::vector<std::int64_t> frames(kGlobalSolveMaxKeyframes);
  for (std::size_t i = 0; i < frames.size(); ++i) frames[i] = static_cast<std::int64_t>(i) * 9;
  EXPECT_FALSE(plan_windows({}, kFps, frames));
  frames.push_back(static_cast<std::int64_t>(frames.size()) * 9);
  const auto auto_layout = plan_windows({}, kFps, frames);
  ASSERT_TRUE(auto_layout);
  EXPECT_TRUE(auto_layout->automatic);
  // 64 keyframes' share of the span is 576 frames: the nearest power of two is 512.
  EXPECT_EQ(auto_layout->width, 512.0);
  EXPECT_EQ(auto_layout->count, static_cast<int>(frames.back() / 512) + 1);
  EXPECT_FALSE(plan_windows({}, kFps, std::vector<std::int64_t>{}));
  const RbfInterpolator small(random_set(100, 3, 0, 900), 1, {}, kFps);
  EXPECT_FALSE(small.local());
}

TEST(RbfLocal, AutomaticReachOfALargeSetReproducesItsKeyframes) {
  const auto k = random_set(6000, 4, 0, 17999);
  const RbfInterpolator rbf(k, 1, {}, kFps);
  ASSERT_TRUE(rbf.local());
  EXPECT_TRUE(rbf.layout().automatic);
  EXPECT_EQ(rbf.layout().width, 256.0);  // 64 * 18000 / 6000 = 192 -> 256
  expect_reproduces(rbf, k);
}

TEST(RbfLocal, WindowWeightsSumToOneAndBlendSmoothly) {
  WindowLayout l;
  l.width = 40.0;
  l.first = 2;
  l.count = 3;  // cores [80, 120), [120, 160), [160, 200)
  EXPECT_EQ(blend_at(l, 100.0).a, 0);
  EXPECT_EQ(blend_at(l, 100.0).b, 0);
  EXPECT_EQ(blend_at(l, 120.0).a, 0);
  EXPECT_EQ(blend_at(l, 120.0).b, 1);
  EXPECT_DOUBLE_EQ(blend_at(l, 120.0).weight, 0.5);
  EXPECT_EQ(blend_at(l, 70.0).b, 0);   // before the first window: it alone
  EXPECT_EQ(blend_at(l, 250.0).a, 2);  // after the last
  double previous = -1.0;
  for (double f = 110.0; f <= 130.0; f += 0.25) {
    const WindowBlend b = blend_at(l, f);
    const double w1 = b.a == 1 ? 1.0 - b.weight : (b.b == 1 ? b.weight : 0.0);
    EXPECT_GE(w1, previous);  // window 1's weight rises monotonically across the zone
    previous = w1;
  }
  // The quintic smoothstep: 0 and 1 at the ends with zero slope and curvature there.
  EXPECT_EQ(blend_weight(0.0), 0.0);
  EXPECT_EQ(blend_weight(1.0), 1.0);
  const double h = 1e-4;
  EXPECT_NEAR((blend_weight(h) - blend_weight(0.0)) / h, 0.0, 1e-6);
  EXPECT_NEAR((blend_weight(1.0) - blend_weight(1.0 - h)) / h, 0.0, 1e-6);
  EXPECT_NEAR(blend_weight(0.3) + blend_weight(0.7), 1.0, 1e-15);
}

/// Value and slope are continuous across a boundary: inside the blend zone the blended values'
/// second differences stay within the windows' own plus what their (small) disagreement adds
/// through the smoothstep, where switching from one window to the next at the boundary would
/// put the whole disagreement into one step.
TEST(RbfLocal, ContinuousInValueAndSlopeAcrossWindowBoundaries) {
  std::vector<Keyframe> k;
  std::mt19937_64 rng(6);
  for (std::int64_t f = 0; f <= 600; f += 12)
    for (int i = 0; i < 4; ++i) {
      Keyframe kf = random_keyframe(rng, 1, f, f);
      const Eigen::Vector3d n = to_unit(kf.direction);
      kf.params[0] = std::sin(f / 90.0) * n.x() + 0.5 * n.y() + 0.2 * n.z() * std::cos(f / 50.0);
      k.push_back(kf);
    }
  const RbfInterpolator rbf(k, 1, reach(2.0), kFps);  // windows of 60 frames, zones of +-15
  ASSERT_TRUE(rbf.local());
  const double d = rbf.layout().blend();
  const Eigen::Vector3d view = to_unit(Direction{33.3, 12.1});
  for (int j = 1; j + 1 < rbf.layout().count; ++j) {
    const auto b = static_cast<std::int64_t>(rbf.layout().core_start(j));
    const RbfInterpolator& wa = *rbf.windows()[static_cast<std::size_t>(j - 1)];
    const RbfInterpolator& wb = *rbf.windows()[static_cast<std::size_t>(j)];
    const auto f = [&](std::int64_t t) { return rbf.evaluate(view, t)[0]; };
    const auto sa = [&](std::int64_t t) { return wa.evaluate(view, t)[0]; };
    const auto sb = [&](std::int64_t t) { return wb.evaluate(view, t)[0]; };
    const auto delta = [&](std::int64_t t) { return sb(t) - sa(t); };
    double own = 0.0, dis = 0.0, dis1 = 0.0, dis2 = 0.0, blended = 0.0;
    for (std::int64_t t = b - 20; t <= b + 20; ++t) {
      own = std::max({own, std::abs(sa(t + 1) - 2 * sa(t) + sa(t - 1)),
                      std::abs(sb(t + 1) - 2 * sb(t) + sb(t - 1))});
      dis = std::max(dis, std::abs(delta(t)));
      dis1 = std::max(dis1, std::abs(delta(t + 1) - delta(t)));
      dis2 = std::max(dis2, std::abs(delta(t + 1) - 2 * delta(t) + delta(t - 1)));
      blended = std::max(blended, std::abs(f(t + 1) - 2 * f(t) + f(t - 1)));
    }
    // (s_a + S D)'' = s_a'' + S'' D + 2 S' D' + S D''; |S'| <= 1.875, |S''| <= 5.78 per unit.
    const double zone = 2.0 * d;
    const double bound = own + 5.78 * dis / (zone * zone) + 2 * 1.875 * dis1 / zone + dis2;
    EXPECT_LE(blended, bound * 1.01 + 1e-12) << "boundary at frame " << b;
    // The test means something: the windows disagree by far more than the blend's curvature.
    EXPECT_GT(std::abs(delta(b)), 3.0 * (blended - own)) << "boundary at frame " << b;
    EXPECT_GT(std::abs(delta(b)), 1e-6) << "boundary at frame " << b;
  }
}

TEST(RbfLocal, ApproachesTheGlobalSolveAsTheReachGrows) {
  for (const double c : {1.0, kAuthorTimeScale}) {
    const auto k = random_set(1500, 7, 0, 2999);
    InterpolationSettings g;
    g.time_scale = c;
    const RbfInterpolator global(k, 1, g, kFps);
    double previous = 1e9;
    for (const double r : {0.5, 2.0, 8.0, 32.0}) {
      double rms = 0.0;
      const RbfInterpolator local(k, 1, reach(r, c), kFps);
      max_difference(local, global, 0, 2999, 300, &rms);
      EXPECT_LT(rms, previous) << "c " << c << " reach " << r;
      previous = rms;
    }
    const RbfInterpolator whole(k, 1, reach(200.0, c), kFps);  // 6000 frames: all in each window
    EXPECT_LE(max_difference(whole, global, 0, 2999), 1e-9) << "c " << c;
  }
}

TEST(RbfLocal, KeyframesAllInOneWindow) {
  const auto k = random_set(300, 8, 100, 102);
  const RbfInterpolator global(k, 1, {}, kFps);
  const RbfInterpolator local(k, 1, reach(10.0), kFps);
  ASSERT_TRUE(local.local());
  EXPECT_EQ(local.layout().count, 1);
  EXPECT_LE(max_difference(local, global, 90, 110), 1e-12);
  // More than one window solves, crowded into three frames: refused, with where and why.
  std::vector<std::int64_t> crowded(kMaxWindowKeyframes + 10);
  for (std::size_t i = 0; i < crowded.size(); ++i)
    crowded[i] = 1000 + static_cast<std::int64_t>(i % 3);
  const auto why = window_problem({}, kFps, crowded);
  ASSERT_TRUE(why);
  EXPECT_NE(why->find("4106 keyframes between frames"), std::string::npos) << *why;
  EXPECT_NE(why->find("spread them over more frames"), std::string::npos) << *why;
  std::vector<Keyframe> many(crowded.size(), Keyframe{{0, 0}, 0, {1.0}});
  for (std::size_t i = 0; i < many.size(); ++i) {
    many[i].frame = crowded[i];
    many[i].direction.azimuth_deg = static_cast<double>(i % 360) - 179.0;
  }
  EXPECT_THROW(RbfInterpolator(many, 1, {}, kFps), std::invalid_argument);
  EXPECT_FALSE(window_problem(reach(0.01), kFps, std::vector<std::int64_t>(100, 5)));
}

TEST(RbfLocal, EmptyWindowsInAGapShareTheNearestKeyframes) {
  auto k = random_set(40, 9, 0, 90);
  const auto later = random_set(40, 10, 3000, 3090);
  k.insert(k.end(), later.begin(), later.end());
  const RbfInterpolator rbf(k, 1, reach(1.0), kFps);  // windows of 30 frames
  ASSERT_TRUE(rbf.local());
  expect_reproduces(rbf, k);
  // The windows well inside the gap see the same keyframes: one solve for all of them, holding
  // the nearest keyframes on both sides.
  const auto& w = rbf.windows();
  const std::size_t mid = 50;  // frames 1500..1529
  EXPECT_EQ(w[mid].get(), w[mid + 30].get());
  EXPECT_NE(w[0].get(), w[mid].get());
  EXPECT_GE(w[mid]->diagnostics().keyframes, 2 * static_cast<int>(kMinMarginKeyframes));
  EXPECT_LT(w[mid]->diagnostics().keyframes, 40);
  // Finite and without jumps across the gap: from frame to frame a view's value moves by steps
  // like the global solve's.
  const RbfInterpolator global(k, 1, {}, kFps);
  const Eigen::Vector3d view = to_unit(Direction{-40.0, 5.0});
  const auto largest_step = [&](const RbfInterpolator& r) {
    double step = 0.0, previous = r.evaluate(view, 60)[0];
    for (std::int64_t f = 61; f <= 3030; ++f) {
      const double v = r.evaluate(view, f)[0];
      EXPECT_TRUE(std::isfinite(v)) << f;
      step = std::max(step, std::abs(v - previous));
      previous = v;
    }
    return step;
  };
  const double local_step = largest_step(rbf), global_step = largest_step(global);
  EXPECT_LT(local_step, 1.5 * global_step) << global_step;
}

TEST(RbfLocal, AStillIsConstantOverTheClip) {
  auto k = random_set(200, 11, 0, 0);
  const RbfInterpolator rbf(k, 1, reach(0.5), kFps);
  ASSERT_TRUE(rbf.local());
  EXPECT_EQ(rbf.layout().count, 1);
  const RbfInterpolator global(k, 1, {}, kFps);
  expect_reproduces(rbf, k);
  const Eigen::Vector3d view = to_unit(Direction{70.0, -20.0});
  const double v0 = rbf.evaluate(view, 0)[0];
  EXPECT_EQ(rbf.evaluate(view, 100000)[0], v0);
  EXPECT_NEAR(v0, global.evaluate(view, 0)[0], 1e-12);
}

TEST(RbfLocal, ExtrapolatesOutsideTheSpanWhenAsked) {
  const auto k = random_set(300, 12, 100, 1000);
  InterpolationSettings s = reach(1.0);
  s.outside = TimeOutside::Extrapolate;
  const RbfInterpolator rbf(k, 1, s, kFps);
  const Eigen::Vector3d view = to_unit(Direction{10.0, 0.0});
  EXPECT_EQ(rbf.effective_frame(50), 50);
  EXPECT_NE(rbf.evaluate(view, 50)[0], rbf.evaluate(view, 100)[0]);
  EXPECT_TRUE(std::isfinite(rbf.evaluate(view, -5000)[0]));
  InterpolationSettings held = reach(1.0);
  const RbfInterpolator hold(k, 1, held, kFps);
  EXPECT_EQ(hold.evaluate(view, 50)[0], hold.evaluate(view, 100)[0]);
}

}  // namespace
}  // namespace vdfx::effects
