/// @file
/// @brief Desktop input events (keys, mouse) as the window glue queues them.
///
/// The glue (GLFW callbacks) only translates to these and queues them on the active backend
/// (InputBackend::push_event); all logic lives in the backends, so tests drive them without a
/// window. These are vdfx's own types, not GLFW's.
#pragma once

#include <glm/vec3.hpp>
#include <optional>
#include <string_view>
#include <variant>

namespace vdfx::xr {

enum class Key {
  Unknown,
  A,
  B,
  C,
  D,
  E,
  F,
  G,
  H,
  I,
  J,
  K,
  L,
  M,
  N,
  O,
  P,
  Q,
  R,
  S,
  T,
  U,
  V,
  W,
  X,
  Y,
  Z,
  Num0,
  Num1,
  Num2,
  Num3,
  Num4,
  Num5,
  Num6,
  Num7,
  Num8,
  Num9,
  Space,
  Enter,
  Escape,
  Tab,
  Backspace,
  Delete,
  Left,
  Right,
  Up,
  Down,
  LeftShift,
  RightShift,
  LeftControl,
  RightControl,
  LeftAlt,
  RightAlt,
  F1,
  F2,
  F3,
  F4,
  F5,
  F6,
  F7,
  F8,
  F9,
  F10,
  F11,
  F12,
};

enum class MouseButton { Left, Right, Middle };

/// The printable name of a key ("Space", "W", "Left arrow").
std::string_view key_name(Key key);

struct KeyEvent {
  Key key = Key::Unknown;
  bool pressed = false;
};

struct MouseButtonEvent {
  MouseButton button = MouseButton::Left;
  bool pressed = false;
};

/// A ray in the head's frame (VIEW space): origin (an eye, or the head) and unit direction.
struct ViewRay {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0, 0.0, -1.0};
};

/// Cursor position in window pixels, origin top-left, y down (as window systems report it).
struct MouseMoveEvent {
  double x = 0.0;
  double y = 0.0;
  /// The ray along which the mirror drew the scene point under the cursor (xr::mirror_ray), set
  /// by the frame loop; the sim aims through it. Unset: the sim's own pinhole of the window.
  std::optional<ViewRay> ray{};
  /// False when the cursor is over no drawn view (letterbox bars, beyond a lens's valid radius):
  /// the mouse button then presses nothing.
  bool over_view = true;
};

/// The desktop view changed: window size in pixels and the horizontal field of view it shows.
struct ViewGeometryEvent {
  int width_px = 0;
  int height_px = 0;
  double hfov_deg = 0.0;
};

using DesktopEvent = std::variant<KeyEvent, MouseButtonEvent, MouseMoveEvent, ViewGeometryEvent>;

}  // namespace vdfx::xr
