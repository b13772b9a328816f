/// @file
/// @brief BlurPyramidGl: exact separable and binomial-pyramid Gaussian blur of float textures.
#include "xr/render/blur_pyramid_gl.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>

#include "effects/effect_shaders.h"
#include "effects/gaussian_blur.h"
#include "xr/render/gl_context.h"

namespace vdfx::xr {

PyramidPlan plan_pyramid(double sigma_x, double sigma_y) {
  PyramidPlan p;
  const double s = std::min(sigma_x, sigma_y);
  while (p.halvings < 12 && s / std::ldexp(1.0, p.halvings + 1) >= kPyramidMinSigma) ++p.halvings;
  if (p.halvings == 0) {
    p.residual_x = sigma_x;
    p.residual_y = sigma_y;
    return p;
  }
  const double scale = std::ldexp(1.0, 2 * p.halvings);  // 4^k
  const auto residual = [&](double sigma) {
    return std::sqrt(std::max(0.0, (sigma * sigma - (scale - 1.0) / 4.0) / scale - 1.0 / 6.0));
  };
  p.residual_x = residual(sigma_x);
  p.residual_y = residual(sigma_y);
  return p;
}

void set_gaussian_uniforms(const GlProgram& program, double sigma, int radius, int unit,
                           GlTexture& taps) {
  // Contract weights exp(-i^2 / (2 sigma^2)), normalised in double; texel k of the table is the
  // pair (i, i + 1) = (2 k + 1, 2 k + 2) read with one bilinear fetch.
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
  // The table keeps a fixed capacity (kMinTapCapacity, doubled when a radius needs more, never
  // shrunk): the per-pixel blur sets a different radius per level, per eye and per frame, and a
  // texture sized to each would be reallocated every time. Texels past u_tap_count stay unread.
  const int needed = std::max<int>(1, static_cast<int>(t.size()));
  // Allocation and upload bind the table: on its own unit, never over the caller's source.
  glActiveTexture(GL_TEXTURE0 + static_cast<unsigned>(unit));
  if (!taps || taps.width() < needed) {
    int capacity = std::max(taps ? taps.width() : 0, kMinTapCapacity);
    while (capacity < needed) capacity *= 2;
    taps = GlTexture(capacity, 1, TexFormat::RG32F);
    taps.set_sampling(false, false);
  }
  t.resize(static_cast<size_t>(taps.width()), cv::Vec2f(0.0f, 0.0f));
  const cv::Mat table = cv::Mat(t, true).reshape(2, 1);
  taps.upload(table);
  glBindTexture(GL_TEXTURE_2D, taps.id());
  glUniform1i(program.uniform("u_taps"), unit);
  glUniform1i(program.uniform("u_tap_count"), (radius + 1) / 2);
  glUniform1f(program.uniform("u_centre_weight"), static_cast<float>(w[0]));
  glActiveTexture(GL_TEXTURE0);
}

BlurPyramidGl::BlurPyramidGl(TexFormat format) : format_(format) {
  blur_1d_ =
      GlProgram::build("blur_1d", fullscreen_vertex_source(), effects::blur_1d_fragment_source());
  downsample_ = GlProgram::build("downsample", fullscreen_vertex_source(),
                                 effects::downsample_fragment_source());
  glGenVertexArrays(1, &vao_);
}

BlurPyramidGl::~BlurPyramidGl() {
  if (vao_) glDeleteVertexArrays(1, &vao_);
}

void BlurPyramidGl::set_source(const GlTexture& src) {
  src_ = &src;
  built_ = 0;
}

const GlTarget& BlurPyramidGl::level(int k) {
  if (!src_) throw GlError("BlurPyramidGl: no source set");
  if (chain_.size() < static_cast<size_t>(k)) chain_.resize(static_cast<size_t>(k));
  glBindVertexArray(vao_);
  glActiveTexture(GL_TEXTURE0);
  downsample_.use();
  glUniform1i(downsample_.uniform("u_src"), 0);
  for (int i = built_ + 1; i <= k; ++i) {
    const GlTexture& in = i == 1 ? *src_ : chain_[static_cast<size_t>(i - 2)].texture();
    const int w = (in.width() + 1) / 2, h = (in.height() + 1) / 2;
    GlTarget& t = chain_[static_cast<size_t>(i - 1)];
    if (!t || t.width() != w || t.height() != h) {
      t = GlTarget(w, h, format_);
      t.texture().set_sampling(true, false);
    }
    t.bind();
    glBindTexture(GL_TEXTURE_2D, in.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  built_ = std::max(built_, k);
  return chain_[static_cast<size_t>(k - 1)];
}

void BlurPyramidGl::blur_separable(const GlTexture& in, double sx, double sy, GlTarget& out) {
  const int w = in.width(), h = in.height();
  if (!out || out.width() != w || out.height() != h) {
    out = GlTarget(w, h, format_);
    out.texture().set_sampling(true, false);
  }
  // One horizontal scratch per size (the chain's sizes repeat from frame to frame).
  auto it = std::find_if(tmp_.begin(), tmp_.end(),
                         [&](const GlTarget& t) { return t.width() == w && t.height() == h; });
  if (it == tmp_.end()) {
    tmp_.emplace_back(w, h, format_);
    tmp_.back().texture().set_sampling(true, false);
    it = tmp_.end() - 1;
  }
  glBindVertexArray(vao_);
  blur_1d_.use();
  glUniform1i(blur_1d_.uniform("u_src"), 0);
  it->bind();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, in.id());
  glUniform2f(blur_1d_.uniform("u_dir"), 1.0f, 0.0f);
  set_gaussian_uniforms(blur_1d_, sx, effects::gaussian_radius(sx), 1, taps_[0]);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  out.bind();
  glBindTexture(GL_TEXTURE_2D, it->texture().id());
  glUniform2f(blur_1d_.uniform("u_dir"), 0.0f, 1.0f);
  set_gaussian_uniforms(blur_1d_, sy, effects::gaussian_radius(sy), 2, taps_[1]);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

int BlurPyramidGl::blur(double sigma_x, double sigma_y, BlurMethod method, GlTarget& out) {
  if (!src_) throw GlError("BlurPyramidGl::blur: no source set");
  glDisable(GL_BLEND);
  if (method == BlurMethod::Exact) {
    blur_separable(*src_, sigma_x, sigma_y, out);
    return 1;
  }
  const PyramidPlan plan = plan_pyramid(sigma_x, sigma_y);
  if (plan.halvings == 0) {
    blur_separable(*src_, sigma_x, sigma_y, out);
    return 1;
  }
  blur_separable(level(plan.halvings).texture(), plan.residual_x, plan.residual_y, out);
  return 1 << plan.halvings;
}

}  // namespace vdfx::xr
