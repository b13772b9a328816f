/// @file
/// @brief The camera's orientation at every frame from a video's CAMM track (io/camm_track.h):
/// its angle-axis orientations where it has them (the device's own sensor fusion), else its
/// gyroscope integrated over time (q' = q exp(w dt / 2), w the mean of two neighbouring samples).
/// Sampled at each frame's presentation time (slerp between records, the first and last held
/// beyond them), then re-based so that frame 0 is the world (q_0 = identity), as `vdfx track
/// camera` writes every camera. The records' camera axes are taken to be the video frame's (+x
/// right, +y up, -z the equirect's centre): the specification leaves the relation of the sensor to
/// the picture to the device.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "io/camm_track.h"

namespace vdfx::app::track {

struct CammMotion {
  enum class Kind { AngleAxis, Gyro };
  Kind kind = Kind::AngleAxis;
  std::size_t records = 0;                      //!< records used
  std::vector<Eigen::Quaterniond> orientation;  //!< per frame
};

/// Throws io::InputError naming `file` when the track has neither orientations nor gyroscope
/// samples.
CammMotion camm_motion(const io::CammTrack& track, const std::vector<double>& frame_times_s,
                       const std::string& file);

/// "angle-axis orientations" or "gyroscope samples (integrated)".
const char* camm_kind_text(CammMotion::Kind kind);

}  // namespace vdfx::app::track
