/// @file
/// @brief Sampling an equirect image at a direction (contract: u = 0.5 + az/360, v = 0.5 -
/// alt/180).
///
/// Images are RGB (not OpenCV's BGR: io converts at load time), CV_32FC3, encoded values (no
/// linearisation). Bilinear filtering with texel centres at (i + 0.5) / W: columns wrap at the
/// azimuth seam (column W-1 blends with column 0), rows are clamped at the poles (as GL's
/// CLAMP_TO_EDGE would) or, optionally, continued across the pole (row -1 is row 0 seen from the
/// opposite azimuth).
///
/// A view pixel (sample_pixel) is, by default, the image filtered over the pixel's footprint
/// (effects/pixel_footprint.h): taps along the footprint's major axis, each trilinear in the
/// area-average mip chain (effects/mip_chain.h) at the level of the minor axis. Near the poles a
/// view pixel covers many equirect columns (a row's length shrinks with cos(altitude)) and few
/// rows; the taps spread along the row without blurring across rows. The GPU's video layer
/// computes the same taps from the same chain (docs/effects.md, "Sampling a view").
///
/// Coverage (effects/stereo_layout.h): a 360 image spans azimuth -180..180 and wraps; a 180
/// (VR180) image spans -90..90: its columns are clamped, never wrapped, and a sample is weighted
/// by coverage_weight() (black outside, a kCoverageEdgeDeg fade inside the edge). A stereo frame
/// is sampled one eye at a time: the sampler is built on that eye's half only, so no filter ever
/// reads the other eye's pixels.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "effects/pixel_footprint.h"
#include "effects/stereo_layout.h"
#include "effects/view_camera.h"

namespace vdfx::effects {

enum class SampleFilter {
  Bilinear,   //!< level 0 at the pixel centre (aliases where the view shrinks the image)
  Footprint,  //!< the pixel's footprint filtered from the mip chain (pixel_footprint.h)
};

enum class PoleRows {
  Clamp,       //!< rows beyond the first/last texel centre repeat it (GL CLAMP_TO_EDGE)
  AcrossPole,  //!< row -1 is row 0 at azimuth + 180 degrees (continuous across the pole)
};

struct SamplerOptions {
  SampleFilter filter = SampleFilter::Footprint;
  PoleRows pole_rows = PoleRows::Clamp;
  /// Degrees of azimuth the image spans, centred on azimuth 0: 360 or 180.
  int coverage_deg = 360;
  /// Footprint: the largest ratio of the footprint's axes resolved by taps (>= 1).
  double max_anisotropy = kDefaultMaxAnisotropy;
};

class EquirectSampler {
 public:
  /// `equirect` must be a non-empty CV_32FC3 RGB image; it is shared, not copied (do not modify
  /// it while the sampler lives). Throws std::invalid_argument otherwise.
  explicit EquirectSampler(const cv::Mat& equirect, SamplerOptions options = {});

  /// Bilinear sample at level 0 at a (non-zero, not necessarily unit) world direction.
  Eigen::Vector3d sample(const Eigen::Vector3d& dir) const;
  /// The view pixel of `camera` centred at continuous pixel position (x, y): filtered over its
  /// footprint (Footprint) or bilinear at (x, y) (Bilinear); times the coverage weight there.
  Eigen::Vector3d sample_pixel(const ViewCamera& camera, double x, double y) const;
  /// Bilinear sample at the image's texture coordinates (u wraps for coverage 360 and is clamped
  /// for 180, v per PoleRows) on a mip level; no coverage weight.
  Eigen::Vector3d sample_uv(double u, double v, int level = 0) const;
  /// Trilinear sample (GL's LINEAR_MIPMAP_LINEAR at level of detail `lod`: level 0 bilinear for
  /// lod <= 0, the last level beyond the chain, else a blend of the two levels around lod).
  Eigen::Vector3d sample_lod(double u, double v, double lod) const;

  int width() const { return width_; }
  int height() const { return height_; }
  int levels() const { return static_cast<int>(levels_.size()); }  //!< 1 without the chain
  const SamplerOptions& options() const { return options_; }

 private:
  Eigen::Vector3d footprint_sample(const ViewCamera& camera, double x, double y) const;
  Eigen::Vector3d row_lerp(const cv::Mat& img, int row, double x) const;
  /// The image's u of a direction's equirect u, and the coverage weight there.
  double image_u(double u) const;
  double weight(double u) const;

  SamplerOptions options_;
  int width_ = 0, height_ = 0;
  std::vector<cv::Mat> levels_;  //!< the mip chain (level 0 only for Bilinear)
};

/// `eye`'s image in a frame of `layout` (mono: the frame): a view into `frame`, not a copy. The
/// layout must divide the frame (effects::layout_problem).
cv::Mat eye_image(const cv::Mat& frame, const StereoLayout& layout, EyeIndex eye);

/// Sampler options for an eye's image of `layout` (its coverage), the rest as `base`.
SamplerOptions sampler_options_for(const StereoLayout& layout, SamplerOptions base = {});

/// Equirect texture coordinates of a world direction (u in [0, 1), v in [0, 1]).
Eigen::Vector2d direction_to_uv(const Eigen::Vector3d& dir);

}  // namespace vdfx::effects
