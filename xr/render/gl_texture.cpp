/// @file
/// @brief GlTexture and GlTarget.
#include "xr/render/gl_texture.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "xr/render/gl_context.h"

namespace vdfx::xr {
namespace {

GLenum internal_format(TexFormat f) {
  switch (f) {
    case TexFormat::RGBA8: return GL_RGBA8;
    case TexFormat::RGBA16F: return GL_RGBA16F;
    case TexFormat::RGBA32F: return GL_RGBA32F;
    case TexFormat::RG32F: return GL_RG32F;
  }
  return GL_RGBA8;
}

}  // namespace

int full_mip_levels(int width, int height) {
  return 1 + static_cast<int>(std::floor(std::log2(std::max({width, height, 1}))));
}

GlTexture::GlTexture(int width, int height, TexFormat format, int mip_levels)
    : width_(width), height_(height), levels_(std::max(1, mip_levels)), format_(format) {
  if (width <= 0 || height <= 0)
    throw GlError("GlTexture: size " + std::to_string(width) + "x" + std::to_string(height) +
                  " is not positive");
  glGenTextures(1, &id_);
  glBindTexture(GL_TEXTURE_2D, id_);
  glTexStorage2D(GL_TEXTURE_2D, levels_, internal_format(format), width, height);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels_ - 1);
  set_sampling(true, false);
  check_gl("GlTexture allocation");
}

GlTexture::~GlTexture() {
  if (id_) glDeleteTextures(1, &id_);
}
GlTexture::GlTexture(GlTexture&& o) noexcept
    : id_(o.id_), width_(o.width_), height_(o.height_), levels_(o.levels_), format_(o.format_) {
  o.id_ = 0;
}
GlTexture& GlTexture::operator=(GlTexture&& o) noexcept {
  if (this != &o) {
    if (id_) glDeleteTextures(1, &id_);
    id_ = o.id_;
    width_ = o.width_;
    height_ = o.height_;
    levels_ = o.levels_;
    format_ = o.format_;
    o.id_ = 0;
  }
  return *this;
}

void GlTexture::upload(const cv::Mat& m) {
  if (m.cols != width_ || m.rows != height_)
    throw GlError("GlTexture::upload: image is " + std::to_string(m.cols) + "x" +
                  std::to_string(m.rows) + ", texture is " + std::to_string(width_) + "x" +
                  std::to_string(height_));
  GLenum fmt = 0, type = 0;
  switch (m.type()) {
    case CV_32FC2:
      fmt = GL_RG;
      type = GL_FLOAT;
      break;
    case CV_8UC3:
      fmt = GL_BGR;
      type = GL_UNSIGNED_BYTE;
      break;
    case CV_8UC4:
      fmt = GL_BGRA;
      type = GL_UNSIGNED_BYTE;
      break;
    case CV_32FC3:
      fmt = GL_BGR;
      type = GL_FLOAT;
      break;
    case CV_32FC4:
      fmt = GL_BGRA;
      type = GL_FLOAT;
      break;
    default:
      throw GlError("GlTexture::upload: unsupported cv::Mat type " + std::to_string(m.type()));
  }
  cv::Mat c;
  cv::flip(m, c, 0);  // GL's first row is the bottom one
  glBindTexture(GL_TEXTURE_2D, id_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width_, height_, fmt, type, c.data);
  check_gl("GlTexture::upload");
}

void GlTexture::upload_rgba_region(const cv::Mat& rgba, const cv::Rect& region) {
  if (rgba.type() != CV_8UC4 || rgba.cols != width_ || rgba.rows != height_)
    throw GlError("GlTexture::upload_rgba_region: a " + std::to_string(width_) + "x" +
                  std::to_string(height_) + " RGBA8 image expected, got " +
                  std::to_string(rgba.cols) + "x" + std::to_string(rgba.rows) + " of type " +
                  std::to_string(rgba.type()));
  if ((region & cv::Rect(0, 0, width_, height_)) != region)
    throw GlError("GlTexture::upload_rgba_region: the region is outside the image");
  if (region.empty()) return;
  glBindTexture(GL_TEXTURE_2D, id_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, static_cast<GLint>(rgba.step1() / 4));
  const cv::Mat part = rgba(region);
  glTexSubImage2D(GL_TEXTURE_2D, 0, region.x, region.y, region.width, region.height, GL_RGBA,
                  GL_UNSIGNED_BYTE, part.data);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  check_gl("GlTexture::upload_rgba_region");
}

void GlTexture::generate_mipmaps() {
  glBindTexture(GL_TEXTURE_2D, id_);
  glGenerateMipmap(GL_TEXTURE_2D);
}

void GlTexture::set_sampling(bool linear, bool repeat_s) {
  glBindTexture(GL_TEXTURE_2D, id_);
  const GLint mag = linear ? GL_LINEAR : GL_NEAREST;
  const GLint min =
      levels_ > 1 ? (linear ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_NEAREST) : mag;
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mag);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, repeat_s ? GL_REPEAT : GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

cv::Mat GlTexture::read_float() const {
  const bool rg = format_ == TexFormat::RG32F;
  cv::Mat m(height_, width_, rg ? CV_32FC2 : CV_32FC4);
  glBindTexture(GL_TEXTURE_2D, id_);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTexImage(GL_TEXTURE_2D, 0, rg ? GL_RG : GL_BGRA, GL_FLOAT, m.data);
  check_gl("GlTexture::read_float");
  cv::Mat up;
  cv::flip(m, up, 0);
  return up;
}

GlTarget::GlTarget(int width, int height, TexFormat format) : tex_(width, height, format) {
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex_.id(), 0);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw GlError("GlTarget " + std::to_string(width) + "x" + std::to_string(height) +
                  ": framebuffer incomplete (status " + std::to_string(status) + ")");
}
GlTarget::~GlTarget() {
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
}
GlTarget::GlTarget(GlTarget&& o) noexcept : tex_(std::move(o.tex_)), fbo_(o.fbo_) {
  o.fbo_ = 0;
}
GlTarget& GlTarget::operator=(GlTarget&& o) noexcept {
  if (this != &o) {
    if (fbo_) glDeleteFramebuffers(1, &fbo_);
    tex_ = std::move(o.tex_);
    fbo_ = o.fbo_;
    o.fbo_ = 0;
  }
  return *this;
}
void GlTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, width(), height());
}

cv::Mat to_bgr8(const cv::Mat& bgra) {
  cv::Mat bgr, out;
  if (bgra.channels() == 4)
    cv::cvtColor(bgra, bgr, cv::COLOR_BGRA2BGR);
  else
    bgr = bgra;
  bgr.convertTo(out, CV_8U, 255.0);  // saturate_cast clamps to [0, 255] and rounds
  return out;
}

}  // namespace vdfx::xr
