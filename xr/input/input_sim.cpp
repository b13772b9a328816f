/// @file
/// @brief The sim backend: a desktop stand-in for a headset and two controllers.
///
/// Right-button drag turns the head (dragging the image like a desktop 360 player, or a game's
/// mouselook: SimConfig::look, the key I switches); the main hand's aim ray goes through the
/// cursor (its origin is the eye, so the ray hits exactly what is under the cursor), except while
/// Space alone holds the trigger: Space is the keyboard's "place at the centre", so the ray then
/// points at the view's centre wherever the cursor rests (a click still presses what is under
/// the cursor); keys press buttons and move sticks. State is a function of the events alone:
/// poll(t) applies the queued events and stamps t. No lost taps: a poll applies the queued events
/// in order until one would change a control that an earlier event of the same poll already
/// changed; that one and the rest wait for the next poll. So a key tapped between two frames is
/// down in exactly one poll (and a double tap in two), and a recording of the polled states replays
/// it as a tap.
#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <iomanip>
#include <set>
#include <sstream>

#include "effects/coords.h"
#include "xr/input/input_backend.h"

namespace vdfx::xr {

namespace {

using effects::kDegToRad;
using effects::kRadToDeg;
constexpr double kMaxPitchDeg = 89.0;
const glm::dvec3 kOffHandOffset{0.2, -0.3, -0.3};  // head frame, mirrored in x for the left hand

/// Switches SimConfig::look (no control of its own: the head pose it changes is what is recorded).
constexpr Key kLookToggleKey = Key::I;
/// The key that is the keyboard's "place at the centre" (the main trigger, aimed at the centre).
constexpr Key kCentreKey = Key::Space;

enum class Role { Main, Off, Left };  // Left: the control exists on the left hand only (menu)

struct KeyBinding {
  Key key;
  Role role;
  Control control;
};

// The binding table: the sim applies it and sim_bindings_text prints it.
constexpr std::array<KeyBinding, 22> kKeyBindings{{
    {Key::Space, Role::Main, Control::Trigger},
    {Key::G, Role::Main, Control::Squeeze},
    {Key::J, Role::Main, Control::Primary},
    {Key::K, Role::Main, Control::Secondary},
    {Key::L, Role::Main, Control::StickClick},
    {Key::Up, Role::Main, Control::StickUp},
    {Key::Down, Role::Main, Control::StickDown},
    {Key::Left, Role::Main, Control::StickLeft},
    {Key::Right, Role::Main, Control::StickRight},
    {Key::E, Role::Off, Control::Trigger},
    {Key::Q, Role::Off, Control::Squeeze},
    {Key::LeftShift, Role::Off, Control::Squeeze},  // held while dragging: fine adjustment
    {Key::RightShift, Role::Off, Control::Squeeze},
    {Key::X, Role::Off, Control::Primary},
    {Key::Y, Role::Off, Control::Secondary},
    {Key::C, Role::Off, Control::StickClick},
    {Key::W, Role::Off, Control::StickUp},
    {Key::S, Role::Off, Control::StickDown},
    {Key::A, Role::Off, Control::StickLeft},
    {Key::D, Role::Off, Control::StickRight},
    {Key::M, Role::Left, Control::Menu},
    {Key::Tab, Role::Left, Control::Menu},
}};

Hand hand_of(Role role, bool left_handed) {
  if (role == Role::Left) return Hand::Left;
  const bool main = role == Role::Main;
  return (main != left_handed) ? Hand::Right : Hand::Left;
}

std::string control_path(Hand hand, Control c) {
  const bool left = hand == Hand::Left;
  const std::string in = std::string("/user/hand/") + (left ? "left" : "right") + "/input/";
  switch (c) {
    case Control::Trigger: return in + "trigger/value";
    case Control::Squeeze: return in + "squeeze/value";
    case Control::Primary: return in + (left ? "x/click" : "a/click");
    case Control::Secondary: return in + (left ? "y/click" : "b/click");
    case Control::Menu: return in + "menu/click";
    case Control::StickClick: return in + "thumbstick/click";
    case Control::StickUp: return in + "thumbstick/y = +1";
    case Control::StickDown: return in + "thumbstick/y = -1";
    case Control::StickLeft: return in + "thumbstick/x = -1";
    case Control::StickRight: return in + "thumbstick/x = +1";
  }
  return in;
}

class SimInputBackend final : public InputBackend {
 public:
  explicit SimInputBackend(const SimConfig& config) : config_(config) {
    mouse_x_ = config_.window_width * 0.5;
    mouse_y_ = config_.window_height * 0.5;
  }

  void push_event(const DesktopEvent& event) override { queue_.push_back(event); }

