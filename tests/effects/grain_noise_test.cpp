/// @file
/// @brief Improved Perlin noise and the grain random streams: permutation, lattice zeros, an
/// independent evaluation of the 2002 formulation, range, continuity, period; SplitMix64 values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "effects/grain_random.h"
#include "effects/perlin_noise.h"

namespace vdfx::effects {
namespace {

// The 2002 paper's gradient selection written the other way it is usually given: from the hash
// bits (h < 8 picks x, ...), not from a table, in double precision. Agreement with the table-based
// float code means both implement the same function.
double grad_bits(int hash, double x, double y, double z) {
  const int h = hash & 15;
  const double u = h < 8 ? x : y;
  const double v = h < 4 ? y : (h == 12 || h == 14 ? x : z);
  return ((h & 1) == 0 ? u : -u) + ((h & 2) == 0 ? v : -v);
}

double reference_noise(const std::array<std::uint8_t, 256>& perm, double x, double y, double z) {
  const auto P = [&](int i) { return static_cast<int>(perm[static_cast<std::size_t>(i & 255)]); };
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const int X = static_cast<int>(fx), Y = static_cast<int>(fy), Z = static_cast<int>(fz);
  const double dx = x - fx, dy = y - fy, dz = z - fz;
  const auto fade = [](double t) {
    return 6 * std::pow(t, 5) - 15 * std::pow(t, 4) + 10 * std::pow(t, 3);
  };
  double sum = 0.0;
  for (int c = 0; c < 8; ++c) {
    const int i = c & 1, j = (c >> 1) & 1, k = (c >> 2) & 1;
    const int h = P(P(P(X + i) + Y + j) + Z + k);
    const double wx = i ? fade(dx) : 1 - fade(dx), wy = j ? fade(dy) : 1 - fade(dy),
                 wz = k ? fade(dz) : 1 - fade(dz);
    sum += wx * wy * wz * grad_bits(h, dx - i, dy - j, dz - k);
  }
  return sum;
}

TEST(PerlinNoise, PermutationIsSeededAndComplete) {
  const PerlinNoise a(7), b(7), c(8);
  EXPECT_EQ(a.permutation(), b.permutation());
  EXPECT_NE(a.permutation(), c.permutation());
  std::set<int> values(a.permutation().begin(), a.permutation().end());
  EXPECT_EQ(values.size(), 256u);
}

TEST(PerlinNoise, GradientTableIsTheTwelveCubeEdges) {
  std::set<std::array<float, 3>> distinct;
  for (const auto& g : PerlinNoise::gradients()) {
    EXPECT_FLOAT_EQ(std::abs(g[0]) + std::abs(g[1]) + std::abs(g[2]), 2.0f);
    distinct.insert(g);
  }
  EXPECT_EQ(distinct.size(), 12u);
  // The table agrees with the hash-bit formulation on every index.
  for (int h = 0; h < 16; ++h) {
    const auto& g = PerlinNoise::gradients()[static_cast<std::size_t>(h)];
    EXPECT_EQ(grad_bits(h, 1, 0, 0), g[0]) << h;
    EXPECT_EQ(grad_bits(h, 0, 1, 0), g[1]) << h;
    EXPECT_EQ(grad_bits(h, 0, 0, 1), g[2]) << h;
  }
}

TEST(PerlinNoise, MatchesAnIndependentDoubleEvaluation) {
  const PerlinNoise n(12345);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-300.0, 700.0);
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const double x = u(rng), y = u(rng), z = u(rng);
    const double ref = reference_noise(n.permutation(), x, y, z);
    worst = std::max(worst, std::abs(ref - n(static_cast<float>(x), static_cast<float>(y),
                                             static_cast<float>(z))));
  }
  // Float inputs near 700 are rounded by up to 3e-5 lattice units; the gradient is below ~3.
  EXPECT_LT(worst, 2e-4);
}

TEST(PerlinNoise, ZeroOnTheLatticeBoundedSmoothAndPeriodic) {
  const PerlinNoise n(1);
  for (int i = -5; i < 5; ++i) EXPECT_EQ(n(float(i), float(2 * i), float(-i)), 0.0f);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<float> u(0.0f, 256.0f);
  double lo = 0, hi = 0, sum2 = 0;
  const int N = 100000;
  for (int i = 0; i < N; ++i) {
    const float x = u(rng), y = u(rng), z = u(rng);
    const float v = n(x, y, z);
    lo = std::min<double>(lo, v);
    hi = std::max<double>(hi, v);
    sum2 += v * v;
    // Continuity: a step of 1e-3 lattice units changes the value by at most a few 1e-3.
    EXPECT_LT(std::abs(n(x + 1e-3f, y, z) - v), 6e-3f);
    // Period 256 in each axis.
    EXPECT_NEAR(n(x - 256.0f, y, z), v, 1e-4f);
  }
  EXPECT_GT(lo, -1.1);
  EXPECT_LT(hi, 1.1);
  EXPECT_LT(lo, -0.6);  // it does use its range
  EXPECT_GT(hi, 0.6);
  const double rms = std::sqrt(sum2 / N);
  EXPECT_GT(rms, 0.12);
  EXPECT_LT(rms, 0.35);
}

TEST(GrainRandom, SplitMix64KnownValuesAndIndependentKeys) {
  // splitmix64 seeded with 0: the first outputs of Vigna's reference implementation.
  RandomStream s(0);
  EXPECT_EQ(s.next(), 0xe220a8397b1dcdafull);
  EXPECT_EQ(s.next(), 0x6e789e6aa1b965f4ull);
  EXPECT_EQ(s.next(), 0x06c45d188009454full);
  EXPECT_NE(random_key(1, 2, 3), random_key(2, 1, 3));
  EXPECT_NE(random_key(1, 2, 3), random_key(1, 2, 4));
  EXPECT_EQ(random_key(1, 2, 3), random_key(1, 2, 3));
  RandomStream r(random_key(5, 6, 7));
  double mean = 0.0;
  for (int i = 0; i < 10000; ++i) {
    const double v = r.uniform();
    ASSERT_GE(v, 0.0);
    ASSERT_LT(v, 1.0);
    mean += v / 10000;
  }
  EXPECT_NEAR(mean, 0.5, 0.01);
}

}  // namespace
}  // namespace vdfx::effects
