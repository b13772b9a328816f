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
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace vdfx::xr {

struct Pose {
  glm::dquat q{1.0, 0.0, 0.0, 0.0};  //!< orientation (w, x, y, z)
  glm::dvec3 p{0.0, 0.0, 0.0};       //!< position, metres
};

enum class Hand { Left = 0, Right = 1 };

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

  HandState& hand(Hand h) { return h == Hand::Left ? left : right; }
  const HandState& hand(Hand h) const { return h == Hand::Left ? left : right; }
};

/// The standing eye height the backends use for the head when nothing else says (metres).
inline constexpr double kDefaultEyeHeight = 1.6;

/// Nothing tracked, nothing pressed, head at (0, eye height, 0) looking down -z.
InputState neutral_input_state(std::int64_t t_ns);

/// The forward direction (-z) of a pose, unit length.
glm::dvec3 forward(const Pose& pose);

/// Orientation looking at azimuth/altitude (degrees, contract conventions: azimuth positive to the
/// right, altitude positive up), no roll.
glm::dquat look_rotation(double azimuth_deg, double altitude_deg);

using ActionValue = std::variant<bool, double, glm::dvec2, Pose>;

/// The value at an action path, or nullopt for an unknown path.
std::optional<ActionValue> get_action(const InputState& state, std::string_view path);

/// Every path get_action knows, in documentation order.
const std::vector<std::string>& action_paths();

}  // namespace vdfx::xr
