/// @file
/// @brief The video layer: each pixel samples the equirect along its own view ray.
///
/// No tessellated sphere: a full-screen pass turns the pixel's tangent coordinates into a world
/// ray (RenderView) and the ray into equirect (u, v) (contract). The texture wraps in u (azimuth)
/// only; its mip chain is the area-average chain of effects/mip_chain.h, drawn level by level
/// (MipChainGl), not glGenerateMipmap.
///
/// LodMode::Footprint (the default, the project's definition of a view pixel): the pixel's
/// footprint filtered from the mip chain exactly as the CPU reference does
/// (effects/pixel_footprint.h): the analytic Jacobian of (u, v) with respect to the pixel, taps
/// along its major axis through each tap's own ray, each a textureLod at the minor axis' level,
/// box weights. Explicit taps rather than the hardware's anisotropic filtering: the hardware's
/// choice of taps and levels differs between GPUs (and llvmpipe), so it could not be held to the
/// CPU reference; explicit taps make CPU and GPU agree up to float precision and 8-bit texels.
/// set_max_anisotropy() is the knob (the CPU's SamplerOptions::max_anisotropy).
///
/// The older isotropic choices remain as peers for `vdfx bench` and tests:
/// LodMode::Analytic: textureGrad with the exact screen-space Jacobian of (u, v). With the world
/// ray d = R (tx, ty, -1), one pixel step in x moves d by R_x (tan_right - tan_left) / W
/// (R_x = first column of R), and
///   d az  = (-d_z dd_x + d_x dd_z) / h^2,          h = |(d_x, d_z)|,
///   d alt = (h dd_y - d_y dh) / |d|^2,              dh = (d_x dd_x + d_z dd_z) / h,
///   du = d az / 2 pi,  dt = d alt / pi  (texture t = 1 - v, see gl_texture.h).
/// GL's isotropic LOD (the larger axis) blurs across rows near the poles, where the footprint is
/// long and thin. LodMode::Derivatives uses hardware dFdx/dFdy of u and of u shifted by half a
/// turn, taking the smaller, so the seam column does not see a derivative of ~1.
/// LodMode::Base samples level 0 only (aliases wherever the view shrinks the image).
///
/// Decoded video frames arrive as io::Picture in the stream's own Y'CbCr layout: set_frame
/// uploads the planes as they are (mipmapped one-channel R8/R16 textures, row padding included,
/// no CPU conversion) and this layer's shader converts every sample it takes: luma and chroma
/// are filtered (each tap trilinear, the chroma planes one level finer per halving, the chroma
/// coordinate shifted by the stream's siting, as io/ycbcr.h defines it), then the stream's matrix
/// and range map the code values to R'G'B' (the same affine map as the CPU reference), clamped to
/// [0, 1]. The conversion is affine, so filtering before it equals filtering after it except where
/// the clamp acts (out-of-gamut codes).
#pragma once

#include <memory>
#include <opencv2/core.hpp>

#include "effects/pixel_footprint.h"
#include "effects/stereo_layout.h"
#include "io/picture.h"
#include "xr/headset/render_view.h"
#include "xr/render/gl_texture.h"

namespace vdfx::xr {

/// The values are the shader's u_lod_mode.
enum class LodMode { Analytic = 0, Derivatives = 1, Base = 2, Footprint = 3 };

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
  void render(const GlTarget& target, const RenderView& view, LodMode lod = LodMode::Footprint,
              int eye = 0);
  /// LodMode::Footprint: the largest ratio of the footprint's axes resolved by taps (>= 1;
  /// default effects::kDefaultMaxAnisotropy). Throws GlError otherwise.
  void set_max_anisotropy(double ratio);
  /// The (left eye's) RGB texture (frames given as cv::Mat or RGB pictures; empty for Y'CbCr
  /// pictures).
  const GlTexture& texture() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vdfx::xr
