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
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

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
  /// Bilinear sample at texture coordinates (u wraps, v per PoleRows) on a ripmap level.
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

  SamplerOptions options_;
  int width_ = 0, height_ = 0;
  int max_lx_ = 0, max_ly_ = 0;
  std::vector<std::vector<cv::Mat>> levels_;  //!< levels_[ly][lx - ly]
};

/// Equirect texture coordinates of a world direction (u in [0, 1), v in [0, 1]).
Eigen::Vector2d direction_to_uv(const Eigen::Vector3d& dir);

}  // namespace vdfx::effects
