/// @file
/// @brief The GPU's mip chain of a texture: the area-average chain of effects/mip_chain.h, level
/// by level, in place of glGenerateMipmap (whose filter for odd sizes is the driver's choice).
#pragma once

#include "xr/render/gl_program.h"

namespace vdfx::xr {

class MipChainGl {
 public:
  /// Needs a current GL context.
  MipChainGl();
  ~MipChainGl();
  MipChainGl(const MipChainGl&) = delete;
  MipChainGl& operator=(const MipChainGl&) = delete;

  /// Fills levels 1..levels-1 of 2D texture `texture` (width x height at level 0, every level
  /// allocated, a colour-renderable format) from its level 0, one draw per level. Leaves the
  /// texture's base and max level at 0 and levels - 1, and the framebuffer binding at 0.
  void build(unsigned texture, int width, int height, int levels) const;

 private:
  GlProgram program_;
  unsigned vao_ = 0, fbo_ = 0;
};

}  // namespace vdfx::xr
