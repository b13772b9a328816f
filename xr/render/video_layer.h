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
///
/// Decoded video frames arrive as io::Picture in the stream's own Y'CbCr layout: set_frame
/// uploads the planes as they are (mipmapped one-channel R8/R16 textures, row padding included,
/// no CPU conversion) and this layer's shader converts every sample it takes: luma and chroma
/// are filtered (trilinear, the chroma coordinate shifted by the stream's siting, as io/ycbcr.h
/// defines it), then the stream's matrix and range map the code values to R'G'B' (the same
/// affine map as the CPU reference), clamped to [0, 1]. The conversion is affine, so filtering
/// before it equals filtering after it except where the clamp acts (out-of-gamut codes).
#pragma once

#include <memory>
#include <opencv2/core.hpp>

#include "effects/stereo_layout.h"
#include "io/picture.h"
#include "xr/headset/render_view.h"
#include "xr/render/gl_texture.h"

namespace vdfx::xr {

enum class LodMode { Analytic, Derivatives, Base };

class VideoLayerGl {
 public:
  VideoLayerGl();
  ~VideoLayerGl();
  /// How frames hold the eyes and what they cover (docs/stereo.md); default mono 360. A stereo
  /// frame is uploaded as two images, one per eye, each with its own mip chain, so no filter
  /// reads across the halves' boundary; a VR180 image's columns are clamped, not wrapped, and
  /// the shader shows black outside its half turn (a kCoverageEdgeDeg fade inside the edge).
  /// Drops the current frame.
  void set_layout(const effects::StereoLayout& layout);
  const effects::StereoLayout& layout() const;
  /// Uploads an equirect frame (CV_8UC3/4 or CV_32FC3/4, BGR) and rebuilds the mip chain;
  /// reallocates when the size or depth changes. 8-bit frames are stored RGBA8, float RGBA32F.
  void set_frame(const cv::Mat& equirect);
  /// Uploads a decoded picture: Y'CbCr planes as they are (converted per sample by render(), see
  /// above), or packed RGB (CV_8UC3 / CV_32FC3, RGB order; channels swapped once on the CPU).
  void set_frame(const io::Picture& picture);
  /// Draws the layer into `target` (whole viewport) for one eye; before the first set_frame, a
  /// uniform dark grey (kNoFrameGrey).
  static constexpr float kNoFrameGrey = 0.08f;
  bool has_frame() const;
  /// `eye` (0 left, 1 right) picks the eye's image of stereo video; mono ignores it.
  void render(const GlTarget& target, const RenderView& view, LodMode lod = LodMode::Analytic,
              int eye = 0);
  /// The (left eye's) RGB texture (frames given as cv::Mat or RGB pictures; empty for Y'CbCr
  /// pictures).
  const GlTexture& texture() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vdfx::xr
