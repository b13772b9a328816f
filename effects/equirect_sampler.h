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
/// Near the poles one view pixel covers many equirect columns (a row's length shrinks with
/// cos(altitude)), so plain bilinear sampling aliases there. The area-aware filter keeps a
/// "ripmap": levels (lx, ly) of width W / 2^lx and height H / 2^ly (ly <= lx, box-averaged with
/// cv::resize INTER_AREA), and picks lx from the footprint's horizontal extent in texels and ly
/// from its vertical extent, blending linearly between neighbouring levels (4 bilinear lookups).
/// The horizontal level can thus grow towards the poles without blurring vertically.
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

#include "effects/stereo_layout.h"

namespace vdfx::effects {

enum class SampleFilter {
  Bilinear,   //!< level 0 only
  AreaAware,  //!< ripmap level chosen from the pixel footprint
};

enum class PoleRows {
  Clamp,       //!< rows beyond the first/last texel centre repeat it (GL CLAMP_TO_EDGE)
  AcrossPole,  //!< row -1 is row 0 at azimuth + 180 degrees (continuous across the pole)
};

struct SamplerOptions {
  SampleFilter filter = SampleFilter::AreaAware;
  PoleRows pole_rows = PoleRows::Clamp;
  /// Degrees of azimuth the image spans, centred on azimuth 0: 360 or 180.
  int coverage_deg = 360;
};

/// Extent of one view pixel in level-0 equirect texels.
struct Footprint {
  double du_texels = 0.0;  //!< horizontal (azimuth) extent
  double dv_texels = 0.0;  //!< vertical (altitude) extent
};

class EquirectSampler {
 public:
  /// `equirect` must be a non-empty CV_32FC3 RGB image; it is shared, not copied (do not modify
  /// it while the sampler lives). Throws std::invalid_argument otherwise.
  explicit EquirectSampler(const cv::Mat& equirect, SamplerOptions options = {});

  /// Bilinear sample at level 0 at a (non-zero, not necessarily unit) world direction.
  Eigen::Vector3d sample(const Eigen::Vector3d& dir) const;
  /// Sample whose filter width follows `footprint` (level 0 bilinear when filter is Bilinear).
  Eigen::Vector3d sample(const Eigen::Vector3d& dir, const Footprint& footprint) const;
  /// Bilinear sample at the image's texture coordinates (u wraps for coverage 360 and is clamped
  /// for 180, v per PoleRows) on a ripmap level; no coverage weight.
  Eigen::Vector3d sample_uv(double u, double v, int level_x = 0, int level_y = 0) const;

  /// Footprint of a pixel whose ray is `dir` and whose right and lower neighbours' rays are
  /// `dir_dx` and `dir_dy` (finite differences, as GPU derivatives are); the azimuth difference
  /// is taken the short way round the seam.
  Footprint footprint(const Eigen::Vector3d& dir, const Eigen::Vector3d& dir_dx,
                      const Eigen::Vector3d& dir_dy) const;

  int width() const { return width_; }
  int height() const { return height_; }
  int max_level_x() const { return max_lx_; }  //!< 0 without the ripmap
  int max_level_y() const { return max_ly_; }
  const SamplerOptions& options() const { return options_; }

 private:
  const cv::Mat& level(int lx, int ly) const;
  Eigen::Vector3d row_lerp(const cv::Mat& img, int row, double x) const;
  /// The image's u of a direction's equirect u, and the coverage weight there.
  double image_u(double u) const;
  double weight(double u) const;

  SamplerOptions options_;
  int width_ = 0, height_ = 0;
  int max_lx_ = 0, max_ly_ = 0;
  std::vector<std::vector<cv::Mat>> levels_;  //!< levels_[ly][lx - ly]
};

/// `eye`'s image in a frame of `layout` (mono: the frame): a view into `frame`, not a copy. The
/// layout must divide the frame (effects::layout_problem).
cv::Mat eye_image(const cv::Mat& frame, const StereoLayout& layout, EyeIndex eye);

/// Sampler options for an eye's image of `layout` (its coverage), the rest as `base`.
SamplerOptions sampler_options_for(const StereoLayout& layout, SamplerOptions base = {});

/// Equirect texture coordinates of a world direction (u in [0, 1), v in [0, 1]).
Eigen::Vector2d direction_to_uv(const Eigen::Vector3d& dir);

}  // namespace vdfx::effects
