/// @file
/// @brief vdfx's OpenXR backend: a real headset through the Khronos loader (`--runtime openxr`,
/// docs/openxr.md). The simulated headset (xr/headset/session.h) stays the default; this is the
/// second backend behind the same frame and input interfaces, so the editor and the player do not
/// know which one runs.
///
/// In three steps, so that what a user can fix is reported before any window opens:
///   create()         instance (XR_KHR_opengl_enable), the HMD system, the stereo view
///                    configuration and the action set: no runtime, no headset or no OpenGL
///                    support is an OpenXrUnavailable (exit 1) here;
///   start_session()  on the GLX context of the window (after xrGetOpenGLGraphicsRequirementsKHR),
///                    the reference spaces, the eye swapchains (format: xr/openxr/openxr_format.h);
///   per frame        poll_events() (the lifecycle: xr/openxr/openxr_lifecycle.h), begin_frame()
///                    (xrWaitFrame + xrBeginFrame: the frame clock), locate_views(),
///                    submit_eye() x 2, submit_quads(), end_frame().
/// Times: the loop's clock is the runtime's XrTime less an epoch taken at the first frame (one
/// period before its predicted display time), so a headset session's times start near zero as
/// the sim's do and its recordings replay alike.
///
/// Spaces: vdfx's LOCAL has its origin on the floor (docs/input.md): OpenXR's STAGE where the
/// runtime offers it, else OpenXR's LOCAL with its origin moved down by the standing eye height
/// (xr::kDefaultEyeHeight), so the head is where the other backends put it.
///
/// Files: the GL-free logic is xr/openxr/openxr_{bindings,format,input,lifecycle}.cpp
/// (vdfx_xr_openxr); every file that calls the loader is in xr/openxr/gl/ (vdfx_xr_openxr_gl: the
/// session is bound to the GL context), so only what links that target (the media module, the
/// tests) needs libopenxr_loader.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/input_error.h"
#include "xr/headset/eye_views.h"
#include "xr/headset/session.h"
#include "xr/input/actions.h"
#include "xr/openxr/openxr_format.h"
#include "xr/openxr/openxr_lifecycle.h"

struct GLFWwindow;

namespace vdfx::xr {

class GlTexture;
class InputBackend;

/// A runtime or headset vdfx cannot use; the message names what is missing and the fix. An
/// input error (exit 1): the machine's set-up, not a bug.
class OpenXrUnavailable : public io::InputError {
 public:
  using io::InputError::InputError;
};

/// The session was lost while vdfx used it (a call answered XR_ERROR_SESSION_LOST): the loop
/// ends as on LOSS_PENDING, the document saved.
class OpenXrSessionLost : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct OpenXrOptions {
  std::string application_name = "vdfx";
  /// How long create() waits for a headset while xrGetSystem answers
  /// XR_ERROR_FORM_FACTOR_UNAVAILABLE (a headset being switched on, a streaming client joining).
  std::chrono::milliseconds headset_wait{3000};
};

struct OpenXrViewInfo {
  int recommended_width = 0, recommended_height = 0;
  int max_width = 0, max_height = 0;
  int recommended_samples = 1, max_samples = 1;
};

/// What the runtime and its headset are (`vdfx hmd openxr` prints it).
struct OpenXrSystemInfo {
  std::string runtime_name;
  std::string runtime_version;  //!< "1.0.20"
  std::string system_name;
  std::uint32_t vendor_id = 0;
  std::vector<OpenXrViewInfo> views;  //!< the stereo configuration's: left, then right
  bool orientation_tracking = false, position_tracking = false;
  std::uint32_t max_layers = 0;
  std::vector<std::string> extensions;   //!< instance extensions the runtime offers
  std::vector<std::string> blend_modes;  //!< "OPAQUE", "ADDITIVE", "ALPHA_BLEND"
  /// The interaction profiles whose suggested bindings the runtime accepted, and those it
  /// refused with the reason ("/interaction_profiles/...: XR_ERROR_PATH_UNSUPPORTED").
  std::vector<std::string> profiles_accepted, profiles_refused;
};

/// One frame, waited and begun.
struct OpenXrFrame {
  std::int64_t time_ns = 0;    //!< the predicted display time in the loop's clock
  std::int64_t period_ns = 0;  //!< predicted display period
  std::int64_t xr_time = 0;    //!< the same display time as the runtime's XrTime
  bool should_render = false;  //!< false: end the frame with no layers
};

/// After start_session: what the swapchains are.
struct OpenXrSwapchainInfo {
  std::vector<std::int64_t> offered;  //!< xrEnumerateSwapchainFormats, the runtime's order
  SwapchainFormat format;             //!< the one vdfx took (xr/openxr/openxr_format.h)
  int eye_width = 0, eye_height = 0;
};

class OpenXrRuntime {
 public:
  /// Instance, system, views and actions (no GL yet). Throws OpenXrUnavailable: "no OpenXR
  /// runtime: install Monado, or set XR_RUNTIME_JSON", no headset (after options.headset_wait),
  /// no XR_KHR_opengl_enable, no stereo view configuration.
  static std::unique_ptr<OpenXrRuntime> create(const OpenXrOptions& options = {});
  ~OpenXrRuntime();
  OpenXrRuntime(const OpenXrRuntime&) = delete;
  OpenXrRuntime& operator=(const OpenXrRuntime&) = delete;

