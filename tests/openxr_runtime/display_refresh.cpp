/// @file
/// @brief The display's rhythm: the frame times xrWaitFrame predicts (placeholder frames first
/// when asked, VDFX_TEST_RUNTIME_PLACEHOLDER_FRAMES), and XR_FB_display_refresh_rate when
/// VDFX_TEST_RUNTIME_REFRESH_RATES offers it: the rates, the current one, and a request that
/// changes it from the next frame on (XrEventDataDisplayRefreshRateChangedFB queued).
#include <algorithm>
#include <cmath>

#include "tests/openxr_runtime/entry_points.h"
#include "tests/openxr_runtime/session_state.h"

namespace vdfx::test_runtime {

std::int64_t display_period_ns(const Instance& inst) {
  return inst.refresh_hz > 0.0f ? std::llround(1e9 / static_cast<double>(inst.refresh_hz))
                                : inst.hmd.period_ns();
}

FrameTiming frame_timing(const Instance& inst, const Session& s, std::int64_t k) {
  const std::int64_t placeholder = inst.config.placeholder_frames;
  if (k < placeholder) return {kClockOriginNs + k * kPlaceholderPeriodNs, kPlaceholderPeriodNs};
  std::int64_t k0 = placeholder;
  XrTime t0 = kClockOriginNs + placeholder * kPlaceholderPeriodNs;
  if (s.rate_change_frame > k0) {
    k0 = s.rate_change_frame;
    t0 = s.rate_change_time;
  }
  const std::int64_t period = display_period_ns(inst);
  return {t0 + (k - k0) * period, period};
}

namespace api {
namespace {

/// Runs an entry point of the extension: `body(instance, session)` once the session is known and
/// its instance enabled the extension.
template <class Body>
XrResult with_extension(const char* fn, XrSession session, Body&& body) {
  return guarded(fn, [&] {
    Session* s = find_session(session);
    if (!s) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown session");
    Instance& inst = *live_instance();
    if (!inst.refresh_rate_enabled)
      return fail(fn, XR_ERROR_FUNCTION_UNSUPPORTED, "XR_FB_display_refresh_rate is not enabled");
    if (s->state == XR_SESSION_STATE_LOSS_PENDING) return XR_ERROR_SESSION_LOST;
    return body(inst, *s);
  });
}

}  // namespace

XRAPI_ATTR XrResult XRAPI_CALL xrEnumerateDisplayRefreshRatesFB(XrSession session,
                                                                uint32_t capacity, uint32_t* count,
                                                                float* rates) {
  constexpr const char* fn = "xrEnumerateDisplayRefreshRatesFB";
  return with_extension(fn, session, [&](Instance& inst, Session&) {
    const std::vector<float>& offered = inst.config.refresh_rates;
    return two_call(fn, capacity, count, rates, offered.size(), [&](float& out, std::size_t i) {
      out = offered[i];
      return XR_SUCCESS;
    });
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrGetDisplayRefreshRateFB(XrSession session, float* rate) {
  constexpr const char* fn = "xrGetDisplayRefreshRateFB";
  return with_extension(fn, session, [&](Instance& inst, Session&) {
    if (!rate) return fail(fn, XR_ERROR_VALIDATION_FAILURE, "displayRefreshRate is null");
    *rate = inst.refresh_hz;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrRequestDisplayRefreshRateFB(XrSession session, float rate) {
  constexpr const char* fn = "xrRequestDisplayRefreshRateFB";
  return with_extension(fn, session, [&](Instance& inst, Session& s) {
    const std::vector<float>& offered = inst.config.refresh_rates;
    // 0 asks for the runtime's own choice: the first rate it lists.
    const float want = rate == 0.0f ? offered.front() : rate;
    if (std::find(offered.begin(), offered.end(), want) == offered.end())
      return fail(fn, XR_ERROR_DISPLAY_REFRESH_RATE_UNSUPPORTED_FB,
                  std::to_string(rate) + " Hz is not one of the display's rates");
    if (want == inst.refresh_hz) return XR_SUCCESS;
    // From the next frame on: its time keeps the old period, the frames after it the new one.
    s.rate_change_time = frame_timing(inst, s, s.waits).time;
    s.rate_change_frame = s.waits;
    XrEventDataDisplayRefreshRateChangedFB e{};
    e.type = XR_TYPE_EVENT_DATA_DISPLAY_REFRESH_RATE_CHANGED_FB;
    e.fromDisplayRefreshRate = inst.refresh_hz;
    e.toDisplayRefreshRate = want;
    inst.refresh_hz = want;
    push_event(inst, &e, sizeof e);
    return XR_SUCCESS;
  });
}

}  // namespace api
}  // namespace vdfx::test_runtime
