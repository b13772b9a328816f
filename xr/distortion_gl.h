/// @file
/// @brief Lens pre-distortion (pixel- and mesh-based, with inverse lateral chromatic aberration)
/// and the through-the-lens simulation, on the GPU.
///
/// The panel image of an eye spans the same tangent rectangle as its eye buffer (RenderView), so a
/// panel pixel at tangent t_d (radius r_d about the optical centre) shows, per channel c, the eye
/// buffer at radius r_u = f^-1(r_d / s_c) along the same direction (lens_distortion.h).
///  - Pixel: the fragment shader runs a capped Newton inverse per pixel and channel; black beyond
///    the valid radius (never a folded image) and outside the eye buffer.
///  - Mesh: an N x N grid over the panel whose vertices carry one eye-buffer UV per channel,
///    computed on the CPU in double; the rasteriser interpolates them linearly. Cost no longer
///    depends on the iteration count; error falls with N (tests and docs/compositor.md).
///  - Through the lens: each pixel of what the wearer sees reads the panel at
///    r_d = s_c f(r_u): the forward model, to show the residual distortion and colour fringe.
#pragma once

#include <memory>

#include "xr/gl_texture.h"
#include "xr/lens_distortion.h"
#include "xr/render_view.h"

namespace vdfx::xr {

enum class DistortionMethod { None, Pixel, Mesh };

struct DistortionSettings {
  DistortionMethod method = DistortionMethod::Mesh;
  int mesh_n = 65;           //!< vertices per side (Monado uses 65, Cardboard 40)
  int max_iterations = 8;    //!< Newton cap of the pixel method
  bool correct_lca = true;   //!< false: one inverse for all channels (shows the fringe)
  /// Tests and error measurement: write the green channel's eye-buffer sample position in
  /// pixels (GL convention, origin bottom-left) to an RG32F target instead of colour.
  bool output_sample_position = false;
};

class DistortionGl {
 public:
  DistortionGl();
  ~DistortionGl();
  /// Draws the pre-distorted panel image of `eye_buffer` into `panel`.
  void predistort(const GlTexture& eye_buffer, const GlTarget& panel, const RenderView& eye,
                  const LensDistortion& lens, const DistortionSettings& settings);
  /// Draws what the wearer sees through the lens when `panel` is shown (forward model).
  void through_lens(const GlTexture& panel, const GlTarget& seen, const RenderView& eye,
                    const LensDistortion& lens);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vdfx::xr
