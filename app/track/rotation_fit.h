/// @file
/// @brief The rotation that maps one set of unit vectors onto another, robust to pairs that do not
/// follow it (moving subjects, tracks that slipped): RANSAC over two-pair samples, then the
/// least-squares (Kabsch) rotation of the pairs within the threshold, refitted once. Deterministic
/// (a fixed seed): the same pairs give the same rotation.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace vdfx::app::track {

/// Fewer pairs than this give no rotation.
inline constexpr int kMinRotationPairs = 8;

struct RotationFit {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  //!< R with b ~ R a
  std::vector<unsigned char> inlier;                       //!< per pair
  int inliers = 0;
  double rms_rad = 0.0;  //!< |R a - b| over the inliers
  bool ok() const { return inliers >= kMinRotationPairs; }
};

/// `a` and `b` are unit vectors of the same length; `threshold_rad` the largest |R a - b| of an
/// inlier (radians of arc, as the vectors are unit).
RotationFit fit_rotation(const std::vector<Eigen::Vector3d>& a,
                         const std::vector<Eigen::Vector3d>& b, double threshold_rad,
                         int iterations = 64);

}  // namespace vdfx::app::track
