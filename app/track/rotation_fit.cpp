/// @file
/// @brief fit_rotation: RANSAC + Kabsch (rotation_fit.h).
#include "app/track/rotation_fit.h"

#include <cmath>
#include <random>

#include "app/suggest/motion.h"

namespace vdfx::app::track {
namespace {

Eigen::Matrix3d kabsch_of(const std::vector<Eigen::Vector3d>& a,
                          const std::vector<Eigen::Vector3d>& b,
                          const std::vector<unsigned char>& use) {
  Eigen::Index n = 0;
  for (const unsigned char u : use) n += u ? 1 : 0;
  Eigen::Matrix3Xd pa(3, n), pb(3, n);
  Eigen::Index k = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (use[i]) {
      pa.col(k) = a[i];
      pb.col(k++) = b[i];
    }
  return suggest::kabsch(pa, pb);
}

/// Marks the pairs within `threshold` of `r`; returns how many.
int mark_inliers(const Eigen::Matrix3d& r, const std::vector<Eigen::Vector3d>& a,
                 const std::vector<Eigen::Vector3d>& b, double threshold,
                 std::vector<unsigned char>& inlier) {
  int n = 0;
  const double t2 = threshold * threshold;
  for (std::size_t i = 0; i < a.size(); ++i) {
    inlier[i] = (r * a[i] - b[i]).squaredNorm() <= t2 ? 1 : 0;
    n += inlier[i];
  }
  return n;
}

}  // namespace

RotationFit fit_rotation(const std::vector<Eigen::Vector3d>& a,
                         const std::vector<Eigen::Vector3d>& b, double threshold_rad,
                         int iterations) {
  const std::size_t n = a.size();
  const auto failed = [n] {
    RotationFit none;
    none.inlier.assign(n, 0);
    return none;
  };
  RotationFit fit = failed();
  if (n < static_cast<std::size_t>(kMinRotationPairs) || b.size() != n) return fit;
  std::mt19937 rng(12345);
  std::uniform_int_distribution<std::size_t> pick(0, n - 1);
  std::vector<unsigned char> sample(n, 0), marks(n, 0);
  Eigen::Matrix3d best = Eigen::Matrix3d::Identity();
  int best_count = -1;
  for (int it = 0; it < iterations; ++it) {
    const std::size_t i = pick(rng), j = pick(rng);
    // Two nearly parallel directions leave the rotation about them undetermined.
    if (i == j || std::abs(a[i].dot(a[j])) > 0.98) continue;
    std::fill(sample.begin(), sample.end(), 0);
    sample[i] = sample[j] = 1;
    const Eigen::Matrix3d r = kabsch_of(a, b, sample);
    const int count = mark_inliers(r, a, b, threshold_rad, marks);
    if (count > best_count) {
      best_count = count;
      best = r;
      if (count > static_cast<int>(0.9 * static_cast<double>(n))) break;
    }
  }
  if (best_count < kMinRotationPairs) return failed();
  // Refit on the consensus twice: the least-squares rotation may take in a few pairs the
  // two-pair hypothesis left out.
  fit.rotation = best;
  for (int pass = 0; pass < 2; ++pass) {
    fit.inliers = mark_inliers(fit.rotation, a, b, threshold_rad, fit.inlier);
    if (fit.inliers < kMinRotationPairs) return failed();
    fit.rotation = kabsch_of(a, b, fit.inlier);
  }
  fit.inliers = mark_inliers(fit.rotation, a, b, threshold_rad, fit.inlier);
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    if (fit.inlier[i]) sum += (fit.rotation * a[i] - b[i]).squaredNorm();
  fit.rms_rad = fit.inliers > 0 ? std::sqrt(sum / fit.inliers) : 0.0;
  return fit;
}

}  // namespace vdfx::app::track
