/// @file
/// @brief The runtime tests' OpenXR app.
#include "tests/openxr/xr_test_app.h"

#include <gtest/gtest.h>

#include <cstring>

// After epoxy (xr_test_app.h): GLFW must not include the system GL header itself.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace vdfx::test_runtime {

namespace {

std::string result_text(XrResult r) {
  char name[XR_MAX_RESULT_STRING_SIZE] = {};
  // Without an instance the loader cannot name it: the number is enough then.
  if (xrResultToString(XR_NULL_HANDLE, r, name) != XR_SUCCESS) return std::to_string(r);
  return name;
}

}  // namespace

XrResult expect_ok(XrResult r, const char* what) {
  if (XR_FAILED(r)) ADD_FAILURE() << what << " returned " << r << " " << result_text(r);
  return r;
}

XrPosef XrTestApp::identity() {
  XrPosef p{};
  p.orientation.w = 1.0f;
  return p;
}

XrTestApp::XrTestApp() {
  if (!glfwInit()) {
    ADD_FAILURE() << "glfwInit failed: is there a display (DISPLAY, Xvfb)?";
    return;
  }
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  window = glfwCreateWindow(64, 64, "vdfx OpenXR test", nullptr, nullptr);
  if (!window) {
    ADD_FAILURE() << "no GL window";
    return;
  }
  glfwMakeContextCurrent(window);
  glGenFramebuffers(1, &framebuffer);
}

XrTestApp::~XrTestApp() {
  if (window) glfwMakeContextCurrent(window);
  if (session != XR_NULL_HANDLE) {  // a test that destroyed the session destroyed these with it
    for (XrSwapchain sc : swapchains_) xrDestroySwapchain(sc);
    for (XrSpace sp : spaces_) xrDestroySpace(sp);
    xrDestroySession(session);
  }
  if (instance != XR_NULL_HANDLE) xrDestroyInstance(instance);
  if (window) {
    glDeleteFramebuffers(1, &framebuffer);
    glfwDestroyWindow(window);
  }
}

XrResult XrTestApp::create_instance(bool opengl, const std::vector<const char*>& more) {
  XrInstanceCreateInfo info{};
  info.type = XR_TYPE_INSTANCE_CREATE_INFO;
  std::strcpy(info.applicationInfo.applicationName, "vdfx runtime test");
  info.applicationInfo.apiVersion = XR_CURRENT_API_VERSION;
  std::vector<const char*> extensions = more;
  if (opengl) extensions.insert(extensions.begin(), XR_KHR_OPENGL_ENABLE_EXTENSION_NAME);
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.enabledExtensionNames = extensions.data();
  return xrCreateInstance(&info, &instance);
}

XrResult XrTestApp::get_system() {
  XrSystemGetInfo info{};
  info.type = XR_TYPE_SYSTEM_GET_INFO;
  info.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
  return xrGetSystem(instance, &info, &system);
}

XrResult XrTestApp::create_session() {
  auto requirements = instance_function<PFN_xrGetOpenGLGraphicsRequirementsKHR>(
      instance, "xrGetOpenGLGraphicsRequirementsKHR");
  XrGraphicsRequirementsOpenGLKHR req{};
  req.type = XR_TYPE_GRAPHICS_REQUIREMENTS_OPENGL_KHR;
  if (!requirements) return XR_ERROR_FUNCTION_UNSUPPORTED;
  XrResult r = requirements(instance, system, &req);
  if (XR_FAILED(r)) return r;
  XrGraphicsBindingOpenGLXlibKHR binding{};
  binding.type = XR_TYPE_GRAPHICS_BINDING_OPENGL_XLIB_KHR;
  binding.xDisplay = glXGetCurrentDisplay();
  binding.glxContext = glXGetCurrentContext();
  binding.glxDrawable = glXGetCurrentDrawable();
  XrSessionCreateInfo info{};
  info.type = XR_TYPE_SESSION_CREATE_INFO;
  info.next = &binding;
  info.systemId = system;
  return xrCreateSession(instance, &info, &session);
}

bool XrTestApp::start() {
  return window && XR_SUCCEEDED(XR_EXPECT_OK(create_instance())) &&
         XR_SUCCEEDED(XR_EXPECT_OK(get_system())) && XR_SUCCEEDED(XR_EXPECT_OK(create_session()));
}

std::vector<XrSessionState> XrTestApp::poll_states() {
  std::vector<XrSessionState> states;
  for (;;) {
    XrEventDataBuffer event{};
    event.type = XR_TYPE_EVENT_DATA_BUFFER;
    if (xrPollEvent(instance, &event) != XR_SUCCESS) return states;
    if (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
      states.push_back(reinterpret_cast<const XrEventDataSessionStateChanged&>(event).state);
    }
  }
}

