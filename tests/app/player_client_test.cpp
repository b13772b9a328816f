/// @file
/// @brief Player as a FrameClient: keys, controller buttons, active effects, parameters.
#include <gtest/gtest.h>

#include "app/window/player.h"
#include "effects/effect_shaders.h"
#include "player_test_support.h"

namespace vdfx::app {
namespace {

using effects::EffectType;

io::VideoProperties props(std::int64_t frames) {
  io::VideoProperties v;
  v.fps = {30, 1};
  v.frames = frames;
  return v;
}

xr::DesktopEvent key(xr::Key k, bool pressed) {
  return xr::KeyEvent{k, pressed};
}

struct Step {
  std::vector<xr::DesktopEvent> events;
  std::int64_t t_ns;
  bool right_a = false, right_b = false;
};

/// One frame; `sync` carries the controller edges across steps (InputBackend::poll's job), a
/// fresh one is used when none is given.
FrameInfo step(Player& p, const Step& s, xr::ActionSync* sync = nullptr) {
  xr::ActionSync fresh;
  if (!sync) sync = &fresh;
  for (const auto& e : s.events) p.on_desktop_event(e);
  xr::InputState in = xr::neutral_input_state(s.t_ns);
  in.right.tracked = true;
  in.right.primary = s.right_a;
  in.right.secondary = s.right_b;
  FrameInfo info;
  p.update(sync->sync(in), s.t_ns, info);
  return info;
}

TEST(PlayerClient, ActiveEffectsAreTheTracksWithKeyframes) {
  const auto sc = test::one_effect_sidecar(EffectType::Exposure, {{0, 0, {1.0}}});
  Player p(sc, props(100));
  EXPECT_EQ(p.active_effects(), effects::shader_bit(EffectType::Exposure));
  EXPECT_DOUBLE_EQ(p.params({0, 0}, 0).exposure_stops, 1.0);
}

TEST(PlayerClient, KeysAndButtons) {
  const auto sc = test::one_effect_sidecar(EffectType::Exposure, {{0, 0, {1.0}}});
  Player p(sc, props(300));
  const std::int64_t s = 1'000'000'000;
  EXPECT_EQ(step(p, {{}, 0}).video_frame, 0);
  EXPECT_EQ(step(p, {{}, s}).video_frame, 30);
  // P pauses: the frame holds and the decoder is told.
  FrameInfo i = step(p, {{key(xr::Key::P, true), key(xr::Key::P, false)}, s});
  EXPECT_TRUE(i.video_paused);
  EXPECT_EQ(step(p, {{}, 3 * s}).video_frame, 30);
  // N steps one frame; F seeks 5 s forward; R restarts.
  EXPECT_EQ(step(p, {{key(xr::Key::N, true)}, 3 * s}).video_frame, 31);
  EXPECT_EQ(step(p, {{key(xr::Key::F, true)}, 3 * s}).video_frame, 181);
  EXPECT_EQ(step(p, {{key(xr::Key::B, true)}, 3 * s}).video_frame, 31);
  EXPECT_EQ(step(p, {{key(xr::Key::R, true)}, 3 * s}).video_frame, 0);
  // O toggles looping.
  EXPECT_TRUE(step(p, {{}, 3 * s}).video_loop);
  EXPECT_FALSE(step(p, {{key(xr::Key::O, true)}, 3 * s}).video_loop);
  // V toggles the A/B mode, as does the right b button on its press (not while held).
  EXPECT_EQ(p.param_mode(), ParamMode::ViewDependent);
  step(p, {{key(xr::Key::V, true)}, 3 * s});
  EXPECT_EQ(p.param_mode(), ParamMode::PerPixel);
  xr::ActionSync sync;
  step(p, {{}, 3 * s, false, true}, &sync);
  EXPECT_EQ(p.param_mode(), ParamMode::ViewDependent);
  step(p, {{}, 3 * s, false, true}, &sync);
  EXPECT_EQ(p.param_mode(), ParamMode::ViewDependent);
  step(p, {{}, 3 * s, false, false}, &sync);
  step(p, {{}, 3 * s, false, true}, &sync);
  EXPECT_EQ(p.param_mode(), ParamMode::PerPixel);
  // U and the right a button show the unaltered film while held.
  EXPECT_FALSE(p.unaltered());
  step(p, {{key(xr::Key::U, true)}, 3 * s});
  EXPECT_TRUE(p.unaltered());
  step(p, {{key(xr::Key::U, false)}, 3 * s});
  EXPECT_FALSE(p.unaltered());
  step(p, {{}, 3 * s, true});
  EXPECT_TRUE(p.unaltered());
  step(p, {{}, 3 * s, false});
  EXPECT_FALSE(p.unaltered());
}

TEST(PlayerClient, KeysTextNamesEveryKey) {
  const std::string text = Player::keys_text();
  for (const char* k : {"P ", "B / F", "N ", "R ", "O ", "V ", "U (held)"})
    EXPECT_NE(text.find(k), std::string::npos) << k;
}

}  // namespace
}  // namespace vdfx::app
