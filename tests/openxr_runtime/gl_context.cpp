/// @file
/// @brief Making the app's GL context current around the runtime's GL work.
#include "tests/openxr_runtime/gl_context.h"

namespace vdfx::test_runtime {
namespace {

/// The context the runtime leaves current when asked to behave as SteamVR does: its own, on the
/// app's drawable, with the app's framebuffer configuration.
GLXContext own_context(Session& s) {
  if (s.own_context) return s.own_context;
  GLXFBConfig config = s.gl.fbconfig;
  if (!config) {
    int id = 0;
    glXQueryContext(s.gl.display, s.gl.context, GLX_FBCONFIG_ID, &id);
    const int attributes[] = {GLX_FBCONFIG_ID, id, 0};
    int n = 0;
    GLXFBConfig* configs =
        glXChooseFBConfig(s.gl.display, DefaultScreen(s.gl.display), attributes, &n);
    if (configs && n > 0) config = configs[0];
    if (configs) XFree(configs);
  }
  if (config)
    s.own_context = glXCreateNewContext(s.gl.display, config, GLX_RGBA_TYPE, nullptr, True);
  return s.own_context;
}

}  // namespace

GlContextScope::GlContextScope(Session& session) : session_(session) {
  saved_context_ = glXGetCurrentContext();
  if (saved_context_ == session.gl.context) return;
  saved_display_ = glXGetCurrentDisplay();
  saved_draw_ = glXGetCurrentDrawable();
  saved_read_ = glXGetCurrentReadDrawable();
  glXMakeContextCurrent(session.gl.display, session.gl.drawable, session.gl.drawable,
                        session.gl.context);
  switched_ = true;
}

GlContextScope::~GlContextScope() {
  if (session_.switch_context) {
    if (GLXContext own = own_context(session_)) {
      glXMakeContextCurrent(session_.gl.display, session_.gl.drawable, session_.gl.drawable, own);
      return;
    }
  }
  if (!switched_) return;
  if (saved_context_) {
    glXMakeContextCurrent(saved_display_, saved_draw_, saved_read_, saved_context_);
  } else {
    glXMakeContextCurrent(session_.gl.display, None, None, nullptr);
  }
}

void destroy_own_context(Session& session) {
  if (!session.own_context) return;
  if (glXGetCurrentContext() == session.own_context) {
    glXMakeContextCurrent(session.gl.display, session.gl.drawable, session.gl.drawable,
                          session.gl.context);
  }
  glXDestroyContext(session.gl.display, session.own_context);
  session.own_context = nullptr;
}

}  // namespace vdfx::test_runtime