bool XrTestApp::poll_until(XrSessionState state) {
  for (const XrSessionState s : poll_states()) {
    if (s == state) return true;
  }
  return false;
}

XrResult XrTestApp::begin_session() {
  XrSessionBeginInfo info{};
  info.type = XR_TYPE_SESSION_BEGIN_INFO;
  info.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  return xrBeginSession(session, &info);
}

XrSpace XrTestApp::reference_space(XrReferenceSpaceType type, const XrPosef& pose) {
  XrReferenceSpaceCreateInfo info{};
  info.type = XR_TYPE_REFERENCE_SPACE_CREATE_INFO;
  info.referenceSpaceType = type;
  info.poseInReferenceSpace = pose;
  XrSpace space = XR_NULL_HANDLE;
  XR_EXPECT_OK(xrCreateReferenceSpace(session, &info, &space));
  spaces_.push_back(space);
  return space;
}

XrSwapchain XrTestApp::swapchain(std::int64_t format, std::uint32_t width, std::uint32_t height,
                                 std::uint32_t array_size) {
  XrSwapchainCreateInfo info{};
  info.type = XR_TYPE_SWAPCHAIN_CREATE_INFO;
  info.usageFlags = XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT | XR_SWAPCHAIN_USAGE_SAMPLED_BIT;
  info.format = format;
  info.sampleCount = 1;
  info.width = width;
  info.height = height;
  info.faceCount = 1;
  info.arraySize = array_size;
  info.mipCount = 1;
  XrSwapchain sc = XR_NULL_HANDLE;
  XR_EXPECT_OK(xrCreateSwapchain(session, &info, &sc));
  swapchains_.push_back(sc);
  return sc;
}

std::vector<GLuint> XrTestApp::images(XrSwapchain sc) {
  uint32_t count = 0;
  XR_EXPECT_OK(xrEnumerateSwapchainImages(sc, 0, &count, nullptr));
  std::vector<XrSwapchainImageOpenGLKHR> images(count);
  for (auto& i : images) i = {XR_TYPE_SWAPCHAIN_IMAGE_OPENGL_KHR, nullptr, 0};
  XR_EXPECT_OK(xrEnumerateSwapchainImages(
      sc, count, &count, reinterpret_cast<XrSwapchainImageBaseHeader*>(images.data())));
  std::vector<GLuint> out;
  for (const auto& i : images) out.push_back(i.image);
  return out;
}

void XrTestApp::render(XrSwapchain sc, const std::function<void()>& draw, int array_layer) {
  const std::vector<GLuint> textures = images(sc);
  uint32_t index = 0;
  XR_EXPECT_OK(xrAcquireSwapchainImage(sc, nullptr, &index));
  XrSwapchainImageWaitInfo wait{};
  wait.type = XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO;
  wait.timeout = XR_INFINITE_DURATION;
  XR_EXPECT_OK(xrWaitSwapchainImage(sc, &wait));
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  if (array_layer >= 0) {
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, textures.at(index), 0,
                              array_layer);
  } else {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, textures.at(index),
                           0);
  }
  draw();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glFinish();
  XR_EXPECT_OK(xrReleaseSwapchainImage(sc, nullptr));
}

void XrTestApp::render_clear(XrSwapchain sc, const float rgba[4], int array_layer) {
  render(
      sc,
      [&] {
        glClearColor(rgba[0], rgba[1], rgba[2], rgba[3]);
        glClear(GL_COLOR_BUFFER_BIT);
      },
      array_layer);
}

XrFrameState XrTestApp::wait_frame() {
  XrFrameState state{};
  state.type = XR_TYPE_FRAME_STATE;
  XR_EXPECT_OK(xrWaitFrame(session, nullptr, &state));
  return state;
}

XrResult XrTestApp::begin_frame() {
  return xrBeginFrame(session, nullptr);
}

XrResult XrTestApp::end_frame(const std::vector<const XrCompositionLayerBaseHeader*>& layers,
                              XrTime display_time) {
  XrFrameEndInfo info{};
  info.type = XR_TYPE_FRAME_END_INFO;
  info.displayTime = display_time;
  info.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
  info.layerCount = static_cast<uint32_t>(layers.size());
  info.layers = layers.data();
  return xrEndFrame(session, &info);
}

XrFrameState XrTestApp::empty_frame() {
  const XrFrameState state = wait_frame();
  XR_EXPECT_OK(begin_frame());
  XR_EXPECT_OK(end_frame({}, state.predictedDisplayTime));
  return state;
}

}  // namespace vdfx::test_runtime
