/// @file
/// @brief The action set and the suggested bindings as tables.
#include "xr/openxr/openxr_bindings.h"

#include <sstream>

namespace vdfx::xr {
namespace {

using A = OpenXrAction;
using T = OpenXrActionType;

constexpr std::array<OpenXrActionSpec, kOpenXrActionCount> kActions{{
    {A::Aim, "aim", "Aim (pointer ray)", T::Pose},
    {A::Trigger, "trigger", "Trigger (place a keyframe, press a widget)", T::Float},
    {A::Squeeze, "squeeze", "Squeeze (hold a keyframe)", T::Float},
    {A::Thumbstick, "thumbstick", "Thumbstick", T::Vector2},
    {A::ThumbstickClick, "thumbstick_click", "Thumbstick click", T::Boolean},
    {A::Primary, "primary", "A / X (delete, undo)", T::Boolean},
    {A::Secondary, "secondary", "B / Y (unaltered, redo)", T::Boolean},
    {A::Menu, "menu", "Menu", T::Boolean},
    {A::Haptic, "haptic", "Haptic pulse", T::Vibration},
}};

/// One row of a profile's table: the component under /user/hand/{left,right}/ for each hand
/// (empty: not bound on that hand).
struct Row {
  OpenXrAction action;
  const char* left;
  const char* right;
};

/// Rows every profile shares: the aim pose and the haptic output exist on all five.
void add_common(std::vector<Row>& rows) {
  rows.push_back({A::Aim, "input/aim/pose", "input/aim/pose"});
  rows.push_back({A::Haptic, "output/haptic", "output/haptic"});
}

/// The profiles. Where a controller lacks a control, the nearest one takes its place
/// (docs/openxr.md says which): the Vive's trackpad is the thumbstick, its menu button a/x.
std::vector<OpenXrProfileBindings> build() {
  struct Profile {
    const char* path;
    const char* name;
    std::vector<Row> rows;
  };
  std::vector<Profile> profiles = {
      {"khr/simple_controller",
       "Khronos simple controller",
       {{A::Trigger, "input/select/click", "input/select/click"},
        {A::Menu, "input/menu/click", ""},
        {A::Secondary, "", "input/menu/click"}}},
      {"oculus/touch_controller",
       "Oculus Touch",
       {{A::Trigger, "input/trigger/value", "input/trigger/value"},
        {A::Squeeze, "input/squeeze/value", "input/squeeze/value"},
        {A::Thumbstick, "input/thumbstick", "input/thumbstick"},
        {A::ThumbstickClick, "input/thumbstick/click", "input/thumbstick/click"},
        {A::Primary, "input/x/click", "input/a/click"},
        {A::Secondary, "input/y/click", "input/b/click"},
        {A::Menu, "input/menu/click", ""}}},
      {"valve/index_controller",
       "Valve Index",
       {{A::Trigger, "input/trigger/value", "input/trigger/value"},
        {A::Squeeze, "input/squeeze/value", "input/squeeze/value"},
        {A::Thumbstick, "input/thumbstick", "input/thumbstick"},
        {A::ThumbstickClick, "input/thumbstick/click", "input/thumbstick/click"},
        {A::Primary, "input/a/click", "input/a/click"},
        {A::Secondary, "input/b/click", "input/b/click"}}},
      {"htc/vive_controller",
       "HTC Vive",
       {{A::Trigger, "input/trigger/value", "input/trigger/value"},
        {A::Squeeze, "input/squeeze/click", "input/squeeze/click"},
        {A::Thumbstick, "input/trackpad", "input/trackpad"},
        {A::ThumbstickClick, "input/trackpad/click", "input/trackpad/click"},
        {A::Primary, "input/menu/click", "input/menu/click"}}},
      {"microsoft/motion_controller",
       "Windows Mixed Reality",
       {{A::Trigger, "input/trigger/value", "input/trigger/value"},
        {A::Squeeze, "input/squeeze/click", "input/squeeze/click"},
        {A::Thumbstick, "input/thumbstick", "input/thumbstick"},
        {A::ThumbstickClick, "input/thumbstick/click", "input/thumbstick/click"},
        {A::Primary, "input/trackpad/click", "input/trackpad/click"},
        {A::Secondary, "input/menu/click", "input/menu/click"}}},
  };
  std::vector<OpenXrProfileBindings> out;
  for (Profile& p : profiles) {
    add_common(p.rows);
    OpenXrProfileBindings b{std::string("/interaction_profiles/") + p.path, p.name, {}};
    for (const Row& r : p.rows) {
      for (const Hand h : {Hand::Left, Hand::Right}) {
        const std::string component = h == Hand::Left ? r.left : r.right;
        if (!component.empty())
          b.bindings.push_back({r.action, h, std::string(hand_path(h)) + "/" + component});
      }
    }
    out.push_back(std::move(b));
  }
  return out;
}

/// vdfx's action path of an action on a hand (docs/input.md), as the table's first column.
std::string vdfx_path(OpenXrAction a, Hand h) {
  const std::string base = std::string(hand_path(h)) + "/";
  const bool left = h == Hand::Left;
  switch (a) {
    case A::Aim: return base + "input/aim/pose";
    case A::Trigger: return base + "input/trigger/value";
    case A::Squeeze: return base + "input/squeeze/value";
    case A::Thumbstick: return base + "input/thumbstick";
    case A::ThumbstickClick: return base + "input/thumbstick/click";
    case A::Primary: return base + (left ? "input/x/click" : "input/a/click");
    case A::Secondary: return base + (left ? "input/y/click" : "input/b/click");
    case A::Menu: return base + "input/menu/click";
    case A::Haptic: return base + "output/haptic";
  }
  return base;
}

}  // namespace

const std::array<OpenXrActionSpec, kOpenXrActionCount>& openxr_actions() {
  return kActions;
}

const OpenXrActionSpec& openxr_action(OpenXrAction action) {
  return kActions[static_cast<std::size_t>(action)];
}

std::string_view hand_path(Hand hand) {
  return hand == Hand::Left ? "/user/hand/left" : "/user/hand/right";
}

const std::vector<OpenXrProfileBindings>& openxr_suggested_bindings() {
  static const std::vector<OpenXrProfileBindings> profiles = build();
  return profiles;
}

std::string openxr_bindings_table() {
  const auto& profiles = openxr_suggested_bindings();
  std::ostringstream out;
  out << "| vdfx action path |";
  for (const auto& p : profiles) out << " " << p.profile.substr(22) << " |";
  out << "\n|---|";
  for (std::size_t i = 0; i < profiles.size(); ++i) out << "---|";
  out << "\n";
  for (const Hand h : {Hand::Left, Hand::Right}) {
    for (const OpenXrActionSpec& a : kActions) {
      if (a.action == A::Menu && h == Hand::Right) continue;  // not one of vdfx's paths
      out << "| `" << vdfx_path(a.action, h) << "` |";
      for (const auto& p : profiles) {
        std::string cell = "-";
        for (const OpenXrBinding& b : p.bindings)
          if (b.action == a.action && b.hand == h) cell = b.path.substr(hand_path(h).size() + 1);
        out << " " << cell << " |";
      }
      out << "\n";
    }
  }
  return out.str();
}

}  // namespace vdfx::xr
