/// @file
/// @brief The video layer: each pixel samples the equirect along its own view ray.
///
/// No tessellated sphere: a full-screen pass turns the pixel's tangent coordinates into a world
/// ray (RenderView) and the ray into equirect (u, v) (contract). The texture is mipmapped and
/// wraps in u (azimuth) only.
///
/// Mip level (LodMode::Analytic, the default): textureGrad with the exact screen-space Jacobian of
/// (u, v). With the world ray d = R (tx, ty, -1), one pixel step in x moves d by
/// R_x (tan_right - tan_left) / W (R_x = first column of R), and
///   d az  = (-d_z dd_x + d_x dd_z) / h^2,          h = |(d_x, d_z)|,
///   d alt = (h dd_y - d_y dh) / |d|^2,              dh = (d_x dd_x + d_z dd_z) / h,
///   du = d az / 2 pi,  dt = d alt / pi  (texture t = 1 - v, see gl_texture.h).
/// It is smooth across the azimuth seam (no u jump enters it) and grows as 1/h towards the poles,
/// where equirect rows shrink: the sampler then reads the coarser level that the row's shrinking
/// footprint needs, which removes the aliasing. GL's isotropic LOD (the larger axis) blurs v a
/// little more than needed near the poles; tests measure against a supersampled reference.
/// LodMode::Derivatives uses hardware dFdx/dFdy of u and of u shifted by half a turn, taking the
/// smaller, so the seam column does not see a derivative of ~1 (which would pick the smallest
/// mip and draw a line). LodMode::Base samples level 0 only (aliases at the poles; for tests).
#pragma once

#include <memory>

#include <opencv2/core.hpp>

#include "io/picture.h"
#include "xr/gl_texture.h"
#include "xr/render_view.h"

namespace vdfx::xr {

enum class LodMode { Analytic, Derivatives, Base };

class VideoLayerGl {
 public:
  VideoLayerGl();
  ~VideoLayerGl();
  /// Uploads an equirect frame (CV_8UC3/4 or CV_32FC3/4, BGR) and rebuilds the mip chain;
  /// reallocates when the size or depth changes. 8-bit frames are stored RGBA8, float RGBA32F.
  void set_frame(const cv::Mat& equirect);
  /// Uploads a decoded picture: Y'CbCr planes converted on the GPU (see above), or packed RGB
  /// (CV_8UC3 / CV_32FC3, RGB order) as it is. Rebuilds the mip chain.
  void set_frame(const io::Picture& picture);
  /// Draws the layer into `target` (whole viewport) for one eye.
  void render(const GlTarget& target, const RenderView& view, LodMode lod = LodMode::Analytic);
  const GlTexture& texture() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vdfx::xr
