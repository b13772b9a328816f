/// @file
/// @brief The GLFW window glue: translates GLFW key, mouse and resize callbacks into
/// DesktopEvent and queues them. No logic lives here (style: imgui's AddKeyEvent queue);
/// the frame loop drains the queue once per frame and hands each event to the input backend and
/// to its client.
#pragma once

#include <optional>
#include <vector>

#include "xr/input/input_events.h"

struct GLFWwindow;

namespace vdfx::xr {

/// GLFW_KEY_* -> xr::Key; nullopt for keys vdfx has no name for.
std::optional<Key> translate_glfw_key(int glfw_key);
/// GLFW_MOUSE_BUTTON_* -> MouseButton; nullopt for the extra buttons.
std::optional<MouseButton> translate_glfw_mouse_button(int glfw_button);
/// A GLFW key action (GLFW_PRESS, GLFW_REPEAT, GLFW_RELEASE) as an event; repeats are dropped
/// (a held key is one press), so nullopt for them and for untranslated keys.
std::optional<DesktopEvent> key_event(int glfw_key, int glfw_action);

/// Installs the callbacks on `window` (it takes the window's user pointer) and queues events.
class GlfwInputGlue {
 public:
  explicit GlfwInputGlue(GLFWwindow* window);
  ~GlfwInputGlue();
  GlfwInputGlue(const GlfwInputGlue&) = delete;
  GlfwInputGlue& operator=(const GlfwInputGlue&) = delete;

  /// The events queued since the last call, in arrival order.
  std::vector<DesktopEvent> drain();
  /// Queues an event as if the window had sent it (tests, scripted keys).
  void push(const DesktopEvent& e) { queue_.push_back(e); }

 private:
  GLFWwindow* window_;
  std::vector<DesktopEvent> queue_;
};

}  // namespace vdfx::xr
