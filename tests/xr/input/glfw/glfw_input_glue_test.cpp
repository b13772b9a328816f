/// @file
/// @brief The GLFW glue's translation table, without a window.
#include "xr/input/glfw/glfw_input_glue.h"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace vdfx::xr {
namespace {

// Properties of the table rather than a second copy of it: every key vdfx names is reachable
// from some GLFW key; printable GLFW codes (ASCII for letters and digits) and F-keys land on the
// key of that name; two GLFW keys share a vdfx key only as the keypad's aliases.
TEST(GlfwInputGlue, EveryKeyIsReachableAndNamedAsGlfwNamesIt) {
  std::map<Key, std::vector<int>> sources;
  for (int g = GLFW_KEY_SPACE; g <= GLFW_KEY_LAST; ++g)
    if (const auto k = translate_glfw_key(g)) sources[*k].push_back(g);
  for (int k = static_cast<int>(Key::A); k <= static_cast<int>(Key::F12); ++k)
    EXPECT_TRUE(sources.count(static_cast<Key>(k))) << key_name(static_cast<Key>(k));
  EXPECT_FALSE(sources.count(Key::Unknown));
  for (int g = GLFW_KEY_0; g <= GLFW_KEY_Z; ++g)
    if (const auto k = translate_glfw_key(g)) {
      EXPECT_EQ(key_name(*k), std::string(1, char(g)));
    }
  for (int f = 0; f < 12; ++f)
    EXPECT_EQ(key_name(*translate_glfw_key(GLFW_KEY_F1 + f)), "F" + std::to_string(f + 1));
  for (const auto& [key, glfw] : sources) {
    if (glfw.size() == 1) continue;
    for (int g : glfw) {
      const bool keypad = g >= GLFW_KEY_KP_0 && g <= GLFW_KEY_KP_EQUAL;
      const bool main = (g >= GLFW_KEY_0 && g <= GLFW_KEY_9) || g == GLFW_KEY_ENTER;
      EXPECT_TRUE(keypad || main) << key_name(key) << " also from GLFW key " << g;
    }
  }
  EXPECT_EQ(translate_glfw_key(GLFW_KEY_KP_3), Key::Num3);
  EXPECT_EQ(translate_glfw_key(GLFW_KEY_KP_ENTER), Key::Enter);
  for (int unknown : {GLFW_KEY_UNKNOWN, GLFW_KEY_F13, GLFW_KEY_HOME, GLFW_KEY_COMMA, GLFW_KEY_MENU})
    EXPECT_FALSE(translate_glfw_key(unknown).has_value()) << unknown;
}

TEST(GlfwInputGlue, MouseButtonsAndKeyActions) {
  EXPECT_EQ(translate_glfw_mouse_button(GLFW_MOUSE_BUTTON_LEFT), MouseButton::Left);
  EXPECT_EQ(translate_glfw_mouse_button(GLFW_MOUSE_BUTTON_RIGHT), MouseButton::Right);
  EXPECT_EQ(translate_glfw_mouse_button(GLFW_MOUSE_BUTTON_MIDDLE), MouseButton::Middle);
  EXPECT_FALSE(translate_glfw_mouse_button(GLFW_MOUSE_BUTTON_4).has_value());

  const auto press = key_event(GLFW_KEY_V, GLFW_PRESS);
  ASSERT_TRUE(press.has_value());
  EXPECT_EQ(std::get<KeyEvent>(*press).key, Key::V);
  EXPECT_TRUE(std::get<KeyEvent>(*press).pressed);
  const auto release = key_event(GLFW_KEY_V, GLFW_RELEASE);
  ASSERT_TRUE(release.has_value());
  EXPECT_FALSE(std::get<KeyEvent>(*release).pressed);
  // Auto-repeat is not a new press (a held key stays one press for the sim and the player).
  EXPECT_FALSE(key_event(GLFW_KEY_V, GLFW_REPEAT).has_value());
  EXPECT_FALSE(key_event(GLFW_KEY_HOME, GLFW_PRESS).has_value());
}

}  // namespace
}  // namespace vdfx::xr
