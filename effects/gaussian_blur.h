/// @file
/// @brief Gaussian blur of RGB CV_32FC3 images, three peers (exact 2-D, separable, OpenCV) and a
/// per-pixel varying gather for the per-pixel mode.
///
/// Contract: kernel radius ceil(3 sigma) (in pixels), weights exp(-x^2 / (2 sigma^2)) normalised
/// to sum 1. Borders repeat the edge pixel (BORDER_REPLICATE, GL's CLAMP_TO_EDGE); the view
/// renderer avoids borders altogether by rendering a margin of one kernel radius. The exact and
/// separable versions sum in double.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace vdfx::effects {

/// ceil(3 sigma); 0 for sigma <= 0.
int gaussian_radius(double sigma_px);
/// Normalised 1-D weights, 2 r + 1 of them; {1} for sigma <= 0.
std::vector<double> gaussian_kernel(double sigma_px);

/// Sigma in pixels of a sigma in degrees of visual angle: focal_px * sigma in radians, the local
/// scale of the image plane at the optical centre (d x / d theta = f there). Off-centre the same
/// pixel sigma spans a slightly smaller angle (by cos^2 of the off-axis angle), as in the paper's
/// screen-space blur.
double sigma_px_from_deg(double sigma_deg, double focal_px);

/// Separable: a horizontal then a vertical 1-D pass (double intermediate). O(r) per pixel.
cv::Mat blur_separable(const cv::Mat& src, double sigma_x_px, double sigma_y_px);
/// Exact 2-D: the full (2 rx + 1) x (2 ry + 1) product kernel per pixel. O(r^2) per pixel.
cv::Mat blur_exact_2d(const cv::Mat& src, double sigma_x_px, double sigma_y_px);
/// cv::GaussianBlur with the same kernel size and border (float accumulation).
cv::Mat blur_opencv(const cv::Mat& src, double sigma_x_px, double sigma_y_px);

/// Per-pixel varying 2-D Gaussian gather (exact, slow: O(r^2) per pixel). `src` carries `margin`
/// extra pixels on every side; the result is src shrunk by the margin. `sigma_px` is CV_64FC2
/// (sigma_x, sigma_y per output pixel, output size); each pixel's kernel is normalised over its
/// own window, which must fit in the margin (radii above it are clamped to it).
cv::Mat blur_varying(const cv::Mat& src, int margin, const cv::Mat& sigma_px);

}  // namespace vdfx::effects
