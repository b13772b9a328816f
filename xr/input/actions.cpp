/// @file
/// @brief Action paths to InputState fields.
#include "xr/input/actions.h"

#include <cmath>
#include <functional>

namespace vdfx::xr {

namespace {

using Getter = std::function<ActionValue(const InputState&)>;

std::vector<std::pair<std::string, Getter>> build_table() {
  std::vector<std::pair<std::string, Getter>> t;
  t.emplace_back("/user/head/pose", [](const InputState& s) { return ActionValue(s.head); });
  t.emplace_back("/user/head/tracked",
                 [](const InputState& s) { return ActionValue(s.head_tracked); });
  for (Hand hand : {Hand::Left, Hand::Right}) {
    const std::string base = std::string("/user/hand/") + (hand == Hand::Left ? "left" : "right");
    const std::string in = base + "/input/";
    auto h = [hand](const InputState& s) -> const HandState& { return s.hand(hand); };
    t.emplace_back(base + "/tracked",
                   [h](const InputState& s) { return ActionValue(h(s).tracked); });
    t.emplace_back(in + "aim/pose", [h](const InputState& s) { return ActionValue(h(s).aim); });
    t.emplace_back(in + "grip/pose", [h](const InputState& s) { return ActionValue(h(s).grip); });
    t.emplace_back(in + "trigger/value",
                   [h](const InputState& s) { return ActionValue(h(s).trigger); });
    t.emplace_back(in + "squeeze/value",
                   [h](const InputState& s) { return ActionValue(h(s).squeeze); });
    t.emplace_back(in + "thumbstick",
                   [h](const InputState& s) { return ActionValue(h(s).thumbstick); });
    t.emplace_back(in + "thumbstick/x",
                   [h](const InputState& s) { return ActionValue(h(s).thumbstick.x); });
    t.emplace_back(in + "thumbstick/y",
                   [h](const InputState& s) { return ActionValue(h(s).thumbstick.y); });
    t.emplace_back(in + "thumbstick/click",
                   [h](const InputState& s) { return ActionValue(h(s).thumbstick_click); });
    const bool left = hand == Hand::Left;
    t.emplace_back(in + (left ? "x/click" : "a/click"),
                   [h](const InputState& s) { return ActionValue(h(s).primary); });
    t.emplace_back(in + (left ? "y/click" : "b/click"),
                   [h](const InputState& s) { return ActionValue(h(s).secondary); });
    if (left) {
      t.emplace_back(in + "menu/click",
                     [h](const InputState& s) { return ActionValue(h(s).menu); });
    }
  }
  return t;
}

const std::vector<std::pair<std::string, Getter>>& table() {
  static const auto t = build_table();
  return t;
}

}  // namespace

namespace {

bool analog_down(double value, bool was_down) {
  return was_down ? value >= kReleaseThreshold : value > kPressThreshold;
}

}  // namespace

ControlSet controls_down(const InputState& s, ControlSet before) {
  ControlSet out;
  for (const Hand h : {Hand::Left, Hand::Right}) {
    const HandState& hs = s.hand(h);
    if (!hs.tracked) continue;
    const auto analog = [&](Control c, double v) {
      out.set(h, c, analog_down(v, before.has(h, c)));
    };
    analog(Control::Trigger, hs.trigger);
    analog(Control::Squeeze, hs.squeeze);
    analog(Control::StickUp, hs.thumbstick.y);
    analog(Control::StickDown, -hs.thumbstick.y);
    analog(Control::StickRight, hs.thumbstick.x);
    analog(Control::StickLeft, -hs.thumbstick.x);
    out.set(h, Control::Primary, hs.primary);
    out.set(h, Control::Secondary, hs.secondary);
    out.set(h, Control::Menu, hs.menu);
    out.set(h, Control::StickClick, hs.thumbstick_click);
  }
  return out;
}

ActionEdges action_edges(const InputState& now, ControlSet before) {
  ActionEdges e;
  e.down = controls_down(now, before);
  e.pressed.bits = e.down.bits & ~before.bits;
  e.released.bits = before.bits & ~e.down.bits;
  return e;
}

InputState neutral_input_state(std::int64_t t_ns) {
  InputState s;
  s.t_ns = t_ns;
  s.head.position = {0.0, kDefaultEyeHeight, 0.0};
  return s;
}

std::optional<ActionValue> get_action(const InputState& state, std::string_view path) {
  for (const auto& [name, get] : table()) {
    if (name == path) return get(state);
  }
  return std::nullopt;
}

const std::vector<std::string>& action_paths() {
  static const std::vector<std::string> paths = [] {
    std::vector<std::string> p;
    for (const auto& entry : table()) p.push_back(entry.first);
    return p;
  }();
  return paths;
}

}  // namespace vdfx::xr
