/// @file
/// @brief Gaussian blur of a float texture on the GPU, two methods (BlurMethod):
///  - Exact: separable Gaussian at full resolution, radius ceil(3 sigma) (the contract's kernel);
///  - Pyramid: halve the image with the binomial kernel [1 3 3 1] / 8 (variance 3/4 pixel^2 per
///    level, in that level's input pixels) until sigma / 2^k would drop below kPyramidMinSigma
///    level pixels, blur there separably with the residual sigma
///      r^2 = (sigma^2 - (4^k - 1) / 4) / 4^k - 1/6   (level pixels),
///    where (4^k - 1) / 4 is the variance the k halvings already applied (full-resolution
///    pixels^2) and 1/6 the mean variance the bilinear upsampling adds (weights t, 1 - t give
///    variance t (1 - t), 1/6 on average over t); the caller reads the result bilinearly at full
///    resolution. Cost ~ (1 + 1/4 + 1/16 ...) of a copy plus a tiny blur, whatever sigma is.
/// Error and time against Exact: docs/compositor.md, tests/xr/render/blur_pyramid_gl_test.cpp and
/// tests/bench/compositor_gl_bench.cpp.
#pragma once

#include <vector>

#include "xr/render/blur_method.h"
#include "xr/render/gl_program.h"
#include "xr/render/gl_texture.h"

namespace vdfx::xr {

/// Smallest sigma (level pixels) the pyramid blurs at: below it bilinear upsampling of the level
/// would show (the level must be smooth at its own sampling rate).
inline constexpr double kPyramidMinSigma = 2.0;

/// How a blur of (sigma_x, sigma_y) full-resolution pixels runs on the pyramid.
struct PyramidPlan {
  int halvings = 0;                           //!< k: the level is 2^k times smaller
  double residual_x = 0.0, residual_y = 0.0;  //!< sigma blurred at that level (level pixels)
};
/// k is the largest with min(sigma) / 2^k >= kPyramidMinSigma (0 for small sigmas: then the blur
/// is the exact one at full resolution); GL-free.
PyramidPlan plan_pyramid(double sigma_x, double sigma_y);

/// Smallest width of a tap table texture (64 pairs: radii up to 128 px, sigma ~42 px).
inline constexpr int kMinTapCapacity = 64;
/// Uploads the paired-tap table of a 1-D Gaussian (sigma px, radius taps per side) into `taps`
/// and sets u_taps (on texture unit `unit`), u_tap_count and u_centre_weight of `program`.
/// `taps` is (re)allocated only when it is empty or narrower than the table (it then grows to
/// kMinTapCapacity or by doubling), so a caller that keeps it allocates it about once.
void set_gaussian_uniforms(const GlProgram& program, double sigma, int radius, int unit,
                           GlTexture& taps);

class BlurPyramidGl {
 public:
  explicit BlurPyramidGl(TexFormat format = TexFormat::RGBA16F);
  ~BlurPyramidGl();
  BlurPyramidGl(const BlurPyramidGl&) = delete;
  BlurPyramidGl& operator=(const BlurPyramidGl&) = delete;

  /// A new source image: the halved chain is rebuilt (lazily, once) for it.
  void set_source(const GlTexture& src);
  /// Blurs the source by (sigma_x, sigma_y) full-resolution pixels into `out` (reallocated to
  /// the level's size when needed). Returns the level's scale: source pixels per texel of `out`
  /// (1 for Exact). Leaves the framebuffer bound to `out`.
  int blur(double sigma_x, double sigma_y, BlurMethod method, GlTarget& out);

 private:
  const GlTarget& level(int k);  //!< k >= 1: the source halved k times
  void blur_separable(const GlTexture& in, double sx, double sy, GlTarget& out);
  TexFormat format_;
  const GlTexture* src_ = nullptr;
  int built_ = 0;  //!< halved levels valid for the current source
  std::vector<GlTarget> chain_, tmp_;
  GlProgram blur_1d_, downsample_;
  GlTexture taps_[2];
  unsigned vao_ = 0;
};

}  // namespace vdfx::xr
