/// @file
/// @brief MipChainGl: one area-average reduction pass per mip level.
#include "xr/render/mip_chain_gl.h"

#include <epoxy/gl.h>

#include <algorithm>

#include "effects/video_shaders.h"
#include "xr/render/gl_context.h"

namespace vdfx::xr {

MipChainGl::MipChainGl()
    : program_(GlProgram::build("mip_level", fullscreen_vertex_source(),
                                effects::mip_level_fragment_source())) {
  glGenVertexArrays(1, &vao_);
  glGenFramebuffers(1, &fbo_);
}

MipChainGl::~MipChainGl() {
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
  if (vao_) glDeleteVertexArrays(1, &vao_);
}

void MipChainGl::build(unsigned texture, int width, int height, int levels) const {
  program_.use();
  glUniform1i(program_.uniform("u_src"), 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, texture);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glBindVertexArray(vao_);
  glDisable(GL_BLEND);
  for (int l = 1; l < levels; ++l) {
    width = std::max(1, width / 2);
    height = std::max(1, height / 2);
    // Only the level above is readable while this one is drawn: no feedback loop.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, l - 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, l - 1);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, l);
    glViewport(0, 0, width, height);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels - 1);
  check_gl("MipChainGl::build");
}

}  // namespace vdfx::xr
