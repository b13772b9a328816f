/// @file
/// @brief The GLFW glue's translation table, without a window.
#include <gtest/gtest.h>

#include "app/glfw_input_glue.h"

#ifdef VDFX_WITH_GL
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace vdfx::app {
namespace {

using xr::Key;

TEST(GlfwInputGlue, KeyTable) {
  const struct {
    int glfw;
    Key key;
  } rows[] = {
      {GLFW_KEY_A, Key::A},
      {GLFW_KEY_M, Key::M},
      {GLFW_KEY_Z, Key::Z},
      {GLFW_KEY_0, Key::Num0},
      {GLFW_KEY_9, Key::Num9},
      {GLFW_KEY_KP_3, Key::Num3},
      {GLFW_KEY_SPACE, Key::Space},
      {GLFW_KEY_ENTER, Key::Enter},
      {GLFW_KEY_KP_ENTER, Key::Enter},
      {GLFW_KEY_ESCAPE, Key::Escape},
      {GLFW_KEY_TAB, Key::Tab},
      {GLFW_KEY_BACKSPACE, Key::Backspace},
      {GLFW_KEY_DELETE, Key::Delete},
      {GLFW_KEY_LEFT, Key::Left},
      {GLFW_KEY_RIGHT, Key::Right},
      {GLFW_KEY_UP, Key::Up},
      {GLFW_KEY_DOWN, Key::Down},
      {GLFW_KEY_LEFT_SHIFT, Key::LeftShift},
      {GLFW_KEY_RIGHT_SHIFT, Key::RightShift},
      {GLFW_KEY_LEFT_CONTROL, Key::LeftControl},
      {GLFW_KEY_RIGHT_CONTROL, Key::RightControl},
      {GLFW_KEY_LEFT_ALT, Key::LeftAlt},
      {GLFW_KEY_RIGHT_ALT, Key::RightAlt},
      {GLFW_KEY_F1, Key::F1},
      {GLFW_KEY_F11, Key::F11},
      {GLFW_KEY_F12, Key::F12},
  };
  for (const auto& r : rows) {
    const auto k = translate_glfw_key(r.glfw);
    ASSERT_TRUE(k.has_value()) << r.glfw;
    EXPECT_EQ(*k, r.key) << r.glfw << " -> " << xr::key_name(*k);
  }
  for (int unknown : {GLFW_KEY_UNKNOWN, GLFW_KEY_F13, GLFW_KEY_HOME, GLFW_KEY_COMMA, GLFW_KEY_MENU})
    EXPECT_FALSE(translate_glfw_key(unknown).has_value()) << unknown;
}

TEST(GlfwInputGlue, MouseButtonsAndKeyActions) {
  EXPECT_EQ(translate_glfw_mouse_button(GLFW_MOUSE_BUTTON_LEFT), xr::MouseButton::Left);
  EXPECT_EQ(translate_glfw_mouse_button(GLFW_MOUSE_BUTTON_RIGHT), xr::MouseButton::Right);
  EXPECT_EQ(translate_glfw_mouse_button(GLFW_MOUSE_BUTTON_MIDDLE), xr::MouseButton::Middle);
  EXPECT_FALSE(translate_glfw_mouse_button(GLFW_MOUSE_BUTTON_4).has_value());

  const auto press = key_event(GLFW_KEY_V, GLFW_PRESS);
  ASSERT_TRUE(press.has_value());
  EXPECT_EQ(std::get<xr::KeyEvent>(*press).key, Key::V);
  EXPECT_TRUE(std::get<xr::KeyEvent>(*press).pressed);
  const auto release = key_event(GLFW_KEY_V, GLFW_RELEASE);
  ASSERT_TRUE(release.has_value());
  EXPECT_FALSE(std::get<xr::KeyEvent>(*release).pressed);
  // Auto-repeat is not a new press (a held key stays one press for the sim and the player).
  EXPECT_FALSE(key_event(GLFW_KEY_V, GLFW_REPEAT).has_value());
  EXPECT_FALSE(key_event(GLFW_KEY_HOME, GLFW_PRESS).has_value());
}

}  // namespace
}  // namespace vdfx::app
#endif
