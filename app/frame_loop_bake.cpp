/// @file
/// @brief Baked parameter grid and its per-pixel application to an equirect frame.
#include "app/frame_loop_bake.h"

#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "effects/effect_shaders.h"
#include "effects/effect_stack.h"

namespace vdfx::app {

using effects::EffectType;
using effects::shader_bit;

unsigned baked_effects_mask() {
  return shader_bit(EffectType::Tint) | shader_bit(EffectType::Exposure) |
         shader_bit(EffectType::Saturation) | shader_bit(EffectType::Contrast);
}

ParamGrid bake_param_grid(const std::function<effects::StackParams(const effects::Direction&)>& at,
                          int width, int height) {
  if (width < 1 || height < 1) throw std::invalid_argument("bake_param_grid: empty grid");
  ParamGrid g{width, height, {}};
  g.cells.reserve(static_cast<std::size_t>(width) * height);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
      g.cells.push_back(at(effects::from_equirect_uv({(i + 0.5) / width, (j + 0.5) / height})));
  return g;
}

cv::Mat apply_param_grid(const cv::Mat& rgb, const ParamGrid& grid, unsigned active_mask) {
  cv::Mat src;
  if (rgb.depth() == CV_8U)
    rgb.convertTo(src, CV_32FC3, 1.0 / 255.0);
  else
    src = rgb;
  // The grid as two 3-channel images (tint gain; stops, saturation, contrast), padded by one
  // column on each side with the other side's column so the bilinear lookup wraps at the seam.
  cv::Mat gain(grid.height, grid.width, CV_32FC3), scalars(grid.height, grid.width, CV_32FC3);
  for (int j = 0; j < grid.height; ++j)
    for (int i = 0; i < grid.width; ++i) {
      const effects::StackParams& p = grid.at(i, j);
      gain.at<cv::Vec3f>(j, i) = cv::Vec3f(p.tint_gain.x(), p.tint_gain.y(), p.tint_gain.z());
      scalars.at<cv::Vec3f>(j, i) = cv::Vec3f(p.exposure_stops, p.saturation, p.contrast);
    }
  cv::copyMakeBorder(gain, gain, 0, 0, 1, 1, cv::BORDER_WRAP);
  cv::copyMakeBorder(scalars, scalars, 0, 0, 1, 1, cv::BORDER_WRAP);
  // Pixel centre x + 0.5 of the frame lies at grid coordinate (x + 0.5) W / Fw - 0.5 (cell
  // centres at integers), plus 1 for the padding column.
  cv::Mat map_x(src.rows, src.cols, CV_32FC1), map_y(src.rows, src.cols, CV_32FC1);
  for (int y = 0; y < src.rows; ++y)
    for (int x = 0; x < src.cols; ++x) {
      map_x.at<float>(y, x) = static_cast<float>((x + 0.5) * grid.width / src.cols + 0.5);
      map_y.at<float>(y, x) = static_cast<float>((y + 0.5) * grid.height / src.rows - 0.5);
    }
  cv::Mat gain_px, scalars_px;
  cv::remap(gain, gain_px, map_x, map_y, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  cv::remap(scalars, scalars_px, map_x, map_y, cv::INTER_LINEAR, cv::BORDER_REPLICATE);

  const bool tint = active_mask & shader_bit(EffectType::Tint);
  const bool exposure = active_mask & shader_bit(EffectType::Exposure);
  const bool saturation = active_mask & shader_bit(EffectType::Saturation);
  const bool contrast = active_mask & shader_bit(EffectType::Contrast);
  cv::Mat out(src.size(), CV_32FC3);
  out.forEach<cv::Vec3f>([&](cv::Vec3f& o, const int* pos) {
    const cv::Vec3f c0 = src.at<cv::Vec3f>(pos[0], pos[1]);
    const cv::Vec3f g = gain_px.at<cv::Vec3f>(pos[0], pos[1]);
    const cv::Vec3f s = scalars_px.at<cv::Vec3f>(pos[0], pos[1]);
    Eigen::Vector3d c(c0[0], c0[1], c0[2]);
    // The contract's order; the same per-pixel formulas as the CPU reference.
    if (tint) c = effects::apply_tint(c, Eigen::Vector3d(g[0], g[1], g[2]));
    if (exposure) c = effects::apply_exposure(c, s[0]);
    if (saturation) c = effects::apply_saturation(c, s[1]);
    if (contrast) c = effects::apply_contrast(c, s[2]);
    o = cv::Vec3f(static_cast<float>(c.x()), static_cast<float>(c.y()), static_cast<float>(c.z()));
  });
  return out;
}

}  // namespace vdfx::app
