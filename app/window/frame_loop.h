/// @file
/// @brief The windowed runtime loop of the simulated headset, shared by `vdfx play` and
/// `vdfx edit`: a GLFW mirror window, the session's frame timing, input from a backend, video
/// from the decode worker, the client's parameters, both eyes through the compositor.
///
/// One frame (docs/player.md):
///   time: live -> Session::wait_frame(now) -> predicted display time;
///         replay (the backend has a timeline) -> the recording's next sample time, no clock.
///   window events -> input backend (push_event) and client (on_desktop_event);
///   input.poll(display time) -> client.update() -> VideoSource::frame_at(frame, decode_timeout):
///   a frame not decoded yet keeps the previous one on screen and counts as late (never blocks);
///   params once at the head's forward direction (per-pixel mode: a parameter grid, baked when
///   the frame or the parameters change, that the effect shader reads per pixel) -> both eyes ->
///   mirror.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/window/frame_client.h"
#include "effects/stereo_layout.h"
#include "xr/headset/hmd_profile.h"
#include "xr/render/blur_method.h"
#include "xr/render/mirror.h"

namespace vdfx::io {
class VideoSource;
}
namespace vdfx::xr {
class Compositor;
class InputBackend;
class OpenXrRuntime;
}  // namespace vdfx::xr

namespace vdfx::app {

/// Default eye scale for the window: llvmpipe renders 1440x1600 eyes at about 3 frames per
/// second; a quarter of the width and height (1/16 of the pixels) keeps the loop usable.
inline constexpr double kDefaultEyeScale = 0.25;
/// The desktop view: about the horizontal FOV of a headset, so what an author sees on the monitor
/// is what a viewer sees in the headset.
inline constexpr double kDefaultDesktopHfovDeg = 100.0;
inline constexpr double kDefaultDesktopVideoScale = 0.5;

struct FrameLoopOptions {
  xr::HmdProfile profile;
  double eye_scale = kDefaultEyeScale;  //!< eye buffers are the profile's resolution x this
  int window_width = 1280;
  int window_height = 720;
  bool visible = true;    //!< false: hidden window (tests), the mirror still renders
  bool vsync = true;      //!< live mode only; replay never waits
  bool resizable = true;  //!< false while recording the sim (its panels follow the window)
  /// What the window shows: the desktop view (one undistorted view filling the window, the
  /// sim's default) or a headset mirror; keys 1-4 switch.
  xr::MirrorMode mirror = xr::MirrorMode::Desktop;
  double desktop_hfov_deg = kDefaultDesktopHfovDeg;  //!< horizontal FOV of the desktop view
  /// The desktop view renders video and effects at this fraction of the window and scales them
  /// up; panels, text and pointer are drawn at the window's full resolution.
  double desktop_video_scale = kDefaultDesktopVideoScale;
  /// The first decoded frame may take this long (a 4K long-GOP clip on two cores); the window
  /// shows "loading" meanwhile. No frame by then is an input error naming the video.
  std::chrono::milliseconds start_timeout{20000};
  std::int64_t max_frames = -1;                //!< stop after this many frames (-1: no limit)
  std::filesystem::path screenshot;            //!< write the last frame's mirror here (PNG)
  bool stats = false;                          //!< GPU timer per stage, medians printed
  double stats_period_s = 2.0;                 //!< wall seconds between periodic stats lines
  std::ostream* stats_out = nullptr;           //!< default std::cout
  std::chrono::nanoseconds decode_timeout{0};  //!< how long a frame may wait for the decoder
  int bake_width = 256, bake_height = 128;     //!< per-pixel mode's parameter grid
  /// The GPU blur (live default: the pyramid, ~10x cheaper than exact at sigma 2 deg;
  /// docs/compositor.md has the error table).
  xr::BlurMethod blur = xr::BlurMethod::Pyramid;
  bool keep_records = false;  //!< fill FrameLoopResult::records (tests)
  /// Called after each frame is rendered (before the mirror), with the compositor (tests read
  /// eye buffers here).
  std::function<void(xr::Compositor&, std::int64_t loop_frame)> on_frame;
  /// Events injected before the window's own at a given loop frame (tests, scripted demos).
  std::function<std::vector<xr::DesktopEvent>(std::int64_t loop_frame)> script;
  /// `--runtime openxr`: the frames go to this runtime's headset (its session is started on the
  /// loop's GL context; eye buffers at its recommended size x eye_scale, no lens, the panels as
  /// quad layers, the window mirrors the left eye). Null: the simulated headset.
  std::shared_ptr<xr::OpenXrRuntime> openxr;
  /// The video's stereo layout and coverage (docs/stereo.md): each eye samples its own image;
  /// the desktop view shows one eye, key 5 toggles which.
  effects::StereoLayout video_layout;
};

struct FrameRecord {
  std::int64_t display_time_ns = 0;
  std::int64_t requested_frame = 0;  //!< what the client asked for
  std::int64_t shown_frame = -1;     //!< what is on screen (-1: nothing decoded yet)
  bool late = false;                 //!< shown != requested
};

/// Median milliseconds per frame over a window of frames.
struct StageMedian {
  std::string stage;
  double ms = 0.0;
};

struct FrameLoopResult {
  std::int64_t frames = 0;
  std::int64_t late_frames = 0;
  double wall_s = 0.0;
  std::vector<FrameRecord> records;  //!< keep_records only
  std::vector<StageMedian> medians;  //!< stats only: GPU stages (both eyes), CPU parts
  /// Why the loop ended when the headset's runtime ended it ("the OpenXR session is being lost
  /// ..."); empty when vdfx did.
  std::string end_reason;
};

class FrameLoop {
 public:
  /// Opens the window and GL context (throws xr::GlError without a display).
  FrameLoop(FrameLoopOptions options, xr::InputBackend& input, io::VideoSource& video,
            FrameClient& client);
  ~FrameLoop();
  FrameLoop(const FrameLoop&) = delete;
  FrameLoop& operator=(const FrameLoop&) = delete;

  /// Runs until the window closes, Escape, the client asks, max_frames, or the replay ends.
  FrameLoopResult run();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The mirror a key selects (1 desktop, 2 pre-distorted, 3 through the lens, 4 one eye).
std::optional<xr::MirrorMode> mirror_for_key(xr::Key key);

/// The keys the loop itself handles (mirror modes, quit), as text for --help.
std::string frame_loop_keys_text();

}  // namespace vdfx::app
