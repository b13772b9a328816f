/// @file
/// @brief The five interaction profiles the runtime accepts bindings for (OpenXR 1.0 spec,
/// 6.4 "Interaction Profiles": khr/simple_controller, oculus/touch_controller,
/// valve/index_controller, htc/vive_controller, microsoft/motion_controller), and how the
/// script's hand state drives each component.
#pragma once

#include <openxr/openxr.h>

#include <optional>
#include <string>
#include <vector>

#include "tests/openxr_runtime/script.h"

namespace vdfx::test_runtime {

enum class ComponentType { Boolean, Float, Vector2, Pose, Haptic };

/// Which script value a component reads.
enum class Source {
  Unpressed,  //!< exists on the device, never pressed by a script (system, thumbrest, Index
              //!< trackpad)
  Trigger,
  TriggerClick,
  TriggerTouch,
  Squeeze,
  SqueezeClick,
  Stick,
  StickX,
  StickY,
  StickClick,
  StickTouch,
  Primary,
  Secondary,
  Menu,
  Aim,  //!< aim and grip poses (vdfx records one controller pose)
  Haptic,
};

struct Component {
  std::string subpath;  //!< after /user/hand/{left,right}, e.g. "/input/trigger/value"
  ComponentType type;
  Source source;
  bool left = true;  //!< present on the left hand
  bool right = true;
};

struct InteractionProfile {
  std::string path;  //!< "/interaction_profiles/oculus/touch_controller"
  std::string localized;
  std::vector<Component> components;
};

const std::vector<InteractionProfile>& interaction_profiles();
const InteractionProfile* find_interaction_profile(const std::string& path);

/// A binding path resolved to one component of a profile for one hand.
struct ResolvedBinding {
  int hand = 0;  //!< 0 left, 1 right
  const Component* component = nullptr;
};

/// Resolves a suggested binding path ("/user/hand/left/input/trigger/value", or an identifier
/// such as ".../input/trigger", which names its value for a float action and its click for a
/// boolean one) for an action of `type`; nullopt when the profile has no such input or its type
/// cannot drive the action (a pose to a button, a haptic output to an input).
std::optional<ResolvedBinding> resolve_binding(const InteractionProfile& profile,
                                               const std::string& path, XrActionType type);

/// What a component reads from a hand's state. Click and touch of analog controls are
/// `value > 0.5` and `value > 0`; a float action on a click reads 0 or 1.
struct ComponentValue {
  bool b = false;
  float f = 0.0f;
  XrVector2f v{0.0f, 0.0f};
};
ComponentValue component_value(const Component& c, const ScriptHand& hand);

/// "Trigger Value", "Thumbstick", "A Click", ... for xrGetInputSourceLocalizedName.
std::string localized_component_name(const Component& c);

}  // namespace vdfx::test_runtime
