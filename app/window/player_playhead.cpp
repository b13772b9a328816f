/// @file
/// @brief Playhead: exact display time -> frame mapping with pause, seek and loop.
#include "app/window/player_playhead.h"

#include <algorithm>
#include <stdexcept>

namespace vdfx::app {

Playhead::Playhead(io::Rational fps, std::int64_t frames, bool loop)
    : fps_(fps), frames_(frames), loop_(loop) {
  if (fps.num <= 0 || fps.den <= 0 || frames < 1)
    throw std::invalid_argument("Playhead: needs a positive frame rate and at least one frame");
}

void Playhead::anchor(std::int64_t t_ns) {
  if (!origin_ns_) origin_ns_ = t_ns;
}

std::int64_t Playhead::video_time_ns(std::int64_t t_ns) {
  anchor(t_ns);
  return paused_ ? paused_video_ns_ : t_ns - *origin_ns_;
}

std::int64_t Playhead::frame_at(std::int64_t t_ns) {
  return io::playback_frame(video_time_ns(t_ns), fps_, frames_, loop_);
}

void Playhead::set_paused(bool paused, std::int64_t t_ns) {
  if (paused == paused_) return;
  const std::int64_t v = video_time_ns(t_ns);
  paused_ = paused;
  if (paused_)
    paused_video_ns_ = v;
  else
    origin_ns_ = t_ns - v;
}

void Playhead::seek_to(std::int64_t frame, std::int64_t t_ns) {
  anchor(t_ns);
  const std::int64_t v = io::frame_start_ns(std::clamp<std::int64_t>(frame, 0, frames_ - 1), fps_);
  if (paused_)
    paused_video_ns_ = v;
  else
    origin_ns_ = t_ns - v;
}

void Playhead::seek_by(std::int64_t delta, std::int64_t t_ns) {
  std::int64_t f = frame_at(t_ns) + delta;
  if (loop_) f = ((f % frames_) + frames_) % frames_;
  seek_to(f, t_ns);
}

void Playhead::set_loop(bool loop, std::int64_t t_ns) {
  if (loop == loop_) return;
  const std::int64_t f = frame_at(t_ns);
  loop_ = loop;
  seek_to(f, t_ns);
}

}  // namespace vdfx::app
