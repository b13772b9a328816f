/// @file
/// @brief vdfx's OpenXR action set and the bindings it suggests for five interaction profiles.
///
/// Pure data (no loader call): the OpenXR backend (xr/openxr/gl/openxr_instance.cpp) creates one
/// action per entry of openxr_actions(), each with both hands as subaction paths, and suggests
/// openxr_suggested_bindings(); the tests check every path against the profiles' component lists
/// of the OpenXR 1.0 specification (section 6.4, "Interaction Profile Paths") without a runtime.
/// docs/openxr.md prints the table (openxr_bindings_table()).
///
/// Each action fills one field of xr::HandState (xr/input/actions.h), so the OpenXR backend yields
/// the same action paths as the sim, HID and replay backends (docs/input.md).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "xr/input/actions.h"

namespace vdfx::xr {

/// The OpenXR action types vdfx uses (XrActionType without the prefix).
enum class OpenXrActionType { Boolean, Float, Vector2, Pose, Vibration };

/// One action of the set.
enum class OpenXrAction : std::uint8_t {
  Aim,              //!< pose: HandState::aim (and grip: vdfx has no controller model)
  Trigger,          //!< float: HandState::trigger
  Squeeze,          //!< float: HandState::squeeze
  Thumbstick,       //!< vector2: HandState::thumbstick
  ThumbstickClick,  //!< boolean: HandState::thumbstick_click
  Primary,          //!< boolean: HandState::primary (a right, x left)
  Secondary,        //!< boolean: HandState::secondary (b right, y left)
  Menu,             //!< boolean: HandState::menu (left only in vdfx's paths)
  Haptic,           //!< vibration output: the pulse when a keyframe is placed
};
inline constexpr int kOpenXrActionCount = 9;

struct OpenXrActionSpec {
  OpenXrAction action;
  std::string_view name;            //!< xrCreateAction's actionName (lower case, OpenXR's rule)
  std::string_view localized_name;  //!< what a runtime's rebinding UI shows
  OpenXrActionType type;
};

/// The action set's name and its localized name.
inline constexpr std::string_view kOpenXrActionSetName = "vdfx";
inline constexpr std::string_view kOpenXrActionSetLocalizedName = "vdfx editor and player";

/// Every action, in OpenXrAction order.
const std::array<OpenXrActionSpec, kOpenXrActionCount>& openxr_actions();
const OpenXrActionSpec& openxr_action(OpenXrAction action);

/// "/user/hand/left" or "/user/hand/right".
std::string_view hand_path(Hand hand);

struct OpenXrBinding {
  OpenXrAction action;
  Hand hand;
  std::string path;  //!< the whole binding path ("/user/hand/left/input/trigger/value")
};

struct OpenXrProfileBindings {
  std::string profile;  //!< "/interaction_profiles/oculus/touch_controller"
  std::string name;     //!< "Oculus Touch"
  std::vector<OpenXrBinding> bindings;
};

/// khr/simple_controller, oculus/touch_controller, valve/index_controller, htc/vive_controller,
/// microsoft/motion_controller, with their suggested bindings.
const std::vector<OpenXrProfileBindings>& openxr_suggested_bindings();

/// The binding table as markdown: one row per vdfx action path, one column per profile (the
/// component bound, or "-").
std::string openxr_bindings_table();

}  // namespace vdfx::xr
