/// @file
/// @brief The head (cyclopean) pose the flare and grain layouts are computed from, once per frame
/// (flare-grain.md, stereo rule 2): the midpoint of the eyes in LOCAL space.
#pragma once

#include <Eigen/Core>

namespace vdfx::effects {

/// Position in metres and head-to-world rotation (columns: right, up, back).
struct HeadPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d forward() const { return -orientation.col(2); }
};

}  // namespace vdfx::effects
