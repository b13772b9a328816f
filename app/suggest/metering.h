/// @file
/// @brief The metering model of `vdfx suggest exposure` (docs/suggest.md, "Metering"), as a
/// camera's centre-weighted meter reads a scene:
///  1. each sampled frame is area-averaged down to an equirect grid of grid_width x grid_width/2
///     cells (cv::INTER_AREA), its display values turned into linear light by the stream's
///     transfer function (Transfer), and its luminance Y = 0.2126 R + 0.7152 G + 0.0722 B (BT.709
///     primaries) taken as log2(max(Y, floor));
///  2. the level metered for a view direction is the mean of log2 Y over the cells within half the
///     metered field of view of it, each cell weighed by its solid angle (cos of its altitude)
///     times a centre weight exp(-theta^2 / (2 sigma^2)), sigma = fov / 4, theta the angle from the
///     view;
///  3. the reference level of a clip is the solid-angle-weighted mean of log2 Y over the whole
///     sphere and every sampled frame: what the camera's own exposure made "middle".
/// A VR180 image (coverage 180: azimuth -90..90) fills the middle half of the grid's columns; the
/// cells of the other half are not covered and count nowhere: a view near the edge meters the
/// image it shows, the reference level is the covered hemisphere's.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core.hpp>
#include <span>
#include <string_view>
#include <vector>

namespace vdfx::app::suggest {

/// How display-encoded values become linear light.
enum class Transfer {
  Bt1886,  //!< BT.709, BT.601, BT.2020 SDR and unspecified video: gamma 2.4 (ITU-R BT.1886)
  Srgb,    //!< IEC 61966-2-1 (stills, and video tagged so)
  Pq,      //!< SMPTE ST 2084 (BT.2100 PQ): 1.0 is 100 cd/m^2
  Hlg,     //!< ARIB STD-B67 (BT.2100 HLG), inverse OETF: scene light in [0, 1]
  Linear   //!< already linear
};

/// The transfer of a stream from FFmpeg's name of it (VideoProperties::transfer); stills and
/// unnamed streams as the players show them: sRGB for stills, BT.1886 for video.
Transfer transfer_of(std::string_view ffmpeg_name, bool is_still);
std::string_view transfer_name(Transfer transfer);
/// Linear light of one display-encoded value in [0, 1].
double to_linear(double encoded, Transfer transfer);

struct MeteringOptions {
  int grid_width = 128;          //!< cells around the equator (height: grid_width / 2)
  double fov_deg = 90.0;         //!< field of view metered around each view direction
  double floor = 1.0 / 65536.0;  //!< luminance read for black (-16 stops)
};

/// The cells' unit vectors and solid angles, shared by every frame's grid.
class MeterGeometry {
 public:
  explicit MeterGeometry(int grid_width);
  int width() const { return width_; }
  int height() const { return width_ / 2; }
  const Eigen::Matrix3Xd& units() const { return units_; }
  const Eigen::VectorXd& solid_angles() const { return solid_angles_; }

 private:
  int width_;
  Eigen::Matrix3Xd units_;        //!< one column per cell, row-major over the grid
  Eigen::VectorXd solid_angles_;  //!< steradians; they sum to 4 pi
};

/// One frame's log2 luminance per cell (row-major, MeterGeometry's order).
struct LumaGrid {
  std::int64_t frame = 0;
  Eigen::VectorXd log2_luma;
  double max_luma = 0.0;  //!< brightest cell's linear luminance (0: the frame is black)
  /// Per cell 1 where the image covers it, 0 where not (VR180's back half); empty: all covered.
  Eigen::VectorXd covered;
  /// Cell i's weight: its solid angle where the image covers it, else 0.
  double weight(const MeterGeometry& geometry, Eigen::Index i) const {
    return covered.size() ? covered[i] * geometry.solid_angles()[i] : geometry.solid_angles()[i];
  }
};

/// Step 1 for one frame: `rgb` is CV_32FC3 display values in [0, 1] (as io's decoders hand
/// RgbF32), any size with a 2:1 equirect layout; with `coverage_deg` 180, a VR180 image (azimuth
/// -90..90, any size; the grid's width must then be a multiple of 4, else std::invalid_argument).
LumaGrid make_luma_grid(const cv::Mat& rgb, Transfer transfer, const MeterGeometry& geometry,
                        const MeteringOptions& options, std::int64_t frame, int coverage_deg = 360);

/// Step 2: the level (log2 luminance) metered for the view along `view` (unit vector).
double metered_level(const LumaGrid& grid, const MeterGeometry& geometry,
                     const Eigen::Vector3d& view, const MeteringOptions& options);

/// Step 3: the clip's reference level over `grids`.
double reference_level(std::span<const LumaGrid> grids, const MeterGeometry& geometry);

}  // namespace vdfx::app::suggest