  InputState poll_state(std::int64_t t_ns) override {
    ControlSet down = controls_down(state(t_ns), last_down_);
    std::uint32_t changed = 0;  // controls an event of this poll changed
    while (!queue_.empty()) {
      // Only key and left-button events change controls, and only through these two.
      const std::set<Key> keys = keys_;
      const bool left = left_button_;
      std::visit([this](const auto& e) { apply(e); }, queue_.front());
      const ControlSet after = controls_down(state(t_ns), down);
      const std::uint32_t diff = after.bits ^ down.bits;
      if (diff & changed) {  // a second change of one control: it waits for the next poll
        keys_ = keys;
        left_button_ = left;
        break;
      }
      changed |= diff;
      down = after;
      queue_.pop_front();
    }
    last_down_ = down;
    return state(t_ns);
  }

 private:
  void apply(const KeyEvent& e) {
    if (e.key == kLookToggleKey && e.pressed && !keys_.count(e.key))
      config_.look = config_.look == LookMode::Drag ? LookMode::Mouselook : LookMode::Drag;
    if (e.pressed)
      keys_.insert(e.key);
    else
      keys_.erase(e.key);
  }
  void apply(const MouseButtonEvent& e) {
    // A press over no drawn view (a letterbox bar) presses nothing; a release always releases.
    if (e.button == MouseButton::Left) left_button_ = e.pressed && over_view_;
    if (e.button == MouseButton::Right) dragging_ = e.pressed;
  }
  void apply(const MouseMoveEvent& e) {
    if (dragging_) {
      // Drag: the image follows the mouse (drag right turns left, drag down looks up); mouselook:
      // a first-person camera (drag right turns right, drag down looks down).
      const double sign = config_.look == LookMode::Drag ? -1.0 : 1.0;
      const double rate = look_deg_per_px_of(config_);
      azimuth_deg_ += sign * (e.x - mouse_x_) * rate;
      azimuth_deg_ = std::remainder(azimuth_deg_, 360.0);
      altitude_deg_ =
          std::clamp(altitude_deg_ - sign * (e.y - mouse_y_) * rate, -kMaxPitchDeg, kMaxPitchDeg);
    }
    mouse_x_ = e.x;
    mouse_y_ = e.y;
    over_view_ = e.over_view;
    if (e.ray)
      ray_ = *e.ray;
    else
      ray_.reset();
  }
  void apply(const ViewGeometryEvent& e) {
    if (e.width_px > 0 && e.height_px > 0) {
      config_.window_width = e.width_px;
      config_.window_height = e.height_px;
    }
    if (e.hfov_deg > 0.0 && e.hfov_deg < 180.0) config_.hfov_deg = e.hfov_deg;
    ray_.reset();  // the mirror changed: the next move brings the ray through the new geometry
  }

  bool active(Hand hand, Control c) const {
    for (const KeyBinding& b : kKeyBindings) {
      if (b.control == c && hand_of(b.role, config_.left_handed) == hand && keys_.count(b.key))
        return true;
    }
    return false;
  }

  // The ray through the cursor, in the view frame: the mirror's own (MouseMoveEvent::ray), else
  // a pinhole with the configured horizontal FOV, the vertical one from the window's aspect.
  ViewRay cursor_ray() const {
    if (ray_) return *ray_;
    const double w = std::max(1, config_.window_width), h = std::max(1, config_.window_height);
    const double tan_h = std::tan(0.5 * config_.hfov_deg * kDegToRad);
    const double tan_v = tan_h * h / w;
    return {glm::dvec3(0.0), glm::normalize(glm::dvec3((2.0 * mouse_x_ / w - 1.0) * tan_h,
                                                       (1.0 - 2.0 * mouse_y_ / h) * tan_v, -1.0))};
  }
  static glm::dquat rotation_towards(const glm::dvec3& dir) {
    return look_rotation(std::atan2(dir.x, -dir.z) * kRadToDeg,
                         std::asin(std::clamp(dir.y, -1.0, 1.0)) * kRadToDeg);
  }

  void fill_hand(HandState& hs, Hand hand) const {
    hs.tracked = true;
    hs.trigger = active(hand, Control::Trigger) ? 1.0 : 0.0;
    hs.squeeze = active(hand, Control::Squeeze) ? 1.0 : 0.0;
    hs.primary = active(hand, Control::Primary);
    hs.secondary = active(hand, Control::Secondary);
    hs.menu = hand == Hand::Left && active(hand, Control::Menu);
    hs.thumbstick_click = active(hand, Control::StickClick);
    glm::dvec2 stick{(active(hand, Control::StickRight) ? 1.0 : 0.0) -
                         (active(hand, Control::StickLeft) ? 1.0 : 0.0),
                     (active(hand, Control::StickUp) ? 1.0 : 0.0) -
                         (active(hand, Control::StickDown) ? 1.0 : 0.0)};
    if (glm::length(stick) > 1.0)
      stick = glm::normalize(stick);  // diagonals stay on the unit circle
    hs.thumbstick = stick;
  }

