/// @file
/// @brief The GLX side of the OpenXR backend: XR_KHR_opengl_enable's Xlib binding of the current
/// context. The only file of the backend that includes Xlib (through libepoxy's GLX header).
#define XR_USE_PLATFORM_XLIB
#define XR_USE_GRAPHICS_API_OPENGL
// clang-format off: libepoxy first, so OpenXR's platform header sees its GL and GLX types.
#include <epoxy/gl.h>
#include <epoxy/glx.h>
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>
// clang-format on

#include <memory>

namespace vdfx::xr {

std::shared_ptr<const void> current_glx_binding();
const void* current_glx_context();

std::shared_ptr<const void> current_glx_binding() {
  GLXContext context = glXGetCurrentContext();
  Display* dpy = glXGetCurrentDisplay();
  if (!context || !dpy) return nullptr;
  auto b = std::make_shared<XrGraphicsBindingOpenGLXlibKHR>();
  *b = {};
  b->type = XR_TYPE_GRAPHICS_BINDING_OPENGL_XLIB_KHR;
  b->xDisplay = dpy;
  b->glxContext = context;
  b->glxDrawable = glXGetCurrentDrawable();
  // The frame-buffer configuration the context was made with, and its visual.
  int fbconfig_id = 0, count = 0;
  glXQueryContext(dpy, context, GLX_FBCONFIG_ID, &fbconfig_id);
  const int attributes[] = {GLX_FBCONFIG_ID, fbconfig_id, None};
  GLXFBConfig* configs = glXChooseFBConfig(dpy, DefaultScreen(dpy), attributes, &count);
  if (configs && count > 0) {
    b->glxFBConfig = configs[0];
    int visual = 0;
    glXGetFBConfigAttrib(dpy, configs[0], GLX_VISUAL_ID, &visual);
    b->visualid = static_cast<std::uint32_t>(visual);
  }
  if (configs) XFree(configs);
  return b;
}

const void* current_glx_context() {
  return glXGetCurrentContext();
}

}  // namespace vdfx::xr