  const OpenXrSystemInfo& info() const;

  /// The input backend of this runtime's actions (xrSyncActions, the action states and the
  /// aim and head poses at the poll's time; xr/openxr/openxr_input.h fills the InputState). Polls
  /// before the first frame return an untracked state. The runtime must outlive it.
  std::unique_ptr<InputBackend> create_input_backend();

  /// Creates the session on the GLX context of `window`, which must be current (checked against
  /// xrGetOpenGLGraphicsRequirementsKHR), its spaces, and one swapchain per eye of
  /// eye_width x eye_height (clamped to the runtime's maximum). Throws OpenXrUnavailable when the
  /// context's OpenGL is older than the runtime needs or no offered format suits
  /// (xr/openxr/openxr_format.h).
  void start_session(GLFWwindow* window, int eye_width, int eye_height);
  const OpenXrSwapchainInfo& swapchains() const;

  /// xrPollEvent until the queue is empty, stepping the lifecycle (xrBeginSession on READY,
  /// xrEndSession on STOPPING).
  void poll_events();
  const OpenXrLifecycle& lifecycle() const;
  /// Leave: xrRequestExitSession while the session runs (the loop then follows the states to
  /// EXITING), at once otherwise.
  void request_exit();
  /// A call threw OpenXrSessionLost: no more frames; the session is only destroyed.
  void session_lost();

  /// xrWaitFrame then xrBeginFrame (the lifecycle must be running). Blocks as the runtime paces.
  OpenXrFrame begin_frame();
  /// xrLocateViews at the frame's display time, in vdfx's LOCAL: each eye's pose and asymmetric
  /// FOV (sizes: the swapchains').
  std::array<EyeView, 2> locate_views();
  /// Copies an eye's image (the compositor's eye buffer: display-encoded values, GL rows bottom
  /// up, its size the swapchains') into that eye's swapchain image.
  void submit_eye(int eye, const GlTexture& image);
  /// The panels as quad layers, each copied into a swapchain of its own (premultiplied, first row
  /// at the quad's top: xr::QuadLayer's convention).
  void submit_quads(std::span<const QuadLayer> quads);
  /// xrEndFrame: the projection layer (when both eyes were submitted) under the quads.
  void end_frame();
  /// A short vibration (xrApplyHapticFeedback) on a hand's controller.
  void haptic_pulse(Hand hand);
  /// Destroys the session, its spaces and swapchains, with the GL context it was started on
  /// (which must still exist: the frame loop calls this before closing its window). The
  /// instance stays; the destructor does this too when it was not done.
  void end_session();

  /// How often an xr call left another GL context current and vdfx made its own current again
  /// (SteamVR's habit; docs/openxr.md, "Runtime quirks handled").
  int context_restores() const;

  /// The loop time <-> the runtime's XrTime (valid after the first begin_frame()).
  bool has_epoch() const;
  std::int64_t to_xr_time(std::int64_t loop_ns) const;

  struct Impl;  //!< shared by the backend's files (xr/openxr/gl/openxr_runtime_impl.h)
  Impl& impl() { return *impl_; }

 private:
  explicit OpenXrRuntime(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

/// The OpenXR backend's input backend (xr/openxr/gl/input_openxr.cpp).
std::unique_ptr<InputBackend> create_openxr_input_backend(OpenXrRuntime& runtime);

/// `vdfx hmd openxr`: what the active runtime offers, as text. Opens a hidden GL window for a
/// session (swapchain formats need one) and runs it for a few frames for the refresh rate.
std::string openxr_report(const OpenXrOptions& options = {});

}  // namespace vdfx::xr
