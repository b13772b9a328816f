/// @file
/// @brief EffectStackGl: shader variants per active set, view and per-pixel parameter modes,
/// exact or pyramid blur in float textures.
#include "xr/render/effect_stack_gl.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "effects/effect_shaders.h"
#include "xr/render/gl_context.h"

namespace vdfx::xr {

using effects::EffectType;
using effects::shader_bit;
using effects::StackShader;

BlurPixels blur_pixels(double sigma_deg, const RenderView& v, int width, int height) {
  const double s = sigma_deg * effects::kDegToRad;
  const double cx = v.optical_centre_tan.x(), cy = v.optical_centre_tan.y();
  BlurPixels b;
  b.sigma_x = s * (1.0 + cx * cx) * width / (v.tan_right - v.tan_left);
  b.sigma_y = s * (1.0 + cy * cy) * height / (v.tan_up - v.tan_down);
  b.radius_x = static_cast<int>(std::ceil(3.0 * b.sigma_x));
  b.radius_y = static_cast<int>(std::ceil(3.0 * b.sigma_y));
  return b;
}

RenderView with_margin(const RenderView& v, int width, int height, int margin) {
  RenderView m = v;
  const double dx = margin * (v.tan_right - v.tan_left) / width;
  const double dy = margin * (v.tan_up - v.tan_down) / height;
  m.tan_left -= dx;
  m.tan_right += dx;
  m.tan_down -= dy;
  m.tan_up += dy;
  return m;
}

int blur_margin(const effects::StackParams& p, unsigned mask, const RenderView& v, int width,
                int height) {
  if (!(mask & shader_bit(EffectType::Blur)) || !(p.blur_sigma_deg > 0.0)) return 0;
  const BlurPixels b = blur_pixels(p.blur_sigma_deg, v, width, height);
  return std::max(b.radius_x, b.radius_y);
}

EffectStackGl::EffectStackGl(TexFormat scratch_format, BlurMethod blur)
    : scratch_format_(scratch_format), blur_method_(blur), pyramid_(scratch_format) {
  blur_h_ =
      GlProgram::build("blur_1d", fullscreen_vertex_source(), effects::blur_1d_fragment_source());
  glGenVertexArrays(1, &vao_);
}

EffectStackGl::~EffectStackGl() {
  if (vao_) glDeleteVertexArrays(1, &vao_);
}

const GlProgram& EffectStackGl::program_for(const StackShader& variant) {
  auto it = programs_.find(variant);
  if (it == programs_.end()) {
    const std::string name = "effect_stack_" + std::to_string(variant.mask) + "_" +
                             std::to_string(static_cast<int>(variant.blur)) +
                             (variant.per_pixel ? "_pixel" : "_view");
    it = programs_
             .emplace(variant, GlProgram::build(name, fullscreen_vertex_source(),
                                                effects::stack_fragment_source(variant)))
             .first;
  }
  return it->second;
}

void EffectStackGl::check_sizes(const GlTexture& src, const GlTarget& dst, int margin) const {
  const int w = dst.width(), h = dst.height();
  if (margin < 0 || src.width() != w + 2 * margin || src.height() != h + 2 * margin)
    throw GlError("EffectStackGl::apply: source " + std::to_string(src.width()) + "x" +
                  std::to_string(src.height()) + " is not the target " + std::to_string(w) + "x" +
                  std::to_string(h) + " plus a margin of " + std::to_string(margin));
}

void EffectStackGl::set_geometry(const GlProgram& p, const RenderView& v, int w, int h,
                                 int margin) const {
  glUniform1i(p.uniform("u_src"), 0);
  glUniform1i(p.uniform("u_margin"), margin);
  glUniform4f(p.uniform("u_tan"), static_cast<float>(v.tan_left), static_cast<float>(v.tan_right),
              static_cast<float>(v.tan_down), static_cast<float>(v.tan_up));
  glUniform2f(p.uniform("u_size"), static_cast<float>(w), static_cast<float>(h));
  glUniform2f(p.uniform("u_centre_tan"), static_cast<float>(v.optical_centre_tan.x()),
              static_cast<float>(v.optical_centre_tan.y()));
}

void EffectStackGl::apply(const GlTexture& src, const GlTarget& dst, const effects::StackParams& sp,
                          unsigned mask, const RenderView& v, int margin) {
  check_sizes(src, dst, margin);
  const int w = dst.width(), h = dst.height();
  glDisable(GL_BLEND);
  const BlurPixels blur = blur_pixels(sp.blur_sigma_deg, v, w, h);
  const bool blur_on = (mask & shader_bit(EffectType::Blur)) && sp.blur_sigma_deg > 0.0;
  StackShader variant;
  variant.mask = mask & ~shader_bit(EffectType::Blur);
  unsigned pass2_src = src.id();
  int blurred_scale = 0;
  if (blur_on && blur_method_ == BlurMethod::Pyramid &&
      plan_pyramid(blur.sigma_x, blur.sigma_y).halvings > 0) {
    pyramid_.set_source(src);
    blurred_scale = pyramid_.blur(blur.sigma_x, blur.sigma_y, BlurMethod::Pyramid, blurred_);
    variant.blur = StackShader::Blur::Blurred;
  } else if (blur_on) {
    // Exact (or a sigma too small for the pyramid): horizontal pass here, vertical fused below.
    if (!scratch_ || scratch_.width() != src.width() || scratch_.height() != src.height())
      scratch_ = GlTarget(src.width(), src.height(), scratch_format_);
    glBindVertexArray(vao_);
    scratch_.bind();
    blur_h_.use();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, src.id());
    glUniform1i(blur_h_.uniform("u_src"), 0);
    glUniform2f(blur_h_.uniform("u_dir"), 1.0f, 0.0f);
    set_gaussian_uniforms(blur_h_, blur.sigma_x, blur.radius_x, 1, taps_[0]);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    pass2_src = scratch_.texture().id();
    variant.blur = StackShader::Blur::FusedVertical;
  }
  const GlProgram& p = program_for(variant);
  glBindVertexArray(vao_);
  dst.bind();
  p.use();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, pass2_src);
  set_geometry(p, v, w, h, margin);
  if (variant.blur == StackShader::Blur::FusedVertical)
    set_gaussian_uniforms(p, blur.sigma_y, blur.radius_y, 2, taps_[1]);
  if (variant.blur == StackShader::Blur::Blurred) {
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, blurred_.texture().id());
    glUniform1i(p.uniform("u_blurred"), 1);
    glUniform1f(p.uniform("u_blurred_scale"), static_cast<float>(blurred_scale));
    glActiveTexture(GL_TEXTURE0);
  }
  const Eigen::Vector3f g = sp.tint_gain.cast<float>();
  glUniform3f(p.uniform("u_tint"), g.x(), g.y(), g.z());
  glUniform1f(p.uniform("u_exposure_gain"), static_cast<float>(std::exp2(sp.exposure_stops)));
  glUniform1f(p.uniform("u_saturation"), static_cast<float>(sp.saturation));
  glUniform1f(p.uniform("u_contrast"), static_cast<float>(sp.contrast));
  glUniform2f(p.uniform("u_vignette"),
              static_cast<float>(sp.vignette_radius_deg * effects::kDegToRad),
              static_cast<float>(sp.vignette_falloff_deg * effects::kDegToRad));
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void EffectStackGl::set_level_ratio(double r) {
  if (!(r > 1.0 && r <= 16.0))
    throw GlError("EffectStackGl::set_level_ratio: ratio must be in (1, 16], got " +
                  std::to_string(r));
  level_ratio_ = r;
}

