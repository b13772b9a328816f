/// @file
/// @brief The GL film-grain layer: draws a frame's grain layers (effects/grain_layout.h) into one
/// eye's buffer, in world space from that eye's pose (flare-grain.md, stereo rule 1).
///
/// Shader styles (headset, surface): a full-screen pass that intersects each pixel's ray with the
/// grain plane or sphere and evaluates the Perlin noise there (effects/grain_shaders.h; the CPU
/// reference is effects/grain_render.h). Volumetric styles (object_cloud, free_cloud): one
/// instanced camera-facing quad per particle, ray-cast against the particle's ellipsoid in the
/// fragment shader; the particles are uploaded once per refresh. Both blend premultiplied "over"
/// (ONE, ONE_MINUS_SRC_ALPHA) and leave the target's alpha alone. A frame with no layers (every
/// grain at intensity 0) draws nothing and binds nothing.
#pragma once

#include <cstdint>
#include <memory>
#include <span>

#include "effects/grain_layout.h"
#include "xr/gl_texture.h"
#include "xr/render_view.h"

namespace vdfx::xr {

/// What the layer has done since it was created (tests and benchmarks).
struct GrainLayerStats {
  std::int64_t shader_draws = 0;     //!< full-screen passes
  std::int64_t particle_draws = 0;   //!< instanced draws
  std::int64_t particle_uploads = 0;  //!< particle sets sent to the GPU
};

class GrainLayerGl {
 public:
  /// Compiles the programs; needs a current GL 4.3 context.
  static std::unique_ptr<GrainLayerGl> create();
  virtual ~GrainLayerGl() = default;

  /// Blends `layers` (in order) over `target` for the eye `view` (its orientation, position in
  /// LOCAL and tangent FOV; the target spans exactly that FOV).
  virtual void render(const GlTarget& target, const RenderView& view,
                      std::span<const effects::GrainFrame> layers) = 0;
  virtual GrainLayerStats stats() const = 0;
};

}  // namespace vdfx::xr
