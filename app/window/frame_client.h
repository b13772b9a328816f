/// @file
/// @brief What the windowed frame loop (app/window/frame_loop.h) asks of the program it runs: the
/// player (app/window/player.h) or the editor. One call of update() per frame, then params() once
/// for both eyes.
///
/// Order per frame: desktop events (on_desktop_event) -> update(input at the display time) ->
/// the loop fetches info.video_frame from the decoder -> params(head forward, shown frame) unless
/// unaltered() -> flares(head pose, shown frame) and grains(head pose, display time, shown frame)
/// unless unaltered() -> quads() -> both eyes rendered -> mirror.
#pragma once

#include <cstdint>
#include <functional>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "effects/coords.h"
#include "effects/effect_types.h"
#include "effects/flare_layout.h"
#include "effects/grain_layout.h"
#include "io/picture.h"
#include "xr/headset/session.h"
#include "xr/input/actions.h"
#include "xr/input/input_events.h"

namespace vdfx::app {

/// How the effect parameters reach the pixels (the paper's perception-study A/B switch).
enum class ParamMode {
  ViewDependent,  //!< one parameter set per frame, at the head's forward direction (the paper)
  PerPixel,       //!< each direction of the sphere gets its own parameters (static baseline)
};

/// Per-frame exchange between the loop and its client.
struct FrameInfo {
  // Set by the loop before update().
  std::int64_t loop_frame = 0;          //!< frames rendered before this one
  std::int64_t display_time_ns = 0;     //!< predicted display time (replay: the recording's)
  effects::Direction head_forward;      //!< where the head looks at the display time
  std::int64_t shown_video_frame = -1;  //!< the video frame on screen before this one (-1: none)
  // Set by the client in update().
  std::int64_t video_frame = 0;  //!< the video frame this display time shows
  bool video_paused = false;     //!< the decoder need not read ahead of video_frame
  bool video_loop = true;        //!< the decoder wraps at the end
  bool request_exit = false;     //!< end the loop after this frame
  /// A short vibration on this hand's controller (a keyframe was placed); headsets only.
  std::optional<xr::Hand> haptic_pulse;
};

class FrameClient {
 public:
  virtual ~FrameClient() = default;
  /// A window event, after the input backend has had it (the sim backend turns keys into
  /// actions; the client may also react to keys the sim does not bind).
  virtual void on_desktop_event(const xr::DesktopEvent& event) { (void)event; }
  /// Once per frame with the actions at the display time; sets info.video_frame and friends.
  virtual void update(const xr::InputState& input, std::int64_t display_time_ns,
                      FrameInfo& info) = 0;
  /// The stack's parameters for a view direction at a video frame. View-dependent mode calls it
  /// once per frame at the head's forward direction (both eyes alike); per-pixel mode calls it
  /// for every cell of the baked equirect grid (FrameLoopOptions::bake_width x bake_height).
  virtual effects::StackParams params(const effects::Direction& direction,
                                      std::int64_t video_frame) = 0;
  /// params() at one video frame for many directions (the per-pixel bake). A client whose
  /// stack has anchored effects overrides it to turn their centres once for the frame
  /// (effects::StackAtFrame) instead of each cell's direction.
  virtual std::function<effects::StackParams(const effects::Direction&)> params_at(
      std::int64_t video_frame) {
    return [this, video_frame](const effects::Direction& d) { return params(d, video_frame); };
  }
  /// effects::shader_bit mask of the effects that have keyframes (only these are compiled in).
  virtual unsigned active_effects() const = 0;
  /// Changes whenever params() would answer differently for the same arguments (an edit); the
  /// per-pixel bake is redone when it or the shown frame changes.
  virtual std::uint64_t params_revision() const { return 0; }
  /// This frame's flares for the head pose (LOCAL) at a video frame, computed once and drawn
  /// into both eyes after the effects (docs/flare.md). `picture` is that video frame as decoded
  /// (null while none is), for lights found in the video (converted only then: io::to_rgb).
  virtual std::vector<effects::FlareLayout> flares(const xr::Pose& head_in_local,
                                                   std::int64_t video_frame,
                                                   const io::Picture* picture) {
    (void)head_in_local, (void)video_frame, (void)picture;
    return {};
  }
  /// This frame's grain layers for the head pose (LOCAL) at a display time and video frame,
  /// laid out once and drawn into both eyes after the flares (docs/grain.md). The display time
  /// picks the grain pattern (one per refresh_ms); the frame, with the head's direction, the
  /// keyframed intensity and size.
  virtual std::vector<effects::GrainFrame> grains(const xr::Pose& head_in_local,
                                                  std::int64_t display_time_ns,
                                                  std::int64_t video_frame) {
    (void)head_in_local, (void)display_time_ns, (void)video_frame;
    return {};
  }
  /// UI panels, composited after the effects (never blurred or tinted).
  virtual std::vector<xr::QuadLayer> quads() { return {}; }
  /// True while the plain film should be shown (no effect at all).
  virtual bool unaltered() const { return false; }
  virtual ParamMode param_mode() const { return ParamMode::ViewDependent; }
  /// A short line for the window title ("frame 12/300  view-dependent").
  virtual std::string status_line() const { return {}; }
};

}  // namespace vdfx::app