void EffectStackGl::set_param_grid(const ParamGrid& grid) {
  if (grid.width < 1 || grid.height < 1 ||
      grid.cells.size() != static_cast<std::size_t>(grid.width) * grid.height)
    throw GlError("EffectStackGl::set_param_grid: grid " + std::to_string(grid.width) + "x" +
                  std::to_string(grid.height) + " holds " + std::to_string(grid.cells.size()) +
                  " cells");
  // Mats are BGRA: channel 2 lands in GL's r, 1 in g, 0 in b, 3 in a (gl_texture.h).
  cv::Mat m0(grid.height, grid.width, CV_32FC4), m1(grid.height, grid.width, CV_32FC4),
      m2(grid.height, grid.width, CV_32FC4);
  for (int j = 0; j < grid.height; ++j)
    for (int i = 0; i < grid.width; ++i) {
      const effects::StackParams& p = grid.at(i, j);
      const auto f = [](double x) { return static_cast<float>(x); };
      m0.at<cv::Vec4f>(j, i) = {f(p.tint_gain.z()), f(p.tint_gain.y()), f(p.tint_gain.x()),
                                f(p.exposure_stops)};
      m1.at<cv::Vec4f>(j, i) = {f(p.vignette_radius_deg * effects::kDegToRad), f(p.contrast),
                                f(p.saturation), f(p.vignette_falloff_deg * effects::kDegToRad)};
      m2.at<cv::Vec4f>(j, i) = {0.0f, 0.0f, f(p.blur_sigma_deg), 0.0f};
    }
  const cv::Mat* mats[3] = {&m0, &m1, &m2};
  glActiveTexture(GL_TEXTURE0);
  for (int k = 0; k < 3; ++k) {
    GlTexture& t = grid_[k];
    if (!t || t.width() != grid.width || t.height() != grid.height)
      t = GlTexture(grid.width, grid.height, TexFormat::RGBA32F);
    t.set_sampling(true, true);  // bilinear, repeating in azimuth
    t.upload(*mats[k]);
  }
  grid_max_sigma_deg_ = grid.max_blur_sigma_deg();
}

