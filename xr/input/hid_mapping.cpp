/// @file
/// @brief The default HID mapping: gamepad and SpaceMouse states to head and hand actions.
#include "xr/input/hid_mapping.h"

#include <algorithm>
#include <cmath>

#include "effects/coords.h"

namespace vdfx::xr {

namespace {

using effects::kDegToRad;
constexpr double kMaxPitchDeg = 89.0;

// Fixed hand offsets in the head frame (metres) for hands no device positions.
const glm::dvec3 kLeftHandOffset{-0.2, -0.3, -0.3};

double axis_deadzone(double v, double dz) {
  if (std::abs(v) < dz) return 0.0;
  return std::copysign((std::abs(v) - dz) / (1.0 - dz), v);
}

// SpaceMouse axes (x right, y towards the user, z down) in OpenXR axes (+x right, +y up, -z
// forward): (x, y, z) -> (x, -z, y), a proper rotation, so it maps rotation vectors as well.
glm::dvec3 spacemouse_to_openxr(const std::array<double, 3>& v, double dz) {
  return {axis_deadzone(v[0], dz), -axis_deadzone(v[2], dz), axis_deadzone(v[1], dz)};
}

glm::dquat rotation_from_vector(const glm::dvec3& w) {
  const double angle = glm::length(w);
  if (angle < 1e-12) return {1.0, 0.0, 0.0, 0.0};
  return glm::angleAxis(angle, w / angle);
}

}  // namespace

glm::dvec2 apply_deadzone(glm::dvec2 v, double deadzone) {
  const double m = glm::length(v);
  if (m < deadzone || m == 0.0) return {0.0, 0.0};
  const double scaled = std::min(1.0, (m - deadzone) / (1.0 - deadzone));
  return v * (scaled / m);
}

HidInputMapper::HidInputMapper(HidMappingConfig config) : config_(config) {
  spacemouse_hand_.position = config_.head_position + glm::dvec3(0.2, -0.3, -0.3);
}

void HidInputMapper::on_descriptor(const std::string& device, std::span<const std::uint8_t> d) {
  descriptors_[device].assign(d.begin(), d.end());
  parsers_.erase(device);  // rebuilt with the new descriptor on the next report
}

HidReportParser* HidInputMapper::parser_for(const std::string& device) {
  auto it = parsers_.find(device);
  if (it != parsers_.end()) return &it->second;
  const auto ids = parse_device_id(device);
  HidDeviceKind kind = ids ? known_device_kind(ids->first, ids->second) : HidDeviceKind::Unknown;
  const auto desc = descriptors_.find(device);
  if (kind == HidDeviceKind::Unknown && desc != descriptors_.end() && !desc->second.empty()) {
    kind = HidDeviceKind::GenericGamepad;
  }
  if (kind == HidDeviceKind::Unknown) return nullptr;
  std::span<const std::uint8_t> bytes;
  if (desc != descriptors_.end()) bytes = desc->second;
  return &parsers_.emplace(device, HidReportParser(kind, bytes)).first->second;
}

bool HidInputMapper::knows(const std::string& device) const {
  if (parsers_.count(device)) return true;
  const auto ids = parse_device_id(device);
  if (ids && known_device_kind(ids->first, ids->second) != HidDeviceKind::Unknown) return true;
  const auto d = descriptors_.find(device);
  return d != descriptors_.end() && !d->second.empty();
}

bool HidInputMapper::on_report(std::int64_t t_ns, const std::string& device,
                               std::span<const std::uint8_t> report) {
  if (report.empty()) {
    on_disconnect(t_ns, device);
    return true;
  }
  advance(t_ns);  // the old state held until now
  HidReportParser* p = parser_for(device);
  if (!p || !p->apply(report)) return false;
  if (p->is_spacemouse())
    spacemouse_ = p->spacemouse();
  else
    pad_ = p->gamepad();
  return true;
}

void HidInputMapper::on_disconnect(std::int64_t t_ns, const std::string& device) {
  advance(t_ns);
  auto it = parsers_.find(device);
  if (it == parsers_.end()) return;
  if (it->second.is_spacemouse())
    spacemouse_ = {};
  else
    pad_ = {};
  it->second.reset();
}

void HidInputMapper::advance(std::int64_t t_ns) {
  if (!last_t_ || t_ns <= *last_t_) {
    last_t_ = t_ns;
    return;
  }
  const double dt = static_cast<double>(t_ns - *last_t_) * 1e-9;
  last_t_ = t_ns;

  if (config_.left_stick == LeftStickRole::HeadLook) {
    const glm::dvec2 look =
        apply_deadzone({pad_.left_stick[0], pad_.left_stick[1]}, config_.stick_deadzone);
    const double yaw =
        -look.x * config_.look_rate_deg_s * dt * kDegToRad;  // stick right: turn right
    const double pitch = look.y * config_.look_rate_deg_s * dt * kDegToRad;
    // Yaw about the world up axis, pitch about the head's own x axis.
    head_q_ = glm::normalize(glm::angleAxis(yaw, glm::dvec3(0, 1, 0)) * head_q_);
    // Clamp the resulting altitude rather than the step, so long steps stop at the limit.
    const double alt = std::asin(std::clamp((head_q_ * glm::dvec3(0, 0, -1)).y, -1.0, 1.0));
    const double limit = kMaxPitchDeg * kDegToRad;
    const double step = std::clamp(alt + pitch, -limit, limit) - alt;
    head_q_ = glm::normalize(head_q_ * glm::angleAxis(step, glm::dvec3(1, 0, 0)));
  }

  const glm::dvec3 omega = spacemouse_to_openxr(spacemouse_.rotation, config_.spacemouse_deadzone) *
                           (config_.spacemouse_rate_deg_s * kDegToRad);
  const glm::dvec3 velocity =
      spacemouse_to_openxr(spacemouse_.translation, config_.spacemouse_deadzone) *
      config_.spacemouse_speed_m_s;
  if (config_.spacemouse == SpaceMouseTarget::Head) {
    // Rates are about the head's own axes: twist the cap right and the view turns right.
    head_q_ = glm::normalize(head_q_ * rotation_from_vector(omega * dt));
  } else {
    spacemouse_hand_.orientation =
        glm::normalize(spacemouse_hand_.orientation * rotation_from_vector(omega * dt));
    spacemouse_hand_.position +=
        head_q_ * velocity * dt;  // pushes move the hand in the view's frame
  }
}

InputState HidInputMapper::state(std::int64_t t_ns) {
  advance(t_ns);
  InputState s;
  s.t_ns = t_ns;
  s.head_tracked = true;
  s.head.orientation = head_q_;
  s.head.position = config_.head_position;

  // Right hand: aims where the view looks (the ray through the view centre), unless steered.
  HandState& r = s.right;
  r.tracked = true;
  r.aim = s.head;
  r.trigger = std::max(pad_.right_trigger, (spacemouse_.buttons & 1u) ? 1.0 : 0.0);
  r.squeeze = pad_.pressed(PadButton::R1) ? 1.0 : 0.0;
  r.thumbstick = apply_deadzone({pad_.right_stick[0], pad_.right_stick[1]}, config_.stick_deadzone);
  r.primary = pad_.pressed(PadButton::South);
  r.secondary = pad_.pressed(PadButton::East);
  r.thumbstick_click = pad_.pressed(PadButton::R3);

  HandState& l = s.left;
  l.tracked = true;
  l.aim.orientation = head_q_;
  l.aim.position = config_.head_position + head_q_ * kLeftHandOffset;
  l.trigger = pad_.left_trigger;
  l.squeeze = pad_.pressed(PadButton::L1) ? 1.0 : 0.0;
  if (config_.left_stick == LeftStickRole::LeftThumbstick) {
    l.thumbstick = apply_deadzone({pad_.left_stick[0], pad_.left_stick[1]}, config_.stick_deadzone);
  } else {
    l.thumbstick = {(pad_.pressed(PadButton::DpadRight) ? 1.0 : 0.0) -
                        (pad_.pressed(PadButton::DpadLeft) ? 1.0 : 0.0),
                    (pad_.pressed(PadButton::DpadUp) ? 1.0 : 0.0) -
                        (pad_.pressed(PadButton::DpadDown) ? 1.0 : 0.0)};
  }
  l.primary = pad_.pressed(PadButton::West);
  l.secondary = pad_.pressed(PadButton::North);
  l.menu = pad_.pressed(PadButton::Start) || (spacemouse_.buttons & 2u);
  l.thumbstick_click = pad_.pressed(PadButton::L3);

  if (config_.spacemouse == SpaceMouseTarget::RightHand) r.aim = spacemouse_hand_;
  if (config_.spacemouse == SpaceMouseTarget::LeftHand) l.aim = spacemouse_hand_;
  r.grip = r.aim;
  l.grip = l.aim;
  return s;
}

}  // namespace vdfx::xr
