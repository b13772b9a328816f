/// @file
/// @brief video_frame_pose (stabilized_view.h).
#include "app/window/stabilized_view.h"

#include <Eigen/Geometry>
#include <glm/gtc/quaternion.hpp>

namespace vdfx::app {

xr::Pose video_frame_pose(const xr::Pose& pose, const effects::AnchorFrames& world,
                          std::int64_t frame) {
  if (world.identity()) return pose;
  // q_f^-1: the rotation matrix of q_f transposed.
  const Eigen::Quaterniond undo(Eigen::Matrix3d(world.at(frame).transpose()));
  const glm::dquat u(undo.w(), undo.x(), undo.y(), undo.z());
  return {u * pose.position, glm::normalize(u * pose.orientation)};
}

}  // namespace vdfx::app
