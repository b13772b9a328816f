/// @file
/// @brief The compositor's seam for world-space layers: drawn into each eye after the effect
/// stack and before the UI quads and lens pre-distortion, in the order given (flare, then grain;
/// shared/guide/flare-grain.md, stereo rule 4). Effects never see them; they never touch panels.
///
/// A layer holds this frame's content (set once per frame, from the head pose) and draws it
/// from each eye's own pose and FOV, so both eyes see one set of 3-D elements and disparity comes
/// from geometry (stereo rules 1 and 2). GL-free header; implementations are GL (flare_gl.cpp,
/// grain_gl.cpp).
#pragma once

#include "xr/headset/render_view.h"

namespace vdfx::xr {

class EyeLayer {
 public:
  virtual ~EyeLayer() = default;
  /// Stage name for GPU timing (--stats), e.g. "flare".
  virtual const char* name() const = 0;
  /// Draws into the bound eye buffer (framebuffer and viewport, width x height, set by the
  /// compositor) as seen by `view` (that eye's pose and FOV); eye 0 is left, 1 right. Leaves
  /// blending disabled.
  virtual void draw(const RenderView& view, int eye, int width, int height) = 0;
};

}  // namespace vdfx::xr
