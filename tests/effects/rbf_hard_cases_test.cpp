/// @file
/// @brief numerics.md's hard-case table: every row must reproduce its keyframes (~1e-9 relative,
/// merged duplicates: their mean) and give finite values everywhere, solved globally and
/// interpolated locally in time.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <tuple>

#include "effects/rbf_interpolator.h"
#include "tests/effects/rbf_test_util.h"

namespace vdfx::effects {
namespace {

using test::random_direction;
using test::random_keyframe;

constexpr int kDim = 3;

std::vector<Keyframe> random_set(int n, std::uint64_t seed, std::int64_t lo = 0,
                                 std::int64_t hi = 300) {
  std::mt19937_64 rng(seed);
  std::vector<Keyframe> k;
  for (int i = 0; i < n; ++i) k.push_back(random_keyframe(rng, kDim, lo, hi));
  return k;
}

std::vector<Keyframe> with_direction(std::vector<Keyframe> k, std::function<Direction(int)> dir) {
  for (size_t i = 0; i < k.size(); ++i) k[i].direction = dir(static_cast<int>(i));
  return k;
}

std::vector<Keyframe> distinct_frames(std::vector<Keyframe> k) {
  for (size_t i = 0; i < k.size(); ++i) k[i].frame = static_cast<std::int64_t>(10 * i);
  return k;
}

std::vector<Keyframe> with_frame(std::vector<Keyframe> k, std::int64_t frame) {
  for (auto& kf : k) kf.frame = frame;
  return k;
}

std::vector<Keyframe> duplicates() {
  auto k = random_set(10, 7);
  for (int i = 0; i < 3; ++i) {  // same place and frame, different values
    Keyframe d = k[static_cast<size_t>(i)];
    for (auto& p : d.params) p = 4.0 - p;
    k.push_back(d);
  }
  return k;
}

/// Values of a smooth field: what a pair of nearby keyframes of a real edit looks like.
void smooth_values(std::vector<Keyframe>& k) {
  for (auto& kf : k) {
    const Eigen::Vector3d n = to_unit(kf.direction);
    for (int i = 0; i < kDim; ++i)
      kf.params[static_cast<size_t>(i)] = 2.0 + std::sin(3 * n.x() + i) * n.y() + 0.01 * kf.frame;
  }
}

std::vector<Keyframe> close_pairs(bool smooth) {
  auto k = random_set(10, 11);
  for (size_t i = 0; i < 5; ++i) {  // keyframe 5+i sits 1e-7 rad from keyframe i
    k[5 + i].frame = k[i].frame;
    k[5 + i].direction = {k[i].direction.azimuth_deg,
                          k[i].direction.altitude_deg + 1e-7 * kRadToDeg};
  }
  if (smooth) smooth_values(k);
  return k;
}

std::vector<Keyframe> seam_and_poles() {
  auto k = random_set(12, 13, 0, 10);
  const Direction dirs[] = {{180.0, 0.0},   {-179.99, 0.0}, {179.99, 5.0}, {-179.5, -5.0},
                            {0.0, 90.0},    {45.0, 90.0},   {170.0, 90.0}, {-30.0, -90.0},
                            {100.0, -90.0}, {180.0, 89.9},  {90.0, -89.9}, {0.0, 0.0}};
  for (size_t i = 0; i < k.size(); ++i) k[i].direction = dirs[i];
  // The pole keyframes share a frame: each pole is one point whatever the azimuth.
  for (size_t i = 4; i < 9; ++i) k[i].frame = 5;
  return k;
}

struct Row {
  std::string name;
  std::function<std::vector<Keyframe>()> make;
  double alpha = 1.0;
  int merged = 0;  //!< expected merged count
  int max_terms = 5;
  AngularDistance distance = AngularDistance::Chordal;
  double fps = 30.0;
  /// Reproduction tolerance relative to the largest value. 1e-9 everywhere but for O(1) value
  /// jumps across 1e-7 rad: weights ~ jump / 1e-7 and their rounding alone leaves
  /// ~ m eps |jump| / 1e-7 (docs/interpolation.md, "Conditioning floor").
  double tolerance = 1e-9;
};

const std::vector<Row>& rows() {
  static const std::vector<Row> r = {
      {"one", [] { return random_set(1, 1); }, 1.0, 0, 1},
      {"two", [] { return random_set(2, 2); }, 1.0, 0, 1},
      {"three", [] { return random_set(3, 3); }},
      {"four", [] { return random_set(4, 4); }},
      {"five", [] { return random_set(5, 5); }},
      {"all_one_frame", [] { return with_frame(random_set(20, 6), 42); }, 1.0, 0, 4},
      {"all_on_horizon",
       [] {
         return with_direction(random_set(20, 8), [](int i) {
           return Direction{i * 17.0 - 170, 0};
         });
       },
       1.0, 0, 4},
      {"horizon_one_frame",
       [] {
         return with_frame(with_direction(random_set(20, 9),
                                          [](int i) {
                                            return Direction{i * 17.0 - 170, 0};
                                          }),
                           3);
       },
       1.0, 0, 3},
      {"one_direction",
       [] {
         return distinct_frames(with_direction(random_set(10, 10), [](int) {
           return Direction{30, 20};
         }));
       },
       1.0, 0, 2},
      {"one_direction_at_pole",
       [] {
         return distinct_frames(with_direction(random_set(10, 10), [](int i) {
           return Direction{i * 30.0, 90};
         }));
       },
       1.0, 0, 2},
      {"duplicates", duplicates, 1.0, 3},
      {"pairs_1e-7_rad", [] { return close_pairs(true); }},
      {"pairs_1e-7_rad_value_jump", [] { return close_pairs(false); }, 1.0, 0, 5,
       AngularDistance::Chordal, 30.0, 1e-7},
      {"seam_and_poles", seam_and_poles, 1.0, 3},
      {"alpha_0.25", [] { return random_set(30, 20); }, 0.25},
      {"alpha_0.5", [] { return random_set(30, 21); }, 0.5},
      {"alpha_1", [] { return random_set(30, 22); }, 1.0},
      {"alpha_1.5", [] { return random_set(30, 23); }, 1.5},
      {"alpha_1.99", [] { return random_set(30, 24); }, 1.99},
      {"alpha_2_thin_plate", [] { return random_set(30, 25); }, 2.0},
      {"alpha_3", [] { return random_set(30, 26); }, 3.0},
      {"alpha_3_one_frame", [] { return with_frame(random_set(30, 27), 0); }, 3.0, 0, 4},
      {"alpha_2_horizon_one_frame",
       [] {
         return with_frame(with_direction(random_set(12, 28),
                                          [](int i) {
                                            return Direction{i * 29.0 - 170, 0};
                                          }),
                           0);
       },
       2.0, 0, 3},
      {"frames_near_1e6", [] { return random_set(40, 30, 999'000, 1'001'000); }, 1.0, 0, 5,
       AngularDistance::Chordal, 120.0},
      {"frames_near_1e6_adjacent", [] { return random_set(40, 31, 999'990, 1'000'010); }},
      {"geodesic_alpha_1", [] { return random_set(30, 32); }, 1.0, 0, 5, AngularDistance::Geodesic},
      {"geodesic_alpha_1.5", [] { return random_set(30, 33); }, 1.5, 0, 5,
       AngularDistance::Geodesic},
      {"n_1000", [] { return random_set(1000, 40, 0, 3000); }},
      {"n_5000", [] { return random_set(5000, 41, 0, 9000); }},
  };
  return r;
}

/// Each row globally (as the settings choose: n_5000 is above the automatic threshold and is
/// interpolated locally) and locally in time with a short reach (windows of a fifth of a second).
class RbfHardCases : public ::testing::TestWithParam<std::tuple<size_t, bool>> {};

TEST_P(RbfHardCases, ReproducesKeyframesAndStaysFinite) {
  const Row& row = rows()[std::get<0>(GetParam())];
  const std::vector<Keyframe> k = row.make();
  InterpolationSettings s;
  s.exponent = row.alpha;
  s.distance = row.distance;
  if (std::get<1>(GetParam())) s.reach_s = 0.2;
  const RbfInterpolator rbf(k, kDim, s, row.fps);
  EXPECT_EQ(rbf.local(), s.reach_s || k.size() > kGlobalSolveMaxKeyframes);
  const RbfDiagnostics& dg = rbf.diagnostics();
  EXPECT_EQ(dg.keyframes, static_cast<int>(k.size()));
  EXPECT_EQ(dg.merged, row.merged);
  EXPECT_LE(dg.active_terms, row.max_terms);
  EXPECT_GE(dg.active_terms, 1);
  EXPECT_LE(dg.relative_residual, row.tolerance) << to_string(dg.method);

  double scale = 0.0;
  for (const auto& kf : k)
    for (double v : kf.params) scale = std::max(scale, std::abs(v));
  // Reproduction at every keyframe (all of them below 1000; a stride above, for speed).
  const size_t stride = k.size() > 1000 ? 7 : 1;
  for (size_t i = 0; i < k.size(); i += stride) {
    const Eigen::VectorXd got = rbf.evaluate(k[i].direction, k[i].frame);
    const Eigen::VectorXd want = test::expected_value(k, i);
    ASSERT_LE((got - want).cwiseAbs().maxCoeff(), row.tolerance * scale)
        << row.name << " keyframe " << i << " got " << got.transpose() << " want "
        << want.transpose();
  }
  // Finite everywhere, including poles, the seam and frames outside the keyframes' range.
  std::mt19937_64 rng(99);
  std::int64_t lo = k.front().frame, hi = lo;
  for (const auto& kf : k) lo = std::min(lo, kf.frame), hi = std::max(hi, kf.frame);
  std::uniform_int_distribution<std::int64_t> f(lo - 100, hi + 100);
  for (int i = 0; i < 300; ++i) {
    Direction d = random_direction(rng);
    if (i % 10 == 0) d.altitude_deg = (i % 20 == 0) ? 90.0 : -90.0;
    if (i % 10 == 1) d.azimuth_deg = 180.0;
    const Eigen::VectorXd v = rbf.evaluate(d, f(rng));
    ASSERT_TRUE(v.allFinite()) << row.name << " at az " << d.azimuth_deg << " alt "
                               << d.altitude_deg;
  }
}

INSTANTIATE_TEST_SUITE_P(Table, RbfHardCases,
                         ::testing::Combine(::testing::Range<size_t>(0, rows().size()),
                                            ::testing::Bool()),
                         [](const auto& info) {
                           std::string n = rows()[std::get<0>(info.param)].name;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n + (std::get<1>(info.param) ? "_local" : "");
                         });

TEST(RbfInterpolator, NoKeyframesReturnsTheCallersNeutral) {
  const RbfInterpolator rbf({}, 2, {}, 30.0, {180.0, 0.01});
  EXPECT_TRUE(rbf.empty());
  EXPECT_EQ(rbf.diagnostics().method, RbfSolveMethod::Empty);
  const Eigen::VectorXd v = rbf.evaluate(Direction{10, 20}, 5);
  ASSERT_EQ(v.size(), 2);
  EXPECT_EQ(v[0], 180.0);
  EXPECT_EQ(v[1], 0.01);
}

TEST(RbfInterpolator, SingleKeyframeIsConstantEverywhere) {
  const std::vector<Keyframe> k = {{{30, 10}, 5, {1.5}}};
  const RbfInterpolator rbf(k, 1, {}, 30.0);
  EXPECT_DOUBLE_EQ(rbf.evaluate(Direction{-150, -80}, 900)[0], 1.5);
}

TEST(RbfInterpolator, PolynomialDropsWhatTheKeyframesDoNotDetermine) {
  auto k = with_frame(random_set(20, 50), 7);
  const RbfInterpolator one_frame(k, kDim, {}, 30.0);
  EXPECT_FALSE(one_frame.basis().has(PolynomialBasis::T));
  EXPECT_TRUE(one_frame.basis().has(PolynomialBasis::One));
  for (auto& kf : k) kf.direction.altitude_deg = 0.0;
  const RbfInterpolator horizon(k, kDim, {}, 30.0);
  EXPECT_FALSE(horizon.basis().has(PolynomialBasis::Y));
  EXPECT_EQ(horizon.diagnostics().active_terms, 3);  // 1, x, z
}

TEST(RbfInterpolator, RejectsSettingsOutsideTheAcceptedRanges) {
  const std::vector<Keyframe> k = {{{0, 0}, 0, {1.0}}};
  for (double a : {0.0, -1.0, 4.0, 5.0, std::nan("")}) {
    InterpolationSettings s;
    s.exponent = a;
    EXPECT_THROW(RbfInterpolator(k, 1, s, 30.0), std::invalid_argument) << a;
  }
  InterpolationSettings s;
  s.time_scale = 0.0;
  EXPECT_THROW(RbfInterpolator(k, 1, s, 30.0), std::invalid_argument);
  EXPECT_THROW(RbfInterpolator(k, 1, {}, 0.0), std::invalid_argument);
  EXPECT_THROW(RbfInterpolator(k, 2, {}, 30.0), std::invalid_argument);  // wrong param count
}

TEST(RbfInterpolator, FrameDifferencesNearAMillionKeepEveryBit) {
  // Two keyframes one frame apart at frame ~1e6 and the view between them in time: a solver
  // that converted frames to double after scaling would blur them; here the two ends differ.
  const std::vector<Keyframe> k = {{{0, 0}, 1'000'000, {0.0}}, {{0, 0}, 1'000'001, {1.0}}};
  const RbfInterpolator rbf(k, 1, {}, 30.0);
  EXPECT_NEAR(rbf.evaluate(Direction{0, 0}, 1'000'000)[0], 0.0, 1e-12);
  EXPECT_NEAR(rbf.evaluate(Direction{0, 0}, 1'000'001)[0], 1.0, 1e-12);
}

}  // namespace
}  // namespace vdfx::effects
