/// @file
/// @brief GLFW -> DesktopEvent translation table and callback glue.
#include "xr/input/glfw/glfw_input_glue.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <array>
#include <utility>

namespace vdfx::xr {

namespace {

// GLFW's key codes are ASCII for letters and digits; the rest are listed.
constexpr std::array<std::pair<int, Key>, 28> kNamedKeys{{
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
    {GLFW_KEY_F2, Key::F2},
    {GLFW_KEY_F3, Key::F3},
    {GLFW_KEY_F4, Key::F4},
    {GLFW_KEY_F5, Key::F5},
    {GLFW_KEY_F6, Key::F6},
    {GLFW_KEY_F7, Key::F7},
    {GLFW_KEY_F8, Key::F8},
    {GLFW_KEY_F9, Key::F9},
    {GLFW_KEY_F10, Key::F10},
    {GLFW_KEY_F11, Key::F11},
}};

GlfwInputGlue* glue_of(GLFWwindow* w) {
  return static_cast<GlfwInputGlue*>(glfwGetWindowUserPointer(w));
}

}  // namespace

std::optional<Key> translate_glfw_key(int k) {
  if (k >= GLFW_KEY_A && k <= GLFW_KEY_Z)
    return static_cast<Key>(static_cast<int>(Key::A) + (k - GLFW_KEY_A));
  if (k >= GLFW_KEY_0 && k <= GLFW_KEY_9)
    return static_cast<Key>(static_cast<int>(Key::Num0) + (k - GLFW_KEY_0));
  if (k >= GLFW_KEY_KP_0 && k <= GLFW_KEY_KP_9)
    return static_cast<Key>(static_cast<int>(Key::Num0) + (k - GLFW_KEY_KP_0));
  if (k == GLFW_KEY_F12) return Key::F12;
  for (const auto& [g, key] : kNamedKeys)
    if (g == k) return key;
  return std::nullopt;
}

std::optional<MouseButton> translate_glfw_mouse_button(int b) {
  switch (b) {
    case GLFW_MOUSE_BUTTON_LEFT: return MouseButton::Left;
    case GLFW_MOUSE_BUTTON_RIGHT: return MouseButton::Right;
    case GLFW_MOUSE_BUTTON_MIDDLE: return MouseButton::Middle;
    default: return std::nullopt;
  }
}

std::optional<DesktopEvent> key_event(int glfw_key, int glfw_action) {
  if (glfw_action == GLFW_REPEAT) return std::nullopt;
  const auto key = translate_glfw_key(glfw_key);
  if (!key) return std::nullopt;
  return KeyEvent{*key, glfw_action == GLFW_PRESS};
}

GlfwInputGlue::GlfwInputGlue(GLFWwindow* window) : window_(window) {
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
    if (auto e = key_event(key, action)) glue_of(w)->push(*e);
  });
  glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int) {
    if (auto b = translate_glfw_mouse_button(button))
      glue_of(w)->push(MouseButtonEvent{*b, action == GLFW_PRESS});
  });
  glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
    glue_of(w)->push(MouseMoveEvent{x, y});
  });
}

GlfwInputGlue::~GlfwInputGlue() {
  glfwSetKeyCallback(window_, nullptr);
  glfwSetMouseButtonCallback(window_, nullptr);
  glfwSetCursorPosCallback(window_, nullptr);
  glfwSetWindowUserPointer(window_, nullptr);
}

std::vector<DesktopEvent> GlfwInputGlue::drain() {
  return std::exchange(queue_, {});
}

}  // namespace vdfx::xr
