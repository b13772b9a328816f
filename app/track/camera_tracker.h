/// @file
/// @brief The camera's orientation at every frame of a 360 video from its pictures, without drift
/// (docs/anchors.md, "Camera motion"), after Kopf's key frame scheme ("360 video stabilization",
/// SIGGRAPH Asia 2016):
///  1. every frame is a small grey equirect (SphereGrid, `width` pixels per turn);
///  2. at a key frame, up to `points` corners (OpenCV's goodFeaturesToTrack) within
///     |altitude| <= max_altitude_deg are picked and followed frame by frame with pyramidal
///     Lucas-Kanade optical flow on the image padded round the seam;
///  3. every frame's rotation is fitted (RANSAC + Kabsch, rotation_fit.h) between the key frame's
///     directions of its corners and where they are now: a frame is re-anchored to its key frame,
///     never chained frame to frame; corners the fit rejects (moving subjects) are dropped;
///  4. a new key frame comes every `keyframe_spacing` frames, or sooner when fewer than half of the
///     corners are left; it is linked to the previous one by that fit, and to earlier ones (2, 4,
///     8, ... key frames back, and the first) by matching: the earlier key frame's image is turned
///     by the rotation predicted between them (equirect_warp.h), so that only the small error of
///     the prediction is left to the optical flow;
///  5. at the end the key frames' orientations are averaged over all links (rotation_graph.h), and
///     every frame's is its key frame's times its own fitted rotation.
/// A frame that could not be decoded, or where too few corners agree on a rotation (a cut, a black
/// frame), holds the previous orientation and is reported. Tracking restarts at the next frame with
/// corners: its new key frame is matched against the last key frames (allowing a larger correction
/// of the "it stayed put" prediction) and is reported held only when no match succeeds.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "app/track/sphere_grid.h"

namespace vdfx::app::track {

struct CameraTrackOptions {
  int width = 512;                 //!< analysis equirect: width x width/2 (VR180: width/2 square)
  int points = 400;                //!< corners per key frame
  int keyframe_spacing = 10;       //!< frames between key frames
  double max_altitude_deg = 70.0;  //!< nearer the poles the equirect is too stretched to track
  int coverage_deg = 360;          //!< 360, or 180 (VR180)
  double inlier_px = 2.0;          //!< RANSAC threshold, analysis pixels of arc
  int far_links = 8;               //!< links to earlier key frames besides the previous one
};

struct CameraTrack {
  /// Frame f's video-frame directions into the world (the video frame at the first frame).
  std::vector<Eigen::Quaterniond> orientation;
  std::vector<int> inliers;        //!< per frame: corners the frame's fit rests on
  std::vector<std::int64_t> held;  //!< frames with no estimate (orientation held)
  int keyframes = 0;
  int links = 0;                         //!< key frame pairs measured (previous and earlier ones)
  double worst_link_residual_deg = 0.0;  //!< after averaging: how far the links disagree
};

class CameraTracker {
 public:
  explicit CameraTracker(const CameraTrackOptions& options = {});
  ~CameraTracker();
  CameraTracker(const CameraTracker&) = delete;
  CameraTracker& operator=(const CameraTracker&) = delete;

  /// The analysis image size frames must have (CV_8UC1).
  const SphereGrid& grid() const;
  /// The next frame's analysis image; an empty Mat for a frame that could not be decoded.
  void add(const cv::Mat& grey);
  /// Averages the key frames and returns every frame's orientation.
  CameraTrack finish();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vdfx::app::track
