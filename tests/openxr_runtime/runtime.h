/// @file
/// @brief The simulated OpenXR runtime's objects (test code, never installed): one instance at a
/// time, its session, spaces, swapchains, action sets and actions. Handles are the objects'
/// addresses, looked up before use; every entry point holds runtime_mutex().
///
/// Sections: [clock] [objects] [lookup] [results]
#pragma once

#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "tests/openxr_runtime/config.h"
#include "tests/openxr_runtime/hmd.h"
#include "tests/openxr_runtime/paths.h"
#include "tests/openxr_runtime/pose_math.h"
#include "tests/openxr_runtime/script.h"
#include "tests/openxr_runtime/xr_platform.h"

namespace vdfx::test_runtime {

class Recorder;
struct Component;

// [clock] ---------------------------------------------------------------------------------------
/// XrTime of script time 0. The clock is virtual: frame k (the k-th xrWaitFrame of a session,
/// 0-based) is predicted for kClockOriginNs + k * display period, whatever the wall clock says.
/// Starting at 1 s keeps every time the runtime gives positive.
inline constexpr XrTime kClockOriginNs = 1'000'000'000;
inline constexpr XrSystemId kSystemId = 1;
inline constexpr std::uint32_t kSwapchainImageCount = 3;
inline constexpr std::uint32_t kMaxLayerCount = 16;
inline constexpr std::uint32_t kMaxSwapchainSize = 8192;
inline constexpr std::size_t kMaxQueuedEvents = 64;

// [objects] -------------------------------------------------------------------------------------
struct Session;
struct ActionSet;

/// The state of one action for one subaction path after the last xrSyncActions.
struct ActionValue {
  bool active = false;
  bool b = false;
  float f = 0.0f;
  XrVector2f v{0.0f, 0.0f};
  bool changed = false;
  XrTime last_change = 0;
};

struct Action {
  ActionSet* set = nullptr;
  std::string name;
  std::string localized;
  XrActionType type{};
  std::vector<XrPath> subactions;
  std::map<XrPath, ActionValue> values;  //!< by subaction path; XR_NULL_PATH: all of them
  /// Destroyed actions and sets keep their objects until the instance goes: action spaces made
  /// from them stay valid (spec: resources live while other handles refer to them).
  bool destroyed = false;
};

struct ActionSet {
  std::string name;
  std::string localized;
  std::uint32_t priority = 0;
  std::vector<std::unique_ptr<Action>> actions;
  bool attached = false;
  bool destroyed = false;
};

/// A suggested binding: an action and a full input/output path of an interaction profile.
struct Binding {
  Action* action = nullptr;
  XrPath path = XR_NULL_PATH;
  int hand = 0;                          //!< 0 left, 1 right
  const Component* component = nullptr;  //!< the profile's component it resolved to
};

struct Space {
  bool is_action = false;
  XrReferenceSpaceType reference_type{};  //!< reference spaces
  Action* action = nullptr;               //!< action spaces
  XrPath subaction = XR_NULL_PATH;
  Pose offset;  //!< poseInReferenceSpace / poseInActionSpace
};

struct Swapchain {
  XrSwapchainCreateFlags create_flags = 0;
  XrSwapchainUsageFlags usage = 0;
  SwapchainFormat format;
  std::uint32_t width = 0, height = 0, array_size = 1, mip_count = 1;
  GLenum target = 0;
  std::vector<GLuint> textures;
  std::deque<std::uint32_t> acquired;  //!< acquired and not yet released, oldest first
  std::size_t waited = 0;              //!< how many of `acquired` (from the front) were waited
  std::uint32_t next_image = 0;
  std::optional<std::uint32_t> released;  //!< the image the app released last
  bool static_acquired = false;           //!< a static swapchain's one acquire has happened
};

/// What the app gave in XrGraphicsBindingOpenGLXlibKHR.
struct GlBinding {
  Display* display = nullptr;
  GLXFBConfig fbconfig = nullptr;
  GLXDrawable drawable = 0;
  GLXContext context = nullptr;
};

struct Session {
  GlBinding gl;
  GLXContext own_context = nullptr;  //!< VDFX_TEST_RUNTIME_SWITCH_CONTEXT's context
  bool switch_context = false;       //!< leave own_context current after GL work
  XrSessionState state = XR_SESSION_STATE_UNKNOWN;
  bool running = false;
  bool exit_begun = false;  //!< on its way to STOPPING (app's request, script end, frame limit)
  XrViewConfigurationType view_config{};
  std::int64_t waits = 0;         //!< xrWaitFrame calls of this session
  std::int64_t begun_frame = -1;  //!< frame of the last xrBeginFrame
  XrTime begun_time = 0;          //!< its predicted display time
  /// A refresh rate change (xrRequestDisplayRefreshRateFB) takes effect at this frame, predicted
  /// for this time; frames after it are one new period apart (-1: no change).
  std::int64_t rate_change_frame = -1;
  XrTime rate_change_time = 0;
  std::int64_t begins = 0;
  bool in_frame = false;  //!< between xrBeginFrame and xrEndFrame
  std::int64_t frames_ended = 0;
  XrTime now = kClockOriginNs;  //!< the latest predicted display time: the time input is read at
  std::vector<std::unique_ptr<Space>> spaces;
  std::vector<std::unique_ptr<Swapchain>> swapchains;
  bool actions_attached = false;
  std::vector<ActionSet*> attached_sets;
  XrPath profile = XR_NULL_PATH;  //!< the active interaction profile (both hands)
  std::vector<Binding> bindings;  //!< the app's suggestions for `profile`
  std::unique_ptr<Recorder> recorder;

