/// @file
/// @brief The interaction profile tables (component paths from the OpenXR 1.0 specification,
/// section 6.4) and the script values that drive them.
#include "tests/openxr_runtime/interaction_profiles.h"

#include <cctype>

namespace vdfx::test_runtime {
namespace {

using T = ComponentType;
using S = Source;

Component both(const char* subpath, T type, S source) {
  return {subpath, type, source, true, true};
}
Component left_only(const char* subpath, T type, S source) {
  return {subpath, type, source, true, false};
}
Component right_only(const char* subpath, T type, S source) {
  return {subpath, type, source, false, true};
}

/// Poses and haptics every profile has.
void add_common(std::vector<Component>& c) {
  c.push_back(both("/input/grip/pose", T::Pose, S::Aim));
  c.push_back(both("/input/aim/pose", T::Pose, S::Aim));
  c.push_back(both("/output/haptic", T::Haptic, S::Haptic));
}

/// A 2D control: the vector, its axes, and the click and touch the device has.
void add_2d(std::vector<Component>& c, const std::string& name, bool driven, bool click, bool touch,
            bool force = false) {
  const std::string base = "/input/" + name;
  c.push_back({base, T::Vector2, driven ? S::Stick : S::Unpressed, true, true});
  c.push_back({base + "/x", T::Float, driven ? S::StickX : S::Unpressed, true, true});
  c.push_back({base + "/y", T::Float, driven ? S::StickY : S::Unpressed, true, true});
  if (click)
    c.push_back({base + "/click", T::Boolean, driven ? S::StickClick : S::Unpressed, true, true});
  if (touch)
    c.push_back({base + "/touch", T::Boolean, driven ? S::StickTouch : S::Unpressed, true, true});
  if (force) c.push_back({base + "/force", T::Float, S::Unpressed, true, true});
}

InteractionProfile simple() {
  InteractionProfile p{
      "/interaction_profiles/khr/simple_controller", "Khronos Simple Controller", {}};
  p.components.push_back(both("/input/select/click", T::Boolean, S::TriggerClick));
  p.components.push_back(both("/input/menu/click", T::Boolean, S::Menu));
  add_common(p.components);
  return p;
}

InteractionProfile touch() {
  InteractionProfile p{
      "/interaction_profiles/oculus/touch_controller", "Oculus Touch Controller", {}};
  auto& c = p.components;
  c.push_back(left_only("/input/x/click", T::Boolean, S::Primary));
  c.push_back(left_only("/input/x/touch", T::Boolean, S::Primary));
  c.push_back(left_only("/input/y/click", T::Boolean, S::Secondary));
  c.push_back(left_only("/input/y/touch", T::Boolean, S::Secondary));
  c.push_back(left_only("/input/menu/click", T::Boolean, S::Menu));
  c.push_back(right_only("/input/a/click", T::Boolean, S::Primary));
  c.push_back(right_only("/input/a/touch", T::Boolean, S::Primary));
  c.push_back(right_only("/input/b/click", T::Boolean, S::Secondary));
  c.push_back(right_only("/input/b/touch", T::Boolean, S::Secondary));
  c.push_back(right_only("/input/system/click", T::Boolean, S::Unpressed));
  c.push_back(both("/input/squeeze/value", T::Float, S::Squeeze));
  c.push_back(both("/input/trigger/value", T::Float, S::Trigger));
  c.push_back(both("/input/trigger/touch", T::Boolean, S::TriggerTouch));
  add_2d(c, "thumbstick", true, true, true);
  c.push_back(both("/input/thumbrest/touch", T::Boolean, S::Unpressed));
  add_common(c);
  return p;
}

InteractionProfile index() {
  InteractionProfile p{
      "/interaction_profiles/valve/index_controller", "Valve Index Controller", {}};
  auto& c = p.components;
  c.push_back(both("/input/system/click", T::Boolean, S::Unpressed));
  c.push_back(both("/input/system/touch", T::Boolean, S::Unpressed));
  c.push_back(both("/input/a/click", T::Boolean, S::Primary));
  c.push_back(both("/input/a/touch", T::Boolean, S::Primary));
  c.push_back(both("/input/b/click", T::Boolean, S::Secondary));
  c.push_back(both("/input/b/touch", T::Boolean, S::Secondary));
  c.push_back(both("/input/squeeze/value", T::Float, S::Squeeze));
  c.push_back(both("/input/squeeze/force", T::Float, S::Squeeze));
  c.push_back(both("/input/trigger/click", T::Boolean, S::TriggerClick));
  c.push_back(both("/input/trigger/value", T::Float, S::Trigger));
  c.push_back(both("/input/trigger/touch", T::Boolean, S::TriggerTouch));
  add_2d(c, "thumbstick", true, true, true);
  add_2d(c, "trackpad", false, false, true, true);
  add_common(c);
  return p;
}

InteractionProfile vive() {
  InteractionProfile p{"/interaction_profiles/htc/vive_controller", "HTC Vive Controller", {}};
  auto& c = p.components;
  c.push_back(both("/input/system/click", T::Boolean, S::Unpressed));
  c.push_back(both("/input/squeeze/click", T::Boolean, S::SqueezeClick));
  c.push_back(both("/input/menu/click", T::Boolean, S::Menu));
  c.push_back(both("/input/trigger/click", T::Boolean, S::TriggerClick));
  c.push_back(both("/input/trigger/value", T::Float, S::Trigger));
  add_2d(c, "trackpad", true, true, true);  // the script's stick drives the Vive's trackpad
  add_common(c);
  return p;
}

InteractionProfile wmr() {
  InteractionProfile p{"/interaction_profiles/microsoft/motion_controller",
                       "Microsoft Mixed Reality Motion Controller",
                       {}};
  auto& c = p.components;
  c.push_back(both("/input/menu/click", T::Boolean, S::Menu));
  c.push_back(both("/input/squeeze/click", T::Boolean, S::SqueezeClick));
  c.push_back(both("/input/trigger/value", T::Float, S::Trigger));
  add_2d(c, "thumbstick", true, true, false);
  add_2d(c, "trackpad", false, true, true);
  add_common(c);
  return p;
}

const Component* find_component(const InteractionProfile& p, const std::string& subpath, int hand) {
  for (const Component& c : p.components) {
    if (c.subpath == subpath && (hand == 0 ? c.left : c.right)) return &c;
  }
  return nullptr;
}

bool drives(ComponentType component, XrActionType action) {
  switch (action) {
    case XR_ACTION_TYPE_BOOLEAN_INPUT:
    case XR_ACTION_TYPE_FLOAT_INPUT: return component == T::Boolean || component == T::Float;
    case XR_ACTION_TYPE_VECTOR2F_INPUT: return component == T::Vector2;
    case XR_ACTION_TYPE_POSE_INPUT: return component == T::Pose;
    case XR_ACTION_TYPE_VIBRATION_OUTPUT: return component == T::Haptic;
    default: return false;
  }
}

}  // namespace

const std::vector<InteractionProfile>& interaction_profiles() {
  static const std::vector<InteractionProfile> profiles{simple(), touch(), index(), vive(), wmr()};
  return profiles;
}

const InteractionProfile* find_interaction_profile(const std::string& path) {
  for (const auto& p : interaction_profiles()) {
    if (p.path == path) return &p;
  }
  return nullptr;
}

std::optional<ResolvedBinding> resolve_binding(const InteractionProfile& profile,
                                               const std::string& path, XrActionType type) {
  int hand = -1;
  std::string rest;
  for (int h = 0; h < 2; ++h) {
    const std::string user = h == 0 ? "/user/hand/left" : "/user/hand/right";
    if (path.compare(0, user.size(), user) == 0 && path.size() > user.size() &&
        path[user.size()] == '/') {
      hand = h;
      rest = path.substr(user.size());
    }
  }
  if (hand < 0) return std::nullopt;
  if (const Component* c = find_component(profile, rest, hand)) {
    if (drives(c->type, type)) return ResolvedBinding{hand, c};
    return std::nullopt;
  }
  // An identifier without its component (spec 6.3.2): the runtime picks the component the
  // action's type reads.
  std::vector<std::string> tries;
  switch (type) {
    case XR_ACTION_TYPE_BOOLEAN_INPUT: tries = {"/click", "/value", "/touch"}; break;
    case XR_ACTION_TYPE_FLOAT_INPUT: tries = {"/value", "/click", "/force"}; break;
    case XR_ACTION_TYPE_POSE_INPUT: tries = {"/pose"}; break;
    default: break;
  }
  for (const std::string& suffix : tries) {
    if (const Component* c = find_component(profile, rest + suffix, hand)) {
      if (drives(c->type, type)) return ResolvedBinding{hand, c};
    }
  }
  return std::nullopt;
}

ComponentValue component_value(const Component& c, const ScriptHand& h) {
  ComponentValue v;
  auto set_float = [&](double f) {
    v.f = static_cast<float>(f);
    v.b = f > 0.5;
  };
  auto set_bool = [&](bool b) {
    v.b = b;
    v.f = b ? 1.0f : 0.0f;
  };
  switch (c.source) {
    case S::Unpressed: break;
    case S::Trigger: set_float(h.trigger); break;
    case S::TriggerClick: set_bool(h.trigger > 0.5); break;
    case S::TriggerTouch: set_bool(h.trigger > 0.0); break;
    case S::Squeeze: set_float(h.squeeze); break;
    case S::SqueezeClick: set_bool(h.squeeze > 0.5); break;
    case S::Stick: v.v = {static_cast<float>(h.stick[0]), static_cast<float>(h.stick[1])}; break;
    case S::StickX: set_float(h.stick[0]); break;
    case S::StickY: set_float(h.stick[1]); break;
    case S::StickClick: set_bool(h.stick_click); break;
    case S::StickTouch: set_bool(h.stick_click || h.stick[0] != 0.0 || h.stick[1] != 0.0); break;
    case S::Primary: set_bool(h.primary); break;
    case S::Secondary: set_bool(h.secondary); break;
    case S::Menu: set_bool(h.menu); break;
    case S::Aim:
    case S::Haptic: break;
  }
  return v;
}

std::string localized_component_name(const Component& c) {
  // "/input/trigger/value" -> "Trigger Value"
  std::string out;
  std::string rest = c.subpath;
  if (rest.rfind("/input/", 0) == 0) rest = rest.substr(7);
  if (rest.rfind("/output/", 0) == 0) rest = rest.substr(8);
  bool start = true;
  for (const char ch : rest) {
    if (ch == '/') {
      out += ' ';
      start = true;
    } else {
      out += start ? static_cast<char>(std::toupper(static_cast<unsigned char>(ch))) : ch;
      start = false;
    }
  }
  return out;
}

}  // namespace vdfx::test_runtime
