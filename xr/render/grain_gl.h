/// @file
/// @brief The GL film-grain layer: this frame's grain layers (effects/grain_layout.h, laid out
/// once from the head pose) drawn into each eye in world space from that eye's own pose and FOV
/// (flare-grain.md, stereo rule 1), after the flare and before the UI quads
/// (xr/render/eye_layer.h).
///
/// Shader styles (headset, surface): a full-screen pass that intersects each pixel's ray with the
/// grain plane or sphere and evaluates the Perlin noise there (effects/grain_shaders.h; the CPU
/// reference is effects/grain_render.h, from the same uniforms). Volumetric styles
/// (object_cloud, free_cloud): one instanced camera-facing quad per particle, ray-cast against
/// the particle's ellipsoid in the fragment shader. The vertex stage generates particle
/// gl_InstanceID from the refresh's key as effects::grain_particle defines it: no particle is
/// sampled on the CPU or uploaded, whatever the count. Both modulate the eye colour C by their
/// grain value s (dual-source blending ONE, SRC1_COLOR: C becomes s floor + C (1 + s)) and leave
/// the eye buffer's alpha alone. A frame without layers (every grain at intensity 0) draws nothing.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "effects/grain_layout.h"
#include "xr/render/eye_layer.h"

namespace vdfx::xr {

/// What the layer has done since it was created (tests and benchmarks).
struct GrainLayerStats {
  std::int64_t shader_draws = 0;     //!< full-screen passes
  std::int64_t particle_draws = 0;   //!< instanced draws
  std::int64_t particles_drawn = 0;  //!< instances those draws generated
};

class GrainGl final : public EyeLayer {
 public:
  /// Compiles the programs; needs a current GL 4.3 context.
  GrainGl();
  ~GrainGl() override;
  GrainGl(const GrainGl&) = delete;
  GrainGl& operator=(const GrainGl&) = delete;

  /// This frame's grain layers, in order (both eyes draw them); empty draws nothing.
  void set_layers(std::vector<effects::GrainFrame> layers);
  const std::vector<effects::GrainFrame>& layers() const;

  const char* name() const override { return "grain"; }
  /// Blends the layers over the bound eye buffer (width x height spanning the view's FOV).
  void draw(const RenderView& view, int eye, int width, int height) override;

  GrainLayerStats stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vdfx::xr
