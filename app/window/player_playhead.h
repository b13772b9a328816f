/// @file
/// @brief The player's playhead: display time -> video frame, exactly (io::frame_at_time on
/// integer nanoseconds, so no drift however long it plays), with pause, seek and loop.
///
/// Video time = display time - origin while playing; frozen while paused. The first call to
/// frame_at() anchors frame 0's start at that display time.
#pragma once

#include <cstdint>
#include <optional>

#include "io/frame_time.h"

namespace vdfx::app {

class Playhead {
 public:
  Playhead(io::Rational fps, std::int64_t frames, bool loop);

  /// The video frame shown at display time t_ns, in [0, frames).
  std::int64_t frame_at(std::int64_t t_ns);
  /// Video time (ns from frame 0's start, before folding into the video) at display time t_ns.
  std::int64_t video_time_ns(std::int64_t t_ns);

  void set_paused(bool paused, std::int64_t t_ns);
  bool paused() const { return paused_; }
  /// Jumps to the start of `frame` (clamped to the video) at display time t_ns.
  void seek_to(std::int64_t frame, std::int64_t t_ns);
  /// Moves by `delta` frames from the frame shown at t_ns (wrapped when looping, else clamped).
  void seek_by(std::int64_t delta, std::int64_t t_ns);
  /// Looping off keeps the frame shown at t_ns (it does not jump to the end after a wrap).
  void set_loop(bool loop, std::int64_t t_ns);
  bool loop() const { return loop_; }
  io::Rational fps() const { return fps_; }
  std::int64_t frames() const { return frames_; }

 private:
  void anchor(std::int64_t t_ns);
  io::Rational fps_;
  std::int64_t frames_;
  bool loop_;
  bool paused_ = false;
  std::optional<std::int64_t> origin_ns_;  //!< display time of video time 0 (playing)
  std::int64_t paused_video_ns_ = 0;       //!< video time held while paused
};

}  // namespace vdfx::app
