/// @file
/// @brief Gaussian blur on the sphere of a whole equirect image (the baked export's blur): every
/// pixel averages its neighbours by great-circle angle, not by distance in the equirect plane,
/// so a blur stays round at any altitude and crosses the azimuth seam and the poles.
///
/// Constant sigma: out(n) = sum_m w(n, m) in(m) / sum_m w(n, m), with
///   w = exp(-theta^2 / (2 sigma^2)) * cos(alt_m)      (theta: angle between n and m)
/// over theta <= 3 sigma (the contract's kernel radius ceil(3 sigma)), cos(alt_m) being the solid
/// angle of texel m. Because w depends only on the two rows and the column offset, one 1-D
/// kernel per row pair serves a whole output row. Large sigmas are computed on a copy reduced by
/// a power of two (box-averaged, weighted by solid angle) so that sigma spans one to two texels
/// there, then sampled back bilinearly, the gather's sigma reduced by the variance the box and
/// the bilinear read-back add: the work per level stays at most about 150 taps per texel of its
/// level.
///
/// Varying sigma (per pixel): levels of the constant blur at sigmas growing by `ratio` (half
/// octaves by default, as the GPU per-pixel mode, xr/render/blur_method.h), the smallest one half a
/// texel; each pixel mixes the two levels around its own sigma linearly in sigma (level 0 is the
/// unblurred image). A level is computed only where some pixel mixes it (8 x 8 tiles of the
/// sigma map, each with the range of levels its sigmas need, dilated by the read-back), and the
/// solid-angle reduction is made once per call as a chain shared by the levels: the result is
/// the mix of whole levels, to float rounding. docs/export.md gives the measured error of the
/// mix.
///
/// A VR180 image (half a turn of azimuth) is blurred by blur_half_equirect_varying: its edges are
/// clamped, never wrapped.
#pragma once

#include <opencv2/core.hpp>

namespace vdfx::effects {

/// Angular Gaussian blur with one sigma (degrees) for the whole sphere. `rgb` is an equirect
/// CV_32FC3 image (any width x height, rows from altitude +90 to -90).
cv::Mat blur_equirect(const cv::Mat& rgb, double sigma_deg);

/// Angular Gaussian blur with a sigma per pixel (`sigma_deg`: CV_32FC1, the image's size,
/// degrees, >= 0) by mixing blur_equirect levels. Pixels with sigma 0 are unchanged.
cv::Mat blur_equirect_varying(const cv::Mat& rgb, const cv::Mat& sigma_deg,
                              double ratio = 1.4142135623730951);
/// The same into `out` (not `rgb`'s buffer), whose buffer is reused when it has the size and
/// type already (a caller blurring frame after frame then has no fresh image, and its page
/// faults, per frame).
void blur_equirect_varying(const cv::Mat& rgb, const cv::Mat& sigma_deg, cv::Mat& out,
                           double ratio = 1.4142135623730951);

/// The varying blur of a VR180 image: `rgb` spans azimuth -90..90 (its columns 180 / width
/// degrees wide), altitude -90..90. The sphere beyond its edges reads the edge column of the same
/// row, the clamp the VR180 sampler makes (effects/equirect_sampler.h), so nothing wraps from one
/// edge to the other; near a pole the kernel still reaches across it, as on the sphere. Computed
/// as the 360 blur of a canvas twice as wide (the image, then its edge columns repeated over the
/// uncovered half turn, sigma 0 there) cut back to the image: the same levels and mix.
void blur_half_equirect_varying(const cv::Mat& rgb, const cv::Mat& sigma_deg, cv::Mat& out,
                                double ratio = 1.4142135623730951);

}  // namespace vdfx::effects