  ~Session();
};

struct Instance {
  Config config;
  Hmd hmd;
  std::optional<Script> script;
  bool gl_enabled = false;
  bool refresh_rate_enabled = false;  //!< XR_FB_display_refresh_rate enabled by the app
  float refresh_hz = 0.0f;  //!< the display's rate: the headset's, or one of refresh_rates
  std::string app_name;
  PathTable paths;
  int get_system_calls = 0;
  bool system_found = false;
  bool gl_requirements_queried = false;
  std::map<XrPath, std::vector<Binding>> suggested;  //!< by interaction profile
  std::vector<std::unique_ptr<ActionSet>> action_sets;
  std::unique_ptr<Session> session;
  std::deque<XrEventDataBuffer> events;
  std::uint32_t events_lost = 0;
};

/// The display period now, ns (1 / refresh_hz, rounded).
std::int64_t display_period_ns(const Instance& inst);

/// Frame k's predicted display time and period, as xrWaitFrame gives them: kClockOriginNs +
/// k x period, except that the first config.placeholder_frames are kPlaceholderPeriodNs apart and
/// a refresh rate change restarts the count at its frame.
struct FrameTiming {
  XrTime time = 0;
  std::int64_t period_ns = 0;
};
FrameTiming frame_timing(const Instance& inst, const Session& s, std::int64_t k);

// [lookup] --------------------------------------------------------------------------------------
/// Every entry point locks this: the runtime is one state machine, as the spec's "externally
/// synchronized" rules allow (xrWaitFrame never blocks: the clock is virtual).
std::mutex& runtime_mutex();
/// The live instance (at most one: a second xrCreateInstance gets XR_ERROR_LIMIT_REACHED).
std::unique_ptr<Instance>& live_instance();

Instance* find_instance(XrInstance h);
Session* find_session(XrSession h);
Space* find_space(XrSpace h);
Swapchain* find_swapchain(XrSwapchain h);
ActionSet* find_action_set(XrActionSet h);
Action* find_action(XrAction h);

template <class Handle, class T>
Handle to_handle(T* p) {
  return reinterpret_cast<Handle>(p);
}

// [results] -------------------------------------------------------------------------------------
/// Reports why a call fails on stderr ("vdfx-test-runtime: FUNCTION: message (RESULT)") and
/// returns `result`, so a test log says which check of the runtime refused the app.
XrResult fail(const char* function, XrResult result, const std::string& message);

/// Checks an input or output struct: not null, the expected type, and each struct of its next
/// chain one of `allowed_next`. XR_ERROR_VALIDATION_FAILURE (reported) otherwise.
XrResult check_struct(const char* function, const char* name, const void* s,
                      XrStructureType expected,
                      std::initializer_list<XrStructureType> allowed_next = {});

/// The enum's name from the OpenXR headers, or a number for an unknown value.
std::string result_name(XrResult r);
std::string structure_type_name(XrStructureType t);
std::string session_state_name(XrSessionState s);

/// Fills the two-call idiom's output: the count always, the items when capacity allows.
template <class T, class Fill>
XrResult two_call(const char* function, std::uint32_t capacity, std::uint32_t* count, T* out,
                  std::size_t size, Fill&& fill) {
  if (!count) return fail(function, XR_ERROR_VALIDATION_FAILURE, "the count output is null");
  *count = static_cast<std::uint32_t>(size);
  if (capacity == 0) return XR_SUCCESS;
  if (capacity < size) return XR_ERROR_SIZE_INSUFFICIENT;
  if (!out) return fail(function, XR_ERROR_VALIDATION_FAILURE, "the array is null");
  for (std::size_t i = 0; i < size; ++i) {
    const XrResult r = fill(out[i], i);
    if (XR_FAILED(r)) return r;
  }
  return XR_SUCCESS;
}

/// The two-call idiom for a string (count includes the terminating NUL).
XrResult two_call_string(const char* function, std::uint32_t capacity, std::uint32_t* count,
                         char* buffer, const std::string& text);

}  // namespace vdfx::test_runtime
