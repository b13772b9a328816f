/// @file
/// @brief OpenXR-shaped input actions: a pure-data snapshot of head and hand state at a time.
///
/// The editor and player read only these, never devices. Poses use GLM doubles: glm::dquat is
/// (w, x, y, z) and positions are metres in OpenXR axes (+x right, +y up, -z forward). The head
/// pose is the VIEW reference space located in LOCAL.
///
/// Paths (lookup by string with get_action, typed access through the structs):
///   /user/head/pose, /user/head/tracked
///   /user/hand/{left,right}/input/{aim,grip}/pose
///   /user/hand/{left,right}/input/{trigger,squeeze}/value           [0, 1]
///   /user/hand/{left,right}/input/thumbstick (vec2), .../thumbstick/{x,y}  [-1, 1]
///   /user/hand/{left,right}/input/thumbstick/click
///   /user/hand/right/input/{a,b}/click, /user/hand/left/input/{x,y,menu}/click
///   /user/hand/{left,right}/tracked  (vdfx: whether the hand's poses are valid)
#pragma once

#include <cstdint>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "effects/coords.h"
#include "xr/headset/pose.h"

namespace vdfx::xr {

enum class Hand { Left = 0, Right = 1 };

/// The buttons of a hand, and the analog controls read as buttons (trigger and squeeze pulled,
/// the thumbstick pushed one way). The sim's key bindings and the edges below use this list.
enum class Control : std::uint8_t {
  Trigger,
  Squeeze,
  Primary,
  Secondary,
  Menu,
  StickClick,
  StickUp,
  StickDown,
  StickLeft,
  StickRight,
};
inline constexpr int kControlCount = 10;

/// The one table of thresholds: an analog control (trigger, squeeze, a thumbstick axis) goes
/// down above kPressThreshold and up again below kReleaseThreshold. ActionEdges is the only edge
/// detector: the UI pointers take the trigger's edges from it (ui::ButtonEdges).
inline constexpr double kPressThreshold = 0.55;
inline constexpr double kReleaseThreshold = 0.45;

/// A set of (hand, control) pairs, one bit each.
struct ControlSet {
  std::uint32_t bits = 0;
  static constexpr std::uint32_t bit(Hand h, Control c) {
    return 1u << (static_cast<int>(h) * kControlCount + static_cast<int>(c));
  }
  bool has(Hand h, Control c) const { return bits & bit(h, c); }
  void set(Hand h, Control c, bool on) { bits = on ? bits | bit(h, c) : bits & ~bit(h, c); }
  bool empty() const { return bits == 0; }
  bool operator==(const ControlSet&) const = default;
};

/// What changed since the previous poll of the same backend (OpenXR's changedSinceLastSync, as
/// edges): a control pressed and released between two frames is down in exactly one poll, so
/// it is pressed once and released once (InputBackend::poll).
struct ActionEdges {
  ControlSet down;      //!< down in this poll
  ControlSet pressed;   //!< down now, up in the previous poll
  ControlSet released;  //!< up now, down in the previous poll
  bool is_down(Hand h, Control c) const { return down.has(h, c); }
  bool was_pressed(Hand h, Control c) const { return pressed.has(h, c); }
  bool was_released(Hand h, Control c) const { return released.has(h, c); }
};

struct HandState {
  bool tracked = false;
  Pose aim;   //!< ray origin and direction (-z of the pose)
  Pose grip;  //!< where the hand holds the controller; equals aim in the vdfx backends
  double trigger = 0.0;
  double squeeze = 0.0;
  glm::dvec2 thumbstick{0.0, 0.0};  //!< +x right, +y up
  bool primary = false;             //!< a (right) / x (left)
  bool secondary = false;           //!< b (right) / y (left)
  bool menu = false;                //!< left hand only, as on OpenXR's simple profiles
  bool thumbstick_click = false;
};

struct InputState {
  std::int64_t t_ns = 0;  //!< the time this snapshot is for
  bool head_tracked = false;
  Pose head;  //!< VIEW in LOCAL
  HandState left;
  HandState right;
  /// Edges since the backend's previous poll (filled by InputBackend::poll; a recording stores
  /// the levels, and replay derives the same edges from them).
  ActionEdges edges;

  HandState& hand(Hand h) { return h == Hand::Left ? left : right; }
  const HandState& hand(Hand h) const { return h == Hand::Left ? left : right; }
};

/// The standing eye height the backends use for the head when nothing else says (metres).
inline constexpr double kDefaultEyeHeight = 1.6;

/// The controls down in `s`, given those down in the state before (the hysteresis of analog
/// values: between the thresholds a control keeps its previous state). Untracked hands have
/// nothing down.
ControlSet controls_down(const InputState& s, ControlSet before = {});
/// Edges between two polls: `before` is the previous poll's ActionEdges::down.
ActionEdges action_edges(const InputState& now, ControlSet before);

/// xrSyncActions in small: stamps each state of a sequence with its edges since the one before.
/// InputBackend::poll runs every poll through one; tests that build states by hand use their own.
class ActionSync {
 public:
  InputState sync(InputState s) {
    s.edges = action_edges(s, down_);
    down_ = s.edges.down;
    return s;
  }

 private:
  ControlSet down_;
};

/// Nothing tracked, nothing pressed, head at (0, eye height, 0) looking down -z.
InputState neutral_input_state(std::int64_t t_ns);

using ActionValue = std::variant<bool, double, glm::dvec2, Pose>;

/// The value at an action path, or nullopt for an unknown path.
std::optional<ActionValue> get_action(const InputState& state, std::string_view path);

/// Every path get_action knows, in documentation order.
const std::vector<std::string>& action_paths();

}  // namespace vdfx::xr
