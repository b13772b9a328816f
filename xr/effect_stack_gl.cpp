/// @file
/// @brief EffectStackGl: shader variants per active set, separable blur in float textures.
#include <epoxy/gl.h>

#include <cmath>
#include <vector>

#include "effects/effect_shaders.h"
#include "xr/effect_stack_gl.h"
#include "xr/gl_context.h"

namespace vdfx::xr {

using effects::EffectType;
using effects::shader_bit;

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

namespace {

// The paired-tap table of a 1-D Gaussian of `sigma` pixels and `radius` taps per side, weights
// normalised in double: texel k = (offset, weight) of the pair +-offset; returns the centre weight.
double gaussian_taps(double sigma, int radius, cv::Mat* taps) {
  std::vector<double> w(static_cast<size_t>(radius) + 1);
  double sum = 0.0;
  for (int i = 0; i <= radius; ++i) {
    w[static_cast<size_t>(i)] = std::exp(-i * i / (2.0 * sigma * sigma));
    sum += (i == 0 ? 1.0 : 2.0) * w[static_cast<size_t>(i)];
  }
  for (double& x : w) x /= sum;
  std::vector<cv::Vec2f> t;
  for (int i = 1; i <= radius; i += 2) {
    const double a = w[static_cast<size_t>(i)];
    const double b = i + 1 <= radius ? w[static_cast<size_t>(i + 1)] : 0.0;
    t.emplace_back(static_cast<float>(i + b / (a + b)), static_cast<float>(a + b));
  }
  if (t.empty()) t.emplace_back(0.0f, 0.0f);
  *taps = cv::Mat(t, true).reshape(2, 1);
  return w[0];
}

}  // namespace

EffectStackGl::EffectStackGl(TexFormat scratch_format) : scratch_format_(scratch_format) {
  blur_h_ = GlProgram::build("blur_horizontal", fullscreen_vertex_source(),
                             effects::blur_horizontal_fragment_source());
  glGenVertexArrays(1, &vao_);
}

EffectStackGl::~EffectStackGl() {
  if (vao_) glDeleteVertexArrays(1, &vao_);
}

const GlProgram& EffectStackGl::program_for(unsigned mask) {
  auto it = programs_.find(mask);
  if (it == programs_.end())
    it = programs_
             .emplace(mask, GlProgram::build("effect_stack_" + std::to_string(mask),
                                             fullscreen_vertex_source(),
                                             effects::stack_fragment_source(mask)))
             .first;
  return it->second;
}

void EffectStackGl::set_gaussian(const GlProgram& p, double sigma, int radius, int unit) {
  cv::Mat taps;
  const double centre = gaussian_taps(sigma, radius, &taps);
  // Upload on the tap table's own unit: unit 0 holds the source image.
  glActiveTexture(GL_TEXTURE0 + static_cast<unsigned>(unit) + 1);
  GlTexture& t = taps_[unit];
  if (!t || t.width() != taps.cols) t = GlTexture(taps.cols, 1, TexFormat::RG32F);
  t.set_sampling(false, false);
  t.upload(taps);
  glBindTexture(GL_TEXTURE_2D, t.id());
  glUniform1i(p.uniform("u_taps"), unit + 1);
  glUniform1i(p.uniform("u_tap_count"), (radius + 1) / 2);
  glUniform1f(p.uniform("u_centre_weight"), static_cast<float>(centre));
  glActiveTexture(GL_TEXTURE0);
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

void EffectStackGl::apply(const GlTexture& src, const GlTarget& dst, const effects::StackParams& sp,
                          unsigned mask, const RenderView& v, int margin) {
  const int w = dst.width(), h = dst.height();
  if (margin < 0 || src.width() != w + 2 * margin || src.height() != h + 2 * margin)
    throw GlError("EffectStackGl::apply: source " + std::to_string(src.width()) + "x" +
                  std::to_string(src.height()) + " is not the target " + std::to_string(w) + "x" +
                  std::to_string(h) + " plus a margin of " + std::to_string(margin));
  glDisable(GL_BLEND);
  glBindVertexArray(vao_);
  glActiveTexture(GL_TEXTURE0);
  const BlurPixels blur = blur_pixels(sp.blur_sigma_deg, v, w, h);
  const bool blur_on = (mask & shader_bit(EffectType::Blur)) && sp.blur_sigma_deg > 0.0;
  if (!blur_on) mask &= ~shader_bit(EffectType::Blur);
  unsigned pass2_src = src.id();
  if (blur_on) {
    if (!scratch_ || scratch_.width() != src.width() || scratch_.height() != src.height())
      scratch_ = GlTarget(src.width(), src.height(), scratch_format_);
    scratch_.bind();
    blur_h_.use();
    glBindTexture(GL_TEXTURE_2D, src.id());
    glUniform1i(blur_h_.uniform("u_src"), 0);
    set_gaussian(blur_h_, blur.sigma_x, blur.radius_x, 0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    pass2_src = scratch_.texture().id();
  }
  const GlProgram& p = program_for(mask);
  dst.bind();
  p.use();
  glBindTexture(GL_TEXTURE_2D, pass2_src);
  glUniform1i(p.uniform("u_src"), 0);
  glUniform1i(p.uniform("u_margin"), margin);
  if (blur_on) set_gaussian(p, blur.sigma_y, blur.radius_y, 1);
  if (mask & shader_bit(EffectType::Tint)) {
    const Eigen::Vector3f g = sp.tint_gain.cast<float>();
    glUniform3f(p.uniform("u_tint"), g.x(), g.y(), g.z());
  }
  if (mask & shader_bit(EffectType::Exposure))
    glUniform1f(p.uniform("u_exposure_gain"), static_cast<float>(std::exp2(sp.exposure_stops)));
  if (mask & shader_bit(EffectType::Saturation))
    glUniform1f(p.uniform("u_saturation"), static_cast<float>(sp.saturation));
  if (mask & shader_bit(EffectType::Contrast))
    glUniform1f(p.uniform("u_contrast"), static_cast<float>(sp.contrast));
  if (mask & shader_bit(EffectType::Vignette)) {
    glUniform2f(p.uniform("u_vignette"), static_cast<float>(sp.vignette_radius_deg * effects::kDegToRad),
                static_cast<float>(sp.vignette_falloff_deg * effects::kDegToRad));
    glUniform4f(p.uniform("u_tan"), static_cast<float>(v.tan_left), static_cast<float>(v.tan_right),
                static_cast<float>(v.tan_down), static_cast<float>(v.tan_up));
    glUniform2f(p.uniform("u_size"), static_cast<float>(w), static_cast<float>(h));
    glUniform2f(p.uniform("u_centre_tan"), static_cast<float>(v.optical_centre_tan.x()),
                static_cast<float>(v.optical_centre_tan.y()));
  }
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace vdfx::xr
