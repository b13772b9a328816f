/// @file
/// @brief What the simulated OpenXR runtime adds to an app's frame (docs/openxr.md, "Testing
/// without a headset"): xrWaitFrame, xrBeginFrame, xrEndFrame and the swapchain calls of two
/// generic90 eyes (1440 x 1600, GL_SRGB8_ALPHA8), without and with the read-back of every frame
/// (VDFX_TEST_RUNTIME_CAPTURE=last, the default when an output folder is set). The app renders
/// nothing: the time is the runtime's. Run under a display (xvfb-run -a).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

// clang-format off: libepoxy first, so OpenXR's platform header sees its GL and GLX types.
#include <epoxy/gl.h>
#include <epoxy/glx.h>
#define XR_USE_PLATFORM_XLIB
#define XR_USE_GRAPHICS_API_OPENGL
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>
// clang-format on
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace {

constexpr std::uint32_t kWidth = 1440, kHeight = 1600;  // generic90's eyes

/// A session on a hidden window's context, past its first frame (FOCUSED), with one swapchain
/// per eye; every failure stops the benchmark with the call that failed.
class BenchSession {
 public:
  explicit BenchSession(benchmark::State& state) : state_(state) {
    glfwInit();
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    window_ = glfwCreateWindow(64, 64, "vdfx runtime bench", nullptr, nullptr);
    if (!window_) {
      fail("no GL window (run under a display)");
      return;
    }
    glfwMakeContextCurrent(window_);
    XrInstanceCreateInfo info{};
    info.type = XR_TYPE_INSTANCE_CREATE_INFO;
    std::strcpy(info.applicationInfo.applicationName, "vdfx runtime bench");
    info.applicationInfo.apiVersion = XR_CURRENT_API_VERSION;
    const char* ext = XR_KHR_OPENGL_ENABLE_EXTENSION_NAME;
    info.enabledExtensionCount = 1;
    info.enabledExtensionNames = &ext;
    if (XR_FAILED(xrCreateInstance(&info, &instance_))) {
      fail("xrCreateInstance");
      return;
    }
    XrSystemGetInfo sys{XR_TYPE_SYSTEM_GET_INFO, nullptr, XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY};
    if (XR_FAILED(xrGetSystem(instance_, &sys, &system_))) {
      fail("xrGetSystem");
      return;
    }
    PFN_xrVoidFunction f = nullptr;
    xrGetInstanceProcAddr(instance_, "xrGetOpenGLGraphicsRequirementsKHR", &f);
    XrGraphicsRequirementsOpenGLKHR req{XR_TYPE_GRAPHICS_REQUIREMENTS_OPENGL_KHR, nullptr, 0, 0};
    reinterpret_cast<PFN_xrGetOpenGLGraphicsRequirementsKHR>(f)(instance_, system_, &req);
    XrGraphicsBindingOpenGLXlibKHR binding{};
    binding.type = XR_TYPE_GRAPHICS_BINDING_OPENGL_XLIB_KHR;
    binding.xDisplay = glXGetCurrentDisplay();
    binding.glxContext = glXGetCurrentContext();
    binding.glxDrawable = glXGetCurrentDrawable();
    XrSessionCreateInfo sci{XR_TYPE_SESSION_CREATE_INFO, &binding, 0, system_};
    if (XR_FAILED(xrCreateSession(instance_, &sci, &session_))) {
      fail("xrCreateSession");
      return;
    }
    XrReferenceSpaceCreateInfo space{XR_TYPE_REFERENCE_SPACE_CREATE_INFO,
                                     nullptr,
                                     XR_REFERENCE_SPACE_TYPE_LOCAL,
                                     {{0, 0, 0, 1}, {0, 0, 0}}};
    xrCreateReferenceSpace(session_, &space, &local_);
    for (auto& sc : swapchains_) {
      XrSwapchainCreateInfo c{};
      c.type = XR_TYPE_SWAPCHAIN_CREATE_INFO;
      c.usageFlags = XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT;
      c.format = GL_SRGB8_ALPHA8;
      c.sampleCount = c.faceCount = c.arraySize = c.mipCount = 1;
      c.width = kWidth;
      c.height = kHeight;
      if (XR_FAILED(xrCreateSwapchain(session_, &c, &sc))) {
        fail("xrCreateSwapchain");
        return;
      }
    }
    XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO, nullptr,
                             XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO};
    if (XR_FAILED(xrBeginSession(session_, &begin))) {
      fail("xrBeginSession");
      return;
    }
    frame(false);  // frame 0 makes the session FOCUSED
  }

  ~BenchSession() {
    if (session_ != XR_NULL_HANDLE) xrDestroySession(session_);
    if (instance_ != XR_NULL_HANDLE) xrDestroyInstance(instance_);
    if (window_) glfwDestroyWindow(window_);
  }

  bool ok() const { return ok_; }

  /// One frame: wait, begin, each eye's image acquired, waited and released, end with the
  /// projection layer (or none).
  void frame(bool layer) {
    XrFrameState fs{XR_TYPE_FRAME_STATE, nullptr, 0, 0, XR_FALSE};
    xrWaitFrame(session_, nullptr, &fs);
    xrBeginFrame(session_, nullptr);
    XrCompositionLayerProjectionView views[2]{};
    for (int eye = 0; eye < 2; ++eye) {
      std::uint32_t index = 0;
      xrAcquireSwapchainImage(swapchains_[eye], nullptr, &index);
      XrSwapchainImageWaitInfo wait{XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO, nullptr,
                                    XR_INFINITE_DURATION};
      xrWaitSwapchainImage(swapchains_[eye], &wait);
      xrReleaseSwapchainImage(swapchains_[eye], nullptr);
      views[eye].type = XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW;
      views[eye].pose = {{0, 0, 0, 1}, {0, 1.6f, 0}};
      views[eye].fov = {-0.8f, 0.8f, 0.8f, -0.8f};
      views[eye].subImage = {swapchains_[eye], {{0, 0}, {int(kWidth), int(kHeight)}}, 0};
    }
    XrCompositionLayerProjection projection{
        XR_TYPE_COMPOSITION_LAYER_PROJECTION, nullptr, 0, local_, 2, views};
    const XrCompositionLayerBaseHeader* layers[] = {
        reinterpret_cast<const XrCompositionLayerBaseHeader*>(&projection)};
    XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO,           nullptr,         fs.predictedDisplayTime,
                       XR_ENVIRONMENT_BLEND_MODE_OPAQUE, layer ? 1u : 0u, layers};
    if (XR_FAILED(xrEndFrame(session_, &end))) fail("xrEndFrame");
  }

 private:
  void fail(const char* what) {
    ok_ = false;
    state_.SkipWithError(what);
  }

  benchmark::State& state_;
  GLFWwindow* window_ = nullptr;
  XrInstance instance_ = XR_NULL_HANDLE;
  XrSystemId system_ = 0;
  XrSession session_ = XR_NULL_HANDLE;
  XrSpace local_ = XR_NULL_HANDLE;
  XrSwapchain swapchains_[2] = {XR_NULL_HANDLE, XR_NULL_HANDLE};
  bool ok_ = true;
};

/// Arguments: whether a projection layer is submitted, whether every frame is read back.
void BM_TestRuntimeFrame(benchmark::State& state) {
  const bool layer = state.range(0) != 0;
  const bool capture = state.range(1) != 0;
  setenv("XR_RUNTIME_JSON", VDFX_TEST_RUNTIME_MANIFEST, 1);
  unsetenv("XR_ENABLE_API_LAYERS");  // the runtime's time, not the layer's
  const auto out = std::filesystem::temp_directory_path() / "vdfx_runtime_bench";
  setenv("VDFX_TEST_RUNTIME_OUTPUT_DIR", out.c_str(), 1);
  setenv("VDFX_TEST_RUNTIME_CAPTURE", capture ? "last" : "none", 1);
  {
    BenchSession s(state);
    if (!s.ok()) return;
    for (auto _ : state) {
      const auto t0 = std::chrono::steady_clock::now();
      s.frame(layer);
      glFinish();
      state.SetIterationTime(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
  }
  std::filesystem::remove_all(out);
}
BENCHMARK(BM_TestRuntimeFrame)
    ->ArgNames({"layer", "readback"})
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({1, 1})
    ->UseManualTime()
    ->Unit(benchmark::kMicrosecond);

}  // namespace
