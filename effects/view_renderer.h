/// @file
/// @brief CPU reference renderer of one view: camera + equirect image + effect parameters -> image.
///
/// Two modes (the paper's):
/// - View: one StackParams, evaluated once at the view's centre direction (the optical axis), for
///   the whole image: no parameter gradient across the view.
/// - Pixel: parameters evaluated at each pixel's own ray direction (the static per-pixel baseline).
///   The blur is then a per-pixel varying Gaussian gather (exact and slow: O(r^2) per pixel).
/// Blur never sees an image border: the view is sampled with a margin of one kernel radius and
/// cropped after blurring. The vignette is centred on the camera's optical axis (the eye's optical
/// centre, which is off the image centre for asymmetric eye FOVs).
#pragma once

#include <functional>
#include <opencv2/core.hpp>

#include "effects/coords.h"
#include "effects/effect_types.h"
#include "effects/equirect_sampler.h"
#include "effects/view_camera.h"

namespace vdfx::effects {

enum class RenderMode { View, Pixel };

/// Parameters of the whole stack at a direction (the RBF interpolation, or a test function).
/// Called from the calling thread only.
using ParamsAt = std::function<StackParams(const Direction&)>;

/// Equirect sample at every pixel of the camera, no effects (CV_32FC3 RGB):
/// EquirectSampler::sample_pixel at each pixel centre (the footprint filter by default).
cv::Mat sample_view(const EquirectSampler& sampler, const ViewCamera& camera);

/// View mode with given parameters. Unclamped CV_32FC3 RGB.
cv::Mat render_view(const EquirectSampler& sampler, const ViewCamera& camera,
                    const StackParams& params);

/// Either mode with parameters from a function of direction. Unclamped CV_32FC3 RGB.
cv::Mat render_view(const EquirectSampler& sampler, const ViewCamera& camera,
                    const ParamsAt& params_at, RenderMode mode);

/// The output step: clamp to [0, 1], scale by 255, round half up -> CV_8UC3, still RGB order and
/// still the video's encoding (sRGB-encoded values in, sRGB-encoded bytes out).
cv::Mat to_rgb8(const cv::Mat& rgb);

}  // namespace vdfx::effects
