/// @file
/// @brief RAII GL textures and render targets, cv::Mat upload and readback.
///
/// Images cross the CPU/GPU boundary as OpenCV BGR(A) mats; inside GL the channels are RGB(A)
/// (the upload and readback name GL_BGR so nothing is swapped by hand). Mats are upright (row 0 at
/// the top) and GL textures have their origin at the bottom-left: upload and readback flip rows,
/// so texture t = 1 - (row + 0.5) / rows, and an equirect's v (0 at the top) is t = 1 - v.
#pragma once

#include <opencv2/core.hpp>

namespace vdfx::xr {

enum class TexFormat { RGBA8, RGBA16F, RGBA32F, RG32F };

/// Levels of a full mip chain for a width x height image (down to 1 x 1).
int full_mip_levels(int width, int height);

class GlTexture {
 public:
  GlTexture() = default;
  /// Empty texture; `mip_levels` > 1 allocates a mip chain.
  GlTexture(int width, int height, TexFormat format, int mip_levels = 1);
  ~GlTexture();
  GlTexture(GlTexture&& o) noexcept;
  GlTexture& operator=(GlTexture&& o) noexcept;
  GlTexture(const GlTexture&) = delete;
  GlTexture& operator=(const GlTexture&) = delete;

  /// Replaces level 0 with a CV_8UC3/CV_8UC4/CV_32FC3/CV_32FC4 BGR(A) mat of the same size.
  void upload(const cv::Mat& bgr);
  /// Replaces `region` (in the mat's pixels) of level 0 with that part of `rgba`, a CV_8UC4 RGBA
  /// mat of the texture's size, rows as stored: row 0 is the texture's first row (t = 0). Unlike
  /// upload() nothing is flipped or swapped: panel images come RGBA in the quads' row order
  /// (app/window/editor_client.h), and only their damaged rectangles are sent.
  void upload_rgba_region(const cv::Mat& rgba, const cv::Rect& region);
  void generate_mipmaps();
  /// Sets min/mag filter and wrap: linear (+ trilinear when mipmapped), wrap_s repeat or clamp.
  void set_sampling(bool linear, bool repeat_s);
  /// Reads level 0 back as CV_32FC4 BGRA (or CV_32FC2 for RG32F), upright (row 0 = top).
  cv::Mat read_float() const;

  unsigned id() const { return id_; }
  /// Lets go of the texture without deleting it, for an owner that may outlive its context
  /// (destroying the context frees it); this object is then empty.
  void disown() { id_ = 0; }
  int width() const { return width_; }
  int height() const { return height_; }
  int levels() const { return levels_; }
  TexFormat format() const { return format_; }
  explicit operator bool() const { return id_ != 0; }

 private:
  unsigned id_ = 0;
  int width_ = 0, height_ = 0, levels_ = 1;
  TexFormat format_ = TexFormat::RGBA8;
};

/// A texture with a framebuffer that renders into it. The GL origin is the bottom-left; read_float
/// flips so the mat is upright. Passes that render to a target therefore draw "upright" when
/// gl_FragCoord.y grows upwards (image row 0 is the top of the view).
class GlTarget {
 public:
  GlTarget() = default;
  GlTarget(int width, int height, TexFormat format);
  ~GlTarget();
  GlTarget(GlTarget&& o) noexcept;
  GlTarget& operator=(GlTarget&& o) noexcept;
  GlTarget(const GlTarget&) = delete;
  GlTarget& operator=(const GlTarget&) = delete;

  /// Binds the framebuffer and sets the viewport to the whole target.
  void bind() const;
  unsigned fbo() const { return fbo_; }
  const GlTexture& texture() const { return tex_; }
  GlTexture& texture() { return tex_; }
  int width() const { return tex_.width(); }
  int height() const { return tex_.height(); }
  cv::Mat read_float() const { return tex_.read_float(); }
  explicit operator bool() const { return fbo_ != 0; }

 private:
  GlTexture tex_;
  unsigned fbo_ = 0;
};

/// Converts a CV_32FC4 BGRA readback to CV_8UC3 BGR, clamping to [0, 1] (the contract's "only at
/// the very end") and rounding.
cv::Mat to_bgr8(const cv::Mat& bgra_float);

}  // namespace vdfx::xr
