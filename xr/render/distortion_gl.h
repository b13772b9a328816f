/// @file
/// @brief Lens pre-distortion (pixel- and mesh-based, with inverse lateral chromatic aberration)
/// and the through-the-lens simulation, on the GPU.
///
/// The lens model is effects/lens_model.h (r_d = f(r_u) on radii normalised by R, centred on the
/// optical axis, tangent (0, 0)). The panel image of an eye spans the same tangent rectangle as
/// its eye buffer (RenderView / effects::EyeLens), so a panel pixel at tangent t_d shows, per
/// channel c, the eye buffer at radius R f^-1(|t_d| / (R s_c)) along the same direction.
///  - Pixel: the fragment shader runs a capped Newton inverse per pixel and channel; black beyond
///    the valid radius (never a folded image) and outside the eye buffer.
///  - Mesh: effects::build_distortion_mesh (N x N, exact per-channel UVs in double) uploaded as
///    vertex attributes; the rasteriser interpolates them linearly. The valid-radius cut is done
///    per fragment, so the black edge is exact rather than following triangle edges. Cost no longer
///    depends on the iteration count; error falls with N (tests and docs/compositor.md).
///  - Through the lens: each pixel of what the wearer sees reads the panel at
///    r_d = s_c f(r_u): the forward model, to show the residual distortion and colour fringe.
#pragma once

#include <memory>

#include "effects/lens_model.h"
#include "xr/headset/render_view.h"
#include "xr/render/gl_texture.h"

namespace vdfx::xr {

enum class DistortionMethod { None, Pixel, Mesh };

struct DistortionSettings {
  DistortionMethod method = DistortionMethod::Mesh;
  int mesh_n = 65;          //!< vertices per side (Monado uses 65, Cardboard 40)
  int max_iterations = 8;   //!< Newton cap of the pixel method
  bool correct_lca = true;  //!< false: one inverse for all channels (shows the fringe)
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
                  const effects::LensModel& lens, const DistortionSettings& settings);
  /// Draws what the wearer sees through the lens when `panel` is shown (forward model).
  void through_lens(const GlTexture& panel, const GlTarget& seen, const RenderView& eye,
                    const effects::LensModel& lens);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vdfx::xr
