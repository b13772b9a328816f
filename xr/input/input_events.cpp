/// @file
/// @brief Key names for binding tables and help text.
#include "xr/input/input_events.h"

#include <array>

namespace vdfx::xr {

std::string_view key_name(Key key) {
  static constexpr std::array<std::string_view, 26> letters = {
      "A", "B", "C", "D", "E", "F", "G", "H", "I", "J", "K", "L", "M",
      "N", "O", "P", "Q", "R", "S", "T", "U", "V", "W", "X", "Y", "Z"};
  static constexpr std::array<std::string_view, 10> digits = {"0", "1", "2", "3", "4",
                                                              "5", "6", "7", "8", "9"};
  static constexpr std::array<std::string_view, 12> fkeys = {"F1", "F2", "F3", "F4",  "F5",  "F6",
                                                             "F7", "F8", "F9", "F10", "F11", "F12"};
  const int k = static_cast<int>(key);
  if (key >= Key::A && key <= Key::Z) return letters[k - static_cast<int>(Key::A)];
  if (key >= Key::Num0 && key <= Key::Num9) return digits[k - static_cast<int>(Key::Num0)];
  if (key >= Key::F1 && key <= Key::F12) return fkeys[k - static_cast<int>(Key::F1)];
  switch (key) {
    case Key::Space: return "Space";
    case Key::Enter: return "Enter";
    case Key::Escape: return "Escape";
    case Key::Tab: return "Tab";
    case Key::Backspace: return "Backspace";
    case Key::Delete: return "Delete";
    case Key::Left: return "Left arrow";
    case Key::Right: return "Right arrow";
    case Key::Up: return "Up arrow";
    case Key::Down: return "Down arrow";
    case Key::LeftShift: return "Left Shift";
    case Key::RightShift: return "Right Shift";
    case Key::LeftControl: return "Left Ctrl";
    case Key::RightControl: return "Right Ctrl";
    case Key::LeftAlt: return "Left Alt";
    case Key::RightAlt: return "Right Alt";
    default: return "Unknown";
  }
}

}  // namespace vdfx::xr
