/// @file
/// @brief The player (`vdfx play`): a FrameClient with no authoring UI. Plays the video against
/// the display time (exact frame mapping, app/window/player_playhead.h), interpolates the sidecar's
/// effects at the head's forward direction (and its flares and grain for the head pose), and has
/// the perception-study switches: view-dependent vs per-pixel parameters, and the unaltered film
/// while a key is held.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "app/window/frame_client.h"
#include "app/window/player_playhead.h"
#include "effects/flare_set.h"
#include "effects/grain_layout.h"
#include "effects/stack_interpolator.h"
#include "io/frame_decoder.h"
#include "io/sidecar.h"

namespace vdfx::app {

struct PlayerOptions {
  bool loop = true;
  double seek_step_s = 5.0;  //!< B / F keys
  ParamMode mode = ParamMode::ViewDependent;
};

class Player : public FrameClient {
 public:
  /// `video` is what is played (its rate and length drive the playhead); the sidecar's keyframe
  /// frames are indices of that video. Throws io::InputError when the sidecar's effects cannot be
  /// interpolated (e.g. a duplicated effect type).
  Player(const io::Sidecar& sidecar, const io::VideoProperties& video, PlayerOptions options = {});

  void on_desktop_event(const xr::DesktopEvent& event) override;
  void update(const xr::InputState& input, std::int64_t display_time_ns, FrameInfo& info) override;
  effects::StackParams params(const effects::Direction& direction, std::int64_t frame) override;
  std::function<effects::StackParams(const effects::Direction&)> params_at(
      std::int64_t frame) override;
  std::vector<effects::GrainFrame> grains(const xr::Pose& head_in_local,
                                          std::int64_t display_time_ns,
                                          std::int64_t frame) override;
  std::vector<effects::FlareLayout> flares(const xr::Pose& head_in_local, std::int64_t frame,
                                           const io::Picture* picture) override;
  unsigned active_effects() const override { return active_; }
  bool unaltered() const override { return unaltered_key_ || unaltered_button_; }
  ParamMode param_mode() const override { return mode_; }
  std::string status_line() const override;

  const Playhead& playhead() const { return playhead_; }
  std::int64_t current_frame() const { return frame_; }

  /// The player's keys and controller buttons, as text for --help and docs/player.md.
  static std::string keys_text();

 private:
  void apply_key(xr::Key key, std::int64_t t_ns);
  effects::StackInterpolator interp_;
  effects::FlareSet flares_;
  effects::GrainSet grains_;
  unsigned active_ = 0;
  Playhead playhead_;
  PlayerOptions options_;
  ParamMode mode_;
  std::vector<xr::Key> pending_keys_;  //!< pressed since the last update (applied at its time)
  bool unaltered_key_ = false, unaltered_button_ = false;
  std::int64_t frame_ = 0;
};

}  // namespace vdfx::app
