/// @file
/// @brief The display's rhythm as the simulated runtime gives it, through the loader with the
/// core validation layer on: XR_FB_display_refresh_rate when VDFX_TEST_RUNTIME_REFRESH_RATES
/// offers it (the rates, the current one, a change from the next frame on with its event),
/// placeholder frames first (VDFX_TEST_RUNTIME_PLACEHOLDER_FRAMES), and the lifecycle calls
/// session.json lists.
#include <gtest/gtest.h>

#include "tests/openxr/runtime_test_fixture.h"
#include "tests/openxr/xr_test_app.h"

namespace vdfx::test_runtime {
namespace {

class Refresh : public RuntimeTest {};

bool offered(const char* name) {
  uint32_t n = 0;
  XR_EXPECT_OK(xrEnumerateInstanceExtensionProperties(nullptr, 0, &n, nullptr));
  std::vector<XrExtensionProperties> props(n, {XR_TYPE_EXTENSION_PROPERTIES, nullptr, {}, 0});
  XR_EXPECT_OK(xrEnumerateInstanceExtensionProperties(nullptr, n, &n, props.data()));
  for (const auto& p : props)
    if (std::string(p.extensionName) == name) return true;
  return false;
}

/// The next XrEventDataDisplayRefreshRateChangedFB in the queue (state changes skipped).
std::optional<XrEventDataDisplayRefreshRateChangedFB> next_rate_change(XrInstance instance) {
  for (;;) {
    XrEventDataBuffer event{};
    event.type = XR_TYPE_EVENT_DATA_BUFFER;
    if (xrPollEvent(instance, &event) != XR_SUCCESS) return std::nullopt;
    if (event.type == XR_TYPE_EVENT_DATA_DISPLAY_REFRESH_RATE_CHANGED_FB)
      return reinterpret_cast<const XrEventDataDisplayRefreshRateChangedFB&>(event);
  }
}

// The loader keeps the extensions a runtime listed when it first loaded it, for every
// xrCreateInstance while it stays loaded: the variable is set before the first call.
TEST_F(Refresh, TheExtensionGivesTheRatesAndAChangeTakesEffectAtTheNextFrame) {
  set("VDFX_TEST_RUNTIME_REFRESH_RATES", "72,90,120");
  ASSERT_TRUE(offered(XR_FB_DISPLAY_REFRESH_RATE_EXTENSION_NAME));
  XrTestApp app;
  ASSERT_EQ(XR_EXPECT_OK(app.create_instance(true, {XR_FB_DISPLAY_REFRESH_RATE_EXTENSION_NAME})),
            XR_SUCCESS);
  ASSERT_EQ(XR_EXPECT_OK(app.get_system()), XR_SUCCESS);
  ASSERT_EQ(XR_EXPECT_OK(app.create_session()), XR_SUCCESS);
  const auto enumerate = instance_function<PFN_xrEnumerateDisplayRefreshRatesFB>(
      app.instance, "xrEnumerateDisplayRefreshRatesFB");
  const auto get =
      instance_function<PFN_xrGetDisplayRefreshRateFB>(app.instance, "xrGetDisplayRefreshRateFB");
  const auto request = instance_function<PFN_xrRequestDisplayRefreshRateFB>(
      app.instance, "xrRequestDisplayRefreshRateFB");
  ASSERT_TRUE(enumerate && get && request);
  uint32_t n = 0;
  XR_EXPECT_OK(enumerate(app.session, 0, &n, nullptr));
  std::vector<float> rates(n);
  XR_EXPECT_OK(enumerate(app.session, n, &n, rates.data()));
  EXPECT_EQ(rates, (std::vector<float>{72.0f, 90.0f, 120.0f}));
  float now = 0.0f;
  XR_EXPECT_OK(get(app.session, &now));
  EXPECT_EQ(now, 90.0f) << "generic90's own rate, one of those offered";

  ASSERT_TRUE(app.poll_until(XR_SESSION_STATE_READY));
  XR_EXPECT_OK(app.begin_session());
  for (int k = 0; k < 3; ++k) EXPECT_EQ(app.empty_frame().predictedDisplayTime, frame_time(k));
  EXPECT_EQ(request(app.session, 60.0f), XR_ERROR_DISPLAY_REFRESH_RATE_UNSUPPORTED_FB);
  XR_EXPECT_OK(request(app.session, 120.0f));
  const auto change = next_rate_change(app.instance);
  ASSERT_TRUE(change.has_value());
  EXPECT_EQ(change->fromDisplayRefreshRate, 90.0f);
  EXPECT_EQ(change->toDisplayRefreshRate, 120.0f);
  XR_EXPECT_OK(get(app.session, &now));
  EXPECT_EQ(now, 120.0f);
  // Frame 3 comes one old period after frame 2; from there frames are 1/120 s apart.
  const XrFrameState f3 = app.empty_frame(), f4 = app.empty_frame();
  EXPECT_EQ(f3.predictedDisplayTime, frame_time(3));
  EXPECT_EQ(f3.predictedDisplayPeriod, 8333333);
  EXPECT_EQ(f4.predictedDisplayTime, frame_time(3) + 8333333);
}

TEST_F(Refresh, PlaceholderFramesComeFirstThenTheDisplaysPeriod) {
  set("VDFX_TEST_RUNTIME_PLACEHOLDER_FRAMES", "4");
  XrTestApp app;
  ASSERT_TRUE(app.start());
  ASSERT_TRUE(app.poll_until(XR_SESSION_STATE_READY));
  XR_EXPECT_OK(app.begin_session());
  for (int k = 0; k < 4; ++k) {
    const XrFrameState s = app.empty_frame();
    EXPECT_EQ(s.predictedDisplayPeriod, 16'000'000) << "frame " << k;
    EXPECT_EQ(s.predictedDisplayTime, 1'000'000'000 + k * 16'000'000) << "frame " << k;
  }
  for (int k = 4; k < 7; ++k) {
    const XrFrameState s = app.empty_frame();
    EXPECT_EQ(s.predictedDisplayPeriod, 11111111) << "frame " << k;
    EXPECT_EQ(s.predictedDisplayTime, 1'000'000'000 + 4 * 16'000'000 + (k - 4) * 11111111);
  }
}

TEST_F(Refresh, SessionJsonListsTheLifecycleCallsInOrder) {
  XrTestApp app;
  ASSERT_TRUE(app.start());
  ASSERT_TRUE(app.poll_until(XR_SESSION_STATE_READY));
  XR_EXPECT_OK(app.begin_session());
  for (int k = 0; k < 2; ++k) app.empty_frame();
  XR_EXPECT_OK(xrRequestExitSession(app.session));
  ASSERT_TRUE(app.poll_until(XR_SESSION_STATE_STOPPING));
  XR_EXPECT_OK(xrEndSession(app.session));
  XR_EXPECT_OK(xrDestroySession(app.session));
  app.session = XR_NULL_HANDLE;
  const nlohmann::json calls = session_json().at("lifecycle_calls");
  std::vector<std::string> names;
  for (const auto& c : calls) names.push_back(c.at("call"));
  EXPECT_EQ(names, (std::vector<std::string>{"xrBeginSession", "xrRequestExitSession",
                                             "xrEndSession", "xrDestroySession"}));
  EXPECT_EQ(calls.at(1).at("frames_waited"), 2);
}

TEST_F(Refresh, TheExtensionIsOfferedOnlyWhenAsked) {
  EXPECT_FALSE(offered(XR_FB_DISPLAY_REFRESH_RATE_EXTENSION_NAME));
  EXPECT_TRUE(offered(XR_KHR_OPENGL_ENABLE_EXTENSION_NAME));
}

}  // namespace
}  // namespace vdfx::test_runtime
