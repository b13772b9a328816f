/// @file
/// @brief The app's GL context around the runtime's GL work. XR_KHR_opengl_enable lets the app
/// leave its context current or not during xrCreateSwapchain, xrEndFrame and the like (it only
/// must not be current on another thread), so the runtime makes it current itself when needed
/// and puts back what was current after.
#pragma once

#include "tests/openxr_runtime/runtime.h"

namespace vdfx::test_runtime {

class GlContextScope {
 public:
  explicit GlContextScope(Session& session);
  ~GlContextScope();
  GlContextScope(const GlContextScope&) = delete;
  GlContextScope& operator=(const GlContextScope&) = delete;

 private:
  Session& session_;
  Display* saved_display_ = nullptr;
  GLXDrawable saved_draw_ = 0;
  GLXDrawable saved_read_ = 0;
  GLXContext saved_context_ = nullptr;
  bool switched_ = false;
};

/// VDFX_TEST_RUNTIME_SWITCH_CONTEXT's context (made on first use), destroyed with the session.
void destroy_own_context(Session& session);

}  // namespace vdfx::test_runtime