  InputState state(std::int64_t t_ns) const {
    InputState s;
    s.t_ns = t_ns;
    s.head_tracked = true;
    s.head.orientation = look_rotation(azimuth_deg_, altitude_deg_);
    s.head.position = config_.head_position;
    const Hand main = config_.left_handed ? Hand::Left : Hand::Right;
    const Hand off = config_.left_handed ? Hand::Right : Hand::Left;
    fill_hand(s.left, Hand::Left);
    fill_hand(s.right, Hand::Right);
    HandState& m = s.hand(main);
    // Space without the mouse button: the trigger aimed at the view's centre, so it places a
    // keyframe there even with the cursor resting on a panel.
    const bool centre = keys_.count(kCentreKey) && !left_button_;
    const ViewRay ray =
        centre ? ViewRay{glm::dvec3(0.0), glm::dvec3(0.0, 0.0, -1.0)} : cursor_ray();
    m.aim.orientation = glm::normalize(s.head.orientation * rotation_towards(ray.direction));
    m.aim.position = s.head.position + s.head.orientation * ray.origin;
    if (left_button_) m.trigger = 1.0;
    HandState& o = s.hand(off);
    glm::dvec3 offset = kOffHandOffset;
    if (off == Hand::Left) offset.x = -offset.x;
    o.aim.orientation = s.head.orientation;
    o.aim.position = s.head.position + s.head.orientation * offset;
    s.left.grip = s.left.aim;
    s.right.grip = s.right.aim;
    return s;
  }

  SimConfig config_;
  std::deque<DesktopEvent> queue_;
  ControlSet last_down_;
  std::set<Key> keys_;
  bool left_button_ = false;
  bool dragging_ = false;
  bool over_view_ = true;
  std::optional<ViewRay> ray_;
  double mouse_x_ = 0.0, mouse_y_ = 0.0;
  double azimuth_deg_ = 0.0, altitude_deg_ = 0.0;
};

}  // namespace

std::string_view look_mode_name(LookMode mode) {
  return mode == LookMode::Drag ? "drag" : "mouselook";
}

std::optional<LookMode> parse_look_mode(std::string_view name) {
  if (name == "drag") return LookMode::Drag;
  if (name == "mouselook") return LookMode::Mouselook;
  return std::nullopt;
}

double look_deg_per_px_of(const SimConfig& config) {
  if (config.look_deg_per_px > 0.0) return config.look_deg_per_px;
  const double tan_h = std::tan(0.5 * config.hfov_deg * kDegToRad);
  return std::atan(2.0 * tan_h / std::max(1, config.window_width)) * kRadToDeg;
}

std::unique_ptr<InputBackend> create_sim_backend(const SimConfig& config) {
  return std::make_unique<SimInputBackend>(config);
}

std::string sim_bindings_text(const SimConfig& config) {
  const Hand main = config.left_handed ? Hand::Left : Hand::Right;
  const std::string main_name = main == Hand::Left ? "left" : "right";
  std::vector<std::pair<std::string, std::string>> rows;
  std::ostringstream look;
  look << "turn the head (/user/head/pose), ";
  if (config.look_deg_per_px > 0.0)
    look << config.look_deg_per_px << " deg per pixel, ";
  else
    look << "following the cursor (" << std::fixed << std::setprecision(3)
         << look_deg_per_px_of(config) << std::defaultfloat << " deg per pixel at "
         << config.window_width << " px and " << config.hfov_deg << " deg), ";
  look << (config.look == LookMode::Drag ? "drag: as 360 players (left turns right)"
                                         : "mouselook: as games (left turns left)");
  rows.emplace_back("right mouse button drag", look.str());
  rows.emplace_back(std::string(key_name(kLookToggleKey)),
                    "switch the right-button drag between drag and mouselook");
  rows.emplace_back("mouse position",
                    "/user/hand/" + main_name + "/input/aim/pose (ray through the cursor)");
  rows.emplace_back("left mouse button", control_path(main, Control::Trigger));
  for (const KeyBinding& b : kKeyBindings) {
    rows.emplace_back(
        std::string(key_name(b.key)),
        control_path(hand_of(b.role, config.left_handed), b.control) +
            (b.key == kCentreKey ? ", aimed at the view's centre (not the cursor)" : ""));
  }
  std::ostringstream out;
  for (const auto& [input, action] : rows) {
    std::string left = input;
    left.resize(std::max<std::size_t>(left.size() + 2, 26), ' ');
    out << "  " << left << action << "\n";
  }
  return out.str();
}

std::vector<std::string> sim_inputs_of(Hand hand, Control control, const SimConfig& config,
                                       bool pointing) {
  std::vector<std::string> out;
  const Hand main = config.left_handed ? Hand::Left : Hand::Right;
  if (hand == main && control == Control::Trigger) out.emplace_back("left mouse button");
  for (const KeyBinding& b : kKeyBindings)
    if (b.control == control && hand_of(b.role, config.left_handed) == hand &&
        !(pointing && b.key == kCentreKey))
      out.emplace_back(key_name(b.key));
  return out;
}

}  // namespace vdfx::xr
