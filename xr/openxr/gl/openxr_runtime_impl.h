/// @file
/// @brief The OpenXR backend's state, shared by its files (xr/openxr/gl/*.cpp); nothing else
/// includes this header. It pulls in GL (libepoxy) and OpenXR's OpenGL types, not Xlib: Xlib's
/// macros (None, Success, Bool) break Eigen and vdfx's enums, so the GLX binding is made in
/// xr/openxr/gl/openxr_glx.cpp alone.
#pragma once

#define XR_USE_GRAPHICS_API_OPENGL
// clang-format off: libepoxy first, so OpenXR's platform header sees the GL types.
#include <epoxy/gl.h>
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>
// clang-format on

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "xr/openxr/gl/openxr_runtime.h"
#include "xr/openxr/openxr_bindings.h"
#include "xr/render/gl_program.h"

namespace vdfx::xr {

/// "XR_ERROR_FORM_FACTOR_UNAVAILABLE" (from openxr_reflection.h; works without an instance).
const char* xr_result_name(XrResult result);

/// A failed OpenXR call the user cannot fix by a set-up step: an internal error (exit 3) naming
/// the call and the result.
class OpenXrCallError : public std::runtime_error {
 public:
  OpenXrCallError(const char* call, XrResult result);
  XrResult result() const { return result_; }

 private:
  XrResult result_;
};

/// Throws OpenXrCallError unless XR_SUCCEEDED(result).
void xr_check(XrResult result, const char* call);

/// An OpenXR struct with its type set and everything else zero (next = nullptr).
template <typename T>
T xr_struct(XrStructureType type) {
  T s{};
  s.type = type;
  return s;
}

/// XR_KHR_opengl_enable's Xlib binding of the GL context current on this thread (an
/// XrGraphicsBindingOpenGLXlibKHR for XrSessionCreateInfo::next); null when that context is not
/// a GLX one (EGL, or none current). xr/openxr/gl/openxr_glx.cpp.
std::shared_ptr<const void> current_glx_binding();
/// The current GLX context (null: none), to notice a runtime that changed it.
const void* current_glx_context();

/// One swapchain with a framebuffer per image (vdfx renders into them with GL).
struct OpenXrSwapchain {
  XrSwapchain handle = XR_NULL_HANDLE;
  int width = 0, height = 0;
  std::vector<GLuint> images;
  std::vector<GLuint> fbos;
  std::uint32_t acquired = 0;  //!< index of the image acquired this frame
  bool held = false;           //!< acquired and not yet released
};

struct OpenXrRuntime::Impl {
  OpenXrOptions options;
  XrInstance instance = XR_NULL_HANDLE;
  XrSystemId system = XR_NULL_SYSTEM_ID;
  OpenXrSystemInfo info;
  XrEnvironmentBlendMode blend = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;

  // Actions (created with the instance; attached to the session).
  XrActionSet action_set = XR_NULL_HANDLE;
  std::array<XrAction, kOpenXrActionCount> actions{};
  std::array<XrPath, 2> hand_paths{};  //!< left, right

  // The session and what lives in it.
  XrSession session = XR_NULL_HANDLE;
  XrSpace local = XR_NULL_HANDLE;  //!< vdfx's LOCAL: OpenXR's STAGE, else LOCAL moved down
  std::string world_space_name;    //!< which of the two (vdfx hmd openxr prints it)
  XrSpace view = XR_NULL_HANDLE;
  std::array<XrSpace, 2> aim{};  //!< per hand
  OpenXrLifecycle lifecycle;
  OpenXrSwapchainInfo swapchain_info;
  std::array<OpenXrSwapchain, 2> eyes;
  std::unordered_map<unsigned, OpenXrSwapchain> quad_chains;  //!< by the panel's GL texture
  GlProgram copy_program;
  GLuint copy_vao = 0;

  // The GL context the session is bound to (SteamVR may change the current one inside xr calls).
  GLFWwindow* window = nullptr;
  const void* glx_context = nullptr;
  int context_restores = 0;  //!< how often an xr call left another context current

  // The frame in flight.
  bool frame_begun = false;
  XrTime xr_time = 0;
  std::optional<XrTime> epoch;
  std::array<XrView, 2> views{};
  std::array<bool, 2> eye_submitted{};
  std::vector<XrCompositionLayerQuad> quad_layers;

  ~Impl();

  // Instance (openxr_instance.cpp).
  void create_instance();
  void get_system();
  void read_views();
  void create_actions();

  // Session (openxr_session.cpp).
  void check_gl_requirements();
  void create_session(GLFWwindow* w);
  void create_spaces();
  std::vector<std::int64_t> enumerate_formats();
  void handle_event(const XrEventDataBuffer& event);
  /// After xr calls that may run another GL context (SteamVR does): vdfx's is made current again.
  void restore_context();
  void destroy_session();

  // Swapchains (openxr_swapchain.cpp).
  OpenXrSwapchain create_swapchain(std::int64_t format, int width, int height);
  void destroy_swapchain(OpenXrSwapchain& chain);
  /// Acquires an image, draws `src` into it through the copy program (flip: the source's first
  /// row is the image's top; premultiplied: a panel's alpha), releases it.
  void copy_into(OpenXrSwapchain& chain, GLuint src_texture, bool flip, bool premultiplied);
};

}  // namespace vdfx::xr
