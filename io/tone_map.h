/// @file
/// @brief Display encoding of linear radiance (EXR, Radiance HDR) so that the effects, which act
/// on encoded values in [0, 1], see what an author would see.
///
/// Operator (Reinhard, Stark, Shirley, Ferwerda, "Photographic Tone Reproduction for Digital
/// Images", SIGGRAPH 2002, eqs. 1-3): with world luminance L_w = 0.2126 R + 0.7152 G + 0.0722 B
/// (Rec. 709 primaries, linear),
///   L_avg = exp(mean(log(delta + L_w)))          (log-average luminance, eq. 1)
///   L     = key / L_avg * L_w                    (exposure normalisation, eq. 2)
///   L_d   = L / (1 + L)                          (global operator, eq. 3)
/// and each colour is scaled by L_d / L_w (hue and saturation kept), clamped to [0, 1] per
/// channel, then sRGB-encoded (IEC 61966-2-1).
#pragma once

#include <opencv2/core.hpp>

namespace vdfx::io {

struct ToneMapSettings {
  double key = 0.18;    //!< "middle grey" a (Reinhard et al. use 0.18)
  double delta = 1e-6;  //!< keeps log() finite on black pixels
};

/// Rec. 709 luminance of linear RGB.
inline constexpr double kRec709R = 0.2126, kRec709G = 0.7152, kRec709B = 0.0722;

/// exp(mean(log(delta + L_w))) over all pixels of a linear RGB CV_32FC3 image. Negative and
/// non-finite pixels count as black.
double log_average_luminance(const cv::Mat& linear_rgb, double delta = 1e-6);

/// IEC 61966-2-1 sRGB encoding of one linear value in [0, 1].
double srgb_encode(double linear);

/// Linear radiance RGB (CV_32FC3) -> display-encoded sRGB RGB (CV_32FC3) in [0, 1].
cv::Mat tone_map_reinhard(const cv::Mat& linear_rgb, const ToneMapSettings& settings = {});

}  // namespace vdfx::io