void EffectStackGl::apply_per_pixel(const GlTexture& src, const GlTarget& dst, unsigned mask,
                                    const RenderView& v, int margin) {
  if (!has_param_grid()) throw GlError("EffectStackGl::apply_per_pixel: no parameter grid set");
  check_sizes(src, dst, margin);
  const int w = dst.width(), h = dst.height();
  glDisable(GL_BLEND);
  StackShader variant;
  variant.mask = mask & ~shader_bit(EffectType::Blur);
  variant.per_pixel = true;
  const bool blur_on = (mask & shader_bit(EffectType::Blur)) && grid_max_sigma_deg_ > 0.0;
  double tau1_deg = 0.0, ratio = level_ratio_;
  std::vector<int> scales;
  if (blur_on) {
    // Levels tau_j = tau_1 r^(j-1) from half a pixel up to the grid's largest sigma. Where that
    // would need more than kMaxBlurLevels, the levels spread wider (r grows) rather than start
    // higher: a coarser tau_1 would mix the unblurred image into every small sigma.
    const BlurPixels per_deg = blur_pixels(1.0, v, w, h);
    const double per_deg_px = std::max(per_deg.sigma_x, per_deg.sigma_y);
    tau1_deg = kPerPixelFirstLevelPx / per_deg_px;
    int n = 1;
    while (n < effects::kMaxBlurLevels && tau1_deg * std::pow(ratio, n - 1) < grid_max_sigma_deg_)
      ++n;
    if (tau1_deg * std::pow(ratio, n - 1) < grid_max_sigma_deg_)
      ratio = std::pow(grid_max_sigma_deg_ / tau1_deg, 1.0 / (n - 1));
    if (levels_.size() < static_cast<std::size_t>(n)) levels_.resize(static_cast<std::size_t>(n));
    pyramid_.set_source(src);
    for (int j = 0; j < n; ++j) {
      const double tau = tau1_deg * std::pow(ratio, j);
      scales.push_back(pyramid_.blur(tau * per_deg.sigma_x, tau * per_deg.sigma_y, blur_method_,
                                     levels_[static_cast<std::size_t>(j)]));
    }
    variant.blur = StackShader::Blur::Levels;
    variant.levels = n;
  }
  const GlProgram& p = program_for(variant);
  glBindVertexArray(vao_);
  dst.bind();
  p.use();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, src.id());
  set_geometry(p, v, w, h, margin);
  const char* grid_names[3] = {"u_grid0", "u_grid1", "u_grid2"};
  for (int k = 0; k < 3; ++k) {
    glActiveTexture(GL_TEXTURE1 + static_cast<unsigned>(k));
    glBindTexture(GL_TEXTURE_2D, grid_[k].id());
    glUniform1i(p.uniform(grid_names[k]), 1 + k);
  }
  const Eigen::Matrix3f rot = v.orientation.cast<float>();
  glUniformMatrix3fv(p.uniform("u_rot"), 1, GL_FALSE, rot.data());  // column-major, as GLSL
  if (blur_on) {
    glUniform1f(p.uniform("u_tau1_deg"), static_cast<float>(tau1_deg));
    glUniform1f(p.uniform("u_level_log2r"), static_cast<float>(std::log2(ratio)));
    std::vector<float> fscales(scales.begin(), scales.end());
    glUniform1fv(p.uniform("u_level_scale"), static_cast<int>(fscales.size()), fscales.data());
    for (std::size_t j = 0; j < scales.size(); ++j) {
      const unsigned unit = 4 + static_cast<unsigned>(j);
      glActiveTexture(GL_TEXTURE0 + unit);
      glBindTexture(GL_TEXTURE_2D, levels_[j].texture().id());
      glUniform1i(p.uniform(("u_level" + std::to_string(j + 1)).c_str()), static_cast<int>(unit));
    }
  }
  glActiveTexture(GL_TEXTURE0);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace vdfx::xr
