/// @file
/// @brief `"light": "auto"`: the flare's light found in each video frame as its brightest region,
/// tracked and smoothed over frames, measured once per frame (docs/flare.md, "Auto light").
///
/// Measurement of one frame (find_brightest_region):
///  1. area-average the equirect down to grid_width x grid_width/2 (cv::INTER_AREA) and take the
///     contract's luma Y = 0.25 R + 0.5 G + 0.25 B of the encoded values;
///  2. every grid cell weighs its solid angle (cos of its altitude); the top set is the brightest
///     cells making up top_fraction (0.1 %) of the sphere (by rank: ties beyond it stay out),
///     tau the darkest luma in it;
///  3. the peak is the maximum of Y smoothed by a 2-cell Gaussian (wrapping in azimuth), so a
///     clipped plateau peaks in its middle, not at its first cell;
///  4. the region is the top set within region_deg of the peak (another bright spot farther away is
///     another light and is ignored); its direction is the centroid of the cells' unit vectors
///     weighted by solid angle x (Y - tau), so the brightest cells dominate and cells at the
///     threshold weigh nothing; when every cell is at tau (a clipped plateau wider
///     than the top set) by solid angle alone;
///  5. no light when the region's brightest cell is below min_luma or the region's mean luma is
///     below min_contrast x the frame's mean luma (an overcast or dark frame has no sun).
/// Tracking and smoothing (AutoLightTracker::light): the light at frame f is a least-squares
/// straight-line fit, in the tangent plane at f's measurement, of the measurements of frames
/// f - window .. f that lie within max_jump_deg of it, evaluated at f. A light moving at constant
/// angular speed is followed without lag; measurement jitter is averaged out; a jump (a cut, a
/// second sun) restarts the fit. The result depends only on those frames, never on the order
/// frames were shown, so renders, replays and exports agree.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>

#include "effects/light_track.h"

namespace vdfx::effects {

/// The brightest region of one equirect frame (RGB, encoded values: CV_32FC3, or CV_8UC3 read as
/// value / 255) as a unit direction, or nullopt when nothing is bright enough.
std::optional<Eigen::Vector3d> find_brightest_region(const cv::Mat& rgb,
                                                     const AutoLightOptions& options = {});

/// The tracker fed with video frames: each frame measured by find_brightest_region.
class AutoLightTracker : public LightTrack {
 public:
  using LightTrack::LightTrack;
  /// Measures `frame` (a frame measured before is not measured again). Keeps the measurements of
  /// the most recent frames only (bounded memory).
  void observe(std::int64_t frame, const cv::Mat& rgb);
};

}  // namespace vdfx::effects
