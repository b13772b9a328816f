/// @file
/// @brief A small OpenXR app for the runtime's tests: a hidden GLFW window's GLX context, and the
/// calls every test repeats (instance, system, session, spaces, swapchains, one frame) through
/// the Khronos loader, with the environment of test_runtime_env.h applied.
#pragma once

// gtest before Xlib (below): X11's None and Bool macros would break gtest's headers.
#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

// clang-format off: libepoxy first, so OpenXR's platform header sees its GL and GLX types.
#include <epoxy/gl.h>
#include <epoxy/glx.h>
#define XR_USE_PLATFORM_XLIB
#define XR_USE_GRAPHICS_API_OPENGL
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>
// clang-format on

struct GLFWwindow;

namespace vdfx::test_runtime {

/// Fails the test (ADD_FAILURE with the result's name) unless `r` succeeded; returns `r`.
XrResult expect_ok(XrResult r, const char* what);
#define XR_EXPECT_OK(call) ::vdfx::test_runtime::expect_ok((call), #call)

class XrTestApp {
 public:
  /// A hidden window with an OpenGL 3.3 core context, current on this thread.
  XrTestApp();
  ~XrTestApp();
  XrTestApp(const XrTestApp&) = delete;
  XrTestApp& operator=(const XrTestApp&) = delete;

  /// `more`: extensions enabled besides OpenGL's.
  XrResult create_instance(bool opengl = true, const std::vector<const char*>& more = {});
  XrResult get_system();
  /// xrGetOpenGLGraphicsRequirementsKHR, then the session on the window's context.
  XrResult create_session();
  /// Instance, system and session; fails the test on the way if one fails.
  bool start();

  /// Polls every queued event; returns the session states in order.
  std::vector<XrSessionState> poll_states();
  /// Polls until `state` came (or no event is left); true if it came.
  bool poll_until(XrSessionState state);
  /// xrBeginSession (stereo) after READY.
  XrResult begin_session();

  XrSpace reference_space(XrReferenceSpaceType type, const XrPosef& pose = identity());
  XrSwapchain swapchain(std::int64_t format, std::uint32_t width, std::uint32_t height,
                        std::uint32_t array_size = 1);
  std::vector<GLuint> images(XrSwapchain sc);
  /// Acquires and waits for the next image, binds it to `framebuffer` (a 2D texture, or layer
  /// `array_layer` of an array swapchain), runs `draw`, releases it.
  void render(XrSwapchain sc, const std::function<void()>& draw, int array_layer = -1);
  /// render() clearing the image to `rgba`.
  void render_clear(XrSwapchain sc, const float rgba[4], int array_layer = -1);

  XrFrameState wait_frame();
  XrResult begin_frame();
  XrResult end_frame(const std::vector<const XrCompositionLayerBaseHeader*>& layers,
                     XrTime display_time);
  /// One whole frame with no layers; returns its frame state.
  XrFrameState empty_frame();

  static XrPosef identity();

  XrInstance instance = XR_NULL_HANDLE;
  XrSystemId system = XR_NULL_SYSTEM_ID;
  XrSession session = XR_NULL_HANDLE;
  GLFWwindow* window = nullptr;
  GLuint framebuffer = 0;

 private:
  std::vector<XrSwapchain> swapchains_;
  std::vector<XrSpace> spaces_;
};

/// xrGetInstanceProcAddr for an extension function, typed.
template <class F>
F instance_function(XrInstance instance, const char* name) {
  PFN_xrVoidFunction f = nullptr;
  xrGetInstanceProcAddr(instance, name, &f);
  return reinterpret_cast<F>(f);
}

}  // namespace vdfx::test_runtime
