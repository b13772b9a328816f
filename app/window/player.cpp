/// @file
/// @brief Player: playhead, keys, and the sidecar's interpolated effects.
#include "app/window/player.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "app/window/flare_layouts.h"
#include "effects/effect_shaders.h"
#include "io/sidecar_sets.h"
#include "io/ycbcr.h"

namespace vdfx::app {

Player::Player(const io::Sidecar& sidecar, const io::VideoProperties& video, PlayerOptions options)
    : interp_(io::stack_of(sidecar)),
      flares_(io::flare_set_of(sidecar)),
      grains_(io::grain_set_of(sidecar)),
      playhead_(video.fps, std::max<std::int64_t>(video.frames, 1), options.loop),
      options_(options),
      mode_(options.mode) {
  for (const auto& spec : effects::all_effect_specs())
    if (interp_.active(spec.type)) active_ |= effects::shader_bit(spec.type);
}

std::string Player::keys_text() {
  return "  P                         pause / play\n"
         "  B / F                     seek back / forward (--seek-step seconds, default 5)\n"
         "  N                         next frame (pauses)\n"
         "  R                         restart from frame 0\n"
         "  O                         loop on / off\n"
         "  V                         A/B: view-dependent <-> per-pixel parameters\n"
         "  U (held)                  unaltered film (no effects) while held\n"
         "  right controller b        A/B switch (sim: K)\n"
         "  right controller a (held) unaltered film (sim: J)\n";
}

void Player::on_desktop_event(const xr::DesktopEvent& event) {
  const auto* k = std::get_if<xr::KeyEvent>(&event);
  if (!k) return;
  if (k->key == xr::Key::U) {
    unaltered_key_ = k->pressed;
    return;
  }
  if (k->pressed) pending_keys_.push_back(k->key);
}

void Player::apply_key(xr::Key key, std::int64_t t) {
  const auto step =
      static_cast<std::int64_t>(std::llround(options_.seek_step_s * playhead_.fps().value()));
  switch (key) {
    case xr::Key::P: playhead_.set_paused(!playhead_.paused(), t); break;
    case xr::Key::B: playhead_.seek_by(-step, t); break;
    case xr::Key::F: playhead_.seek_by(step, t); break;
    case xr::Key::N:
      playhead_.set_paused(true, t);
      playhead_.seek_by(1, t);
      break;
    case xr::Key::R: playhead_.seek_to(0, t); break;
    case xr::Key::O: playhead_.set_loop(!playhead_.loop(), t); break;
    case xr::Key::V:
      mode_ = mode_ == ParamMode::ViewDependent ? ParamMode::PerPixel : ParamMode::ViewDependent;
      break;
    default: break;
  }
}

void Player::update(const xr::InputState& input, std::int64_t t, FrameInfo& info) {
  for (xr::Key k : pending_keys_) apply_key(k, t);
  pending_keys_.clear();
  // Controller: b toggles A/B on its press, a shows the unaltered film while held.
  if (input.edges.was_pressed(xr::Hand::Right, xr::Control::Secondary)) apply_key(xr::Key::V, t);
  unaltered_button_ = input.edges.is_down(xr::Hand::Right, xr::Control::Primary);

  frame_ = playhead_.frame_at(t);
  info.video_frame = frame_;
  info.video_paused = playhead_.paused();
  info.video_loop = playhead_.loop();
}

effects::StackParams Player::params(const effects::Direction& direction, std::int64_t frame) {
  return interp_.evaluate(direction, frame);
}

std::function<effects::StackParams(const effects::Direction&)> Player::params_at(
    std::int64_t frame) {
  return [at = std::make_shared<const effects::StackAtFrame>(interp_, frame)](
             const effects::Direction& d) { return at->evaluate(d); };
}

std::vector<effects::FlareLayout> Player::flares(const xr::Pose& head, std::int64_t frame,
                                                 const io::Picture* picture) {
  return flare_layouts(flares_, head, frame, picture);
}

std::vector<effects::GrainFrame> Player::grains(const xr::Pose& head, std::int64_t display_time_ns,
                                                std::int64_t frame) {
  if (grains_.empty()) return {};
  return grains_.layout({xr::position_of(head), xr::rotation_of(head)}, display_time_ns, frame);
}

std::string Player::status_line() const {
  std::ostringstream s;
  s << "frame " << frame_ << "/" << playhead_.frames() << (playhead_.paused() ? "  paused" : "")
    << (playhead_.loop() ? "  loop" : "") << "  "
    << (mode_ == ParamMode::ViewDependent ? "view-dependent" : "per-pixel")
    << (unaltered() ? "  UNALTERED" : "");
  return s.str();
}

}  // namespace vdfx::app
