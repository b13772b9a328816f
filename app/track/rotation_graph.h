/// @file
/// @brief Rotation averaging over key frames: the orientations Q_i of key frames that best agree,
/// in the least-squares sense, with measured relative rotations between pairs of them (links to
/// the previous key frame and to some much earlier ones). Chaining the links one after another
/// would add each link's error to every later key frame (a random walk); the links that reach far
/// back tie later key frames to early ones directly, so the error stays bounded.
///
/// A link i -> j with rotation R says: a direction a of key frame i's video frame is R a in key
/// frame j's, i.e. R = Q_j^T Q_i. The solve minimises sum w |log(R^T Q_j^T Q_i)|^2 by Gauss-Newton
/// on right perturbations Q_i exp([d_i]x) (residual Jacobians I for i and -R^T for j, exact at the
/// solution's residual 0), with Q_0 held at its given value. Each step is one sparse symmetric
/// solve (Eigen's SimplicialLDLT): key frames times three unknowns.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace vdfx::app::track {

struct RotationLink {
  int from = 0;
  int to = 0;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  //!< Q_to^T Q_from
  double weight = 1.0;
};

/// Refines `orientations` (key frame i -> world; [0] is kept) against `links`. Every key frame
/// must be reached by links from key frame 0 (else it keeps its given value). Returns the largest
/// remaining link residual, in radians.
double average_rotations(std::vector<Eigen::Matrix3d>& orientations,
                         const std::vector<RotationLink>& links, int iterations = 4);

/// The angle of a rotation matrix, radians.
double rotation_angle(const Eigen::Matrix3d& r);

}  // namespace vdfx::app::track
