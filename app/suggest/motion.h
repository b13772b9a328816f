/// @file
/// @brief The camera's rotation between two frames of a 360 video, for the comfort vignette
/// (docs/suggest.md, "Comfort vignette"):
///  1. both frames are turned to grey and area-averaged down to `width` x `width`/2;
///  2. `points` directions spread evenly (a Fibonacci lattice) over the band |altitude| <=
///     max_altitude_deg, away from the frame's left and right edges, are tracked from the first
///     frame into the second with OpenCV's pyramidal Lucas-Kanade optical flow;
///  3. each tracked pair is turned back into two unit vectors, and the rotation that best maps the
///     first set onto the second is the least-squares (Kabsch) solution; pairs whose residual is
///     over three times the median residual (moving objects, failed tracks) are dropped and the
///     rotation is solved again.
/// A VR180 image (coverage 180) spans azimuth -90..90: its grey frame is width/2 x width/2 (the
/// same texels per degree) and its pixels' directions follow u = 0.5 + azimuth/180.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "effects/anchor.h"

namespace vdfx::app::suggest {

struct MotionOptions {
  int width = 512;                 //!< grey equirect the flow runs on (height width / 2)
  int points = 800;                //!< tracked directions
  double max_altitude_deg = 60.0;  //!< nearer the poles the equirect is too stretched to track
  int coverage_deg = 360;          //!< degrees of azimuth the frames span: 360, or 180 (VR180)
};

struct Rotation {
  Eigen::Matrix3d matrix = Eigen::Matrix3d::Identity();  //!< a direction at frame a -> frame b
  double angle_deg = 0.0;
  int tracked = 0;  //!< pairs the solution rests on (0: no estimate; angle 0)
};

/// Grey, downsampled frame (step 1) from CV_32FC3 RGB display values in [0, 1].
cv::Mat motion_frame(const cv::Mat& rgb, const MotionOptions& options);

/// Steps 2 and 3 between two motion_frame()s.
Rotation estimate_rotation(const cv::Mat& grey_a, const cv::Mat& grey_b,
                           const MotionOptions& options);

/// The camera's angular speed at each of `frames` frames, degrees per second, from recorded
/// orientations (the sidecar's `camera`): the angle of q_{f-1}^-1 q_f times `fps` (frame 0 takes
/// frame 1's; frames past the recording hold its last orientation).
std::vector<double> camera_motion_speeds(const effects::CameraMotion& camera, std::int64_t frames,
                                         double fps);

/// The least-squares rotation R minimising sum |R a_i - b_i|^2 (Kabsch), of unit vectors.
Eigen::Matrix3d kabsch(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b);

}  // namespace vdfx::app::suggest
