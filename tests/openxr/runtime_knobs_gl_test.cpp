/// @file
/// @brief The runtime's knobs, each as an app meets it: no headset (for a while), no OpenGL, a
/// format list, another headset profile, the SteamVR habit of leaving its own GL context
/// current, bad scripts and bad values refused with a message naming the place.
#include <gtest/gtest.h>

#include <fstream>

#include "tests/openxr/runtime_test_fixture.h"
#include "tests/openxr/xr_test_app.h"

namespace vdfx::test_runtime {
namespace {

class Knobs : public RuntimeTest {};

std::vector<std::string> extension_names() {
  uint32_t n = 0;
  XR_EXPECT_OK(xrEnumerateInstanceExtensionProperties(nullptr, 0, &n, nullptr));
  std::vector<XrExtensionProperties> props(n, {XR_TYPE_EXTENSION_PROPERTIES, nullptr, {}, 0});
  XR_EXPECT_OK(xrEnumerateInstanceExtensionProperties(nullptr, n, &n, props.data()));
  std::vector<std::string> names;
  for (const auto& p : props) names.push_back(p.extensionName);
  return names;
}

bool offers(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::vector<std::int64_t> formats(XrTestApp& app) {
  uint32_t n = 0;
  XR_EXPECT_OK(xrEnumerateSwapchainFormats(app.session, 0, &n, nullptr));
  std::vector<std::int64_t> out(n);
  if (n > 0) XR_EXPECT_OK(xrEnumerateSwapchainFormats(app.session, n, &n, out.data()));
  return out;
}

TEST_F(Knobs, NoHeadsetIsFormFactorUnavailable) {
  set("VDFX_TEST_RUNTIME_NO_HMD", "always");
  XrTestApp app;
  ASSERT_EQ(XR_EXPECT_OK(app.create_instance()), XR_SUCCESS);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(app.get_system(), XR_ERROR_FORM_FACTOR_UNAVAILABLE);
}

TEST_F(Knobs, AHeadsetSwitchedOnAfterSomeCallsIsFound) {
  set("VDFX_TEST_RUNTIME_NO_HMD", "2");
  XrTestApp app;
  ASSERT_EQ(XR_EXPECT_OK(app.create_instance()), XR_SUCCESS);
  EXPECT_EQ(app.get_system(), XR_ERROR_FORM_FACTOR_UNAVAILABLE);
  EXPECT_EQ(app.get_system(), XR_ERROR_FORM_FACTOR_UNAVAILABLE);
  EXPECT_EQ(app.get_system(), XR_SUCCESS);
  EXPECT_EQ(XR_EXPECT_OK(app.create_session()), XR_SUCCESS);
}

TEST_F(Knobs, ARuntimeWithoutOpenGl) {
  // Without the layer: version 1.0.20 of it answers any failed xrCreateInstance with
  // XR_ERROR_INITIALIZATION_FAILED, hiding the result the runtime gave.
  without_layer();
  EXPECT_TRUE(offers(extension_names(), XR_KHR_OPENGL_ENABLE_EXTENSION_NAME));
  set("VDFX_TEST_RUNTIME_NO_OPENGL", "1");
  EXPECT_FALSE(offers(extension_names(), XR_KHR_OPENGL_ENABLE_EXTENSION_NAME));
  XrTestApp app;
  EXPECT_EQ(app.create_instance(true), XR_ERROR_EXTENSION_NOT_PRESENT);
  // An app that goes on without OpenGL gets no session: the runtime renders through GL only.
  ASSERT_EQ(XR_EXPECT_OK(app.create_instance(false)), XR_SUCCESS);
  ASSERT_EQ(XR_EXPECT_OK(app.get_system()), XR_SUCCESS);
  XrSessionCreateInfo info{};
  info.type = XR_TYPE_SESSION_CREATE_INFO;
  info.systemId = app.system;
  EXPECT_EQ(xrCreateSession(app.instance, &info, &app.session), XR_ERROR_GRAPHICS_DEVICE_INVALID);
}

TEST_F(Knobs, TheFormatListIsWhatTheAppIsOffered) {
  {
    XrTestApp app;
    ASSERT_TRUE(app.start());
    EXPECT_EQ(formats(app),
              (std::vector<std::int64_t>{GL_SRGB8_ALPHA8, GL_RGBA8, GL_RGBA16F, GL_RGB10_A2,
                                         GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT24,
                                         GL_DEPTH_COMPONENT32F, GL_DEPTH24_STENCIL8}));
  }
  set("VDFX_TEST_RUNTIME_SWAPCHAIN_FORMATS", "GL_R11F_G11F_B10F,GL_DEPTH_COMPONENT16");
  {
    XrTestApp app;
    ASSERT_TRUE(app.start());
    EXPECT_EQ(formats(app), (std::vector<std::int64_t>{GL_R11F_G11F_B10F, GL_DEPTH_COMPONENT16}));
    app.swapchain(GL_R11F_G11F_B10F, 8, 8);  // what it offers, it makes
  }
  set("VDFX_TEST_RUNTIME_SWAPCHAIN_FORMATS", "none");
  {
    XrTestApp app;
    ASSERT_TRUE(app.start());
    EXPECT_TRUE(formats(app).empty());
  }
}

TEST_F(Knobs, TheHeadsetProfileGivesTheViewsAndTheClock) {
  set("VDFX_TEST_RUNTIME_HMD", "offcentre");  // 1200 x 1200 per eye, 72 Hz
  XrTestApp app;
  ASSERT_TRUE(app.start());
  uint32_t n = 0;
  std::array<XrViewConfigurationView, 2> views{};
  for (auto& v : views) v.type = XR_TYPE_VIEW_CONFIGURATION_VIEW;
  XR_EXPECT_OK(xrEnumerateViewConfigurationViews(
      app.instance, app.system, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, 2, &n, views.data()));
  EXPECT_EQ(views[1].recommendedImageRectWidth, 1200u);
  EXPECT_EQ(views[1].recommendedImageRectHeight, 1200u);
  XrSystemProperties props{};
  props.type = XR_TYPE_SYSTEM_PROPERTIES;
  XR_EXPECT_OK(xrGetSystemProperties(app.instance, app.system, &props));
  EXPECT_STREQ(props.systemName, "vdfx test runtime: offcentre");
  app.poll_states();
  XR_EXPECT_OK(app.begin_session());
  app.empty_frame();
  const XrFrameState s = app.empty_frame();
  EXPECT_EQ(s.predictedDisplayPeriod, 13888889);  // 1 s / 72, rounded
  EXPECT_EQ(s.predictedDisplayTime, frame_time(1, 13888889));
}

TEST_F(Knobs, LikeSteamVrTheRuntimeCanLeaveItsOwnContextCurrent) {
  set("VDFX_TEST_RUNTIME_SWITCH_CONTEXT", "1");
  XrTestApp app;
  ASSERT_TRUE(app.start());
  const GLXContext mine = glXGetCurrentContext();
  const XrSwapchain sc = app.swapchain(GL_RGBA8, 8, 8);
  EXPECT_NE(glXGetCurrentContext(), mine);
  EXPECT_NE(glXGetCurrentContext(), nullptr);
  glXMakeContextCurrent(glXGetCurrentDisplay(), glXGetCurrentDrawable(), glXGetCurrentDrawable(),
                        mine);
  uint32_t index = 0;
  XR_EXPECT_OK(xrAcquireSwapchainImage(sc, nullptr, &index));
  EXPECT_NE(glXGetCurrentContext(), mine);
}

TEST_F(Knobs, TheHeaderOfTheScriptChoosesTheHeadset) {
  script({{0}}, "cardboard-v1");
  XrTestApp app;
  ASSERT_TRUE(app.start());
  XrSystemProperties props{};
  props.type = XR_TYPE_SYSTEM_PROPERTIES;
  XR_EXPECT_OK(xrGetSystemProperties(app.instance, app.system, &props));
  EXPECT_STREQ(props.systemName, "vdfx test runtime: cardboard-v1");
}

/// Without the layer: it answers any failed xrCreateInstance with XR_ERROR_INITIALIZATION_FAILED.
class KnobsRefused : public RuntimeTest {
 protected:
  void SetUp() override {
    RuntimeTest::SetUp();
    without_layer();
  }
};

/// xrCreateInstance's result and what the runtime said on stderr.
std::pair<XrResult, std::string> create_instance_output() {
  XrTestApp app;
  ::testing::internal::CaptureStderr();
  const XrResult r = app.create_instance();
  return {r, ::testing::internal::GetCapturedStderr()};
}

TEST_F(KnobsRefused, ABrokenScriptNamesItsFileLineAndField) {
  const std::string path = (env().dir() / "broken.vdrec.jsonl").string();
  std::ofstream(path)
      << R"({"format":"vdfx.recording","version":1,"hmd":"sim","video":null,"note":""})"
      << "\n"
      << R"({"t_ns":0,"head":{"q":[1,0,0,0],"p":[0,1.6,0]}})"
      << "\n"
      << R"({"t_ns":10,"head":{"q":[0.5,0,0,0],"p":[0,1.6,0]}})"
      << "\n";
  set("VDFX_TEST_RUNTIME_SCRIPT", path);
  const auto [result, output] = create_instance_output();
  EXPECT_EQ(result, XR_ERROR_RUNTIME_FAILURE);
  EXPECT_NE(output.find(path + ":3: /head/q: not a unit quaternion"), std::string::npos) << output;
}

TEST_F(KnobsRefused, ABadValueNamesItsVariable) {
  set("VDFX_TEST_RUNTIME_CAPTURE", "frog");
  auto [result, output] = create_instance_output();
  EXPECT_EQ(result, XR_ERROR_RUNTIME_FAILURE);
  EXPECT_NE(output.find("VDFX_TEST_RUNTIME_CAPTURE=frog"), std::string::npos) << output;
  unsetenv("VDFX_TEST_RUNTIME_CAPTURE");
  set("VDFX_TEST_RUNTIME_HMD", "no-such-headset");
  std::tie(result, output) = create_instance_output();
  EXPECT_EQ(result, XR_ERROR_RUNTIME_FAILURE);
  EXPECT_NE(output.find("HMD profile 'no-such-headset'"), std::string::npos) << output;
}

}  // namespace
}  // namespace vdfx::test_runtime
