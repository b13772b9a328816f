/// @file
/// @brief vdfx's OpenXR action set and suggested bindings against the OpenXR 1.0
/// specification's interaction profiles (section 6.4, "Interaction Profile Paths"), without a
/// runtime: every path exists on its profile and hand, fits its action's type, and every
/// profile binds what the editor cannot work without.
#include "xr/openxr/openxr_bindings.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "tests/support/test_paths.h"

namespace vdfx::xr {
namespace {

/// The components of each profile per hand, as the specification lists them (x/y pairs also
/// bind as their parent path, a vector2f: spec section 6.3.2).
struct SpecProfile {
  const char* profile;
  std::vector<std::string> both, left_only, right_only;
};

const std::vector<SpecProfile>& spec_profiles() {
  static const std::vector<SpecProfile> p = {
      {"/interaction_profiles/khr/simple_controller",
       {"input/select/click", "input/menu/click", "input/grip/pose", "input/aim/pose",
        "output/haptic"},
       {},
       {}},
      {"/interaction_profiles/oculus/touch_controller",
       {"input/squeeze/value", "input/trigger/value", "input/trigger/touch", "input/thumbstick",
        "input/thumbstick/x", "input/thumbstick/y", "input/thumbstick/click",
        "input/thumbstick/touch", "input/thumbrest/touch", "input/grip/pose", "input/aim/pose",
        "output/haptic"},
       {"input/x/click", "input/x/touch", "input/y/click", "input/y/touch", "input/menu/click"},
       {"input/a/click", "input/a/touch", "input/b/click", "input/b/touch", "input/system/click"}},
      {"/interaction_profiles/valve/index_controller",
       {"input/system/click",     "input/system/touch",   "input/a/click",
        "input/a/touch",          "input/b/click",        "input/b/touch",
        "input/squeeze/value",    "input/squeeze/force",  "input/trigger/click",
        "input/trigger/value",    "input/trigger/touch",  "input/thumbstick",
        "input/thumbstick/x",     "input/thumbstick/y",   "input/thumbstick/click",
        "input/thumbstick/touch", "input/trackpad",       "input/trackpad/x",
        "input/trackpad/y",       "input/trackpad/force", "input/trackpad/touch",
        "input/grip/pose",        "input/aim/pose",       "output/haptic"},
       {},
       {}},
      {"/interaction_profiles/htc/vive_controller",
       {"input/system/click", "input/squeeze/click", "input/menu/click", "input/trigger/click",
        "input/trigger/value", "input/trackpad", "input/trackpad/x", "input/trackpad/y",
        "input/trackpad/click", "input/trackpad/touch", "input/grip/pose", "input/aim/pose",
        "output/haptic"},
       {},
       {}},
      {"/interaction_profiles/microsoft/motion_controller",
       {"input/menu/click", "input/squeeze/click", "input/trigger/value", "input/thumbstick",
        "input/thumbstick/x", "input/thumbstick/y", "input/thumbstick/click", "input/trackpad",
        "input/trackpad/x", "input/trackpad/y", "input/trackpad/click", "input/trackpad/touch",
        "input/grip/pose", "input/aim/pose", "output/haptic"},
       {},
       {}},
  };
  return p;
}

std::set<std::string> allowed_paths(const SpecProfile& s) {
  std::set<std::string> out;
  for (const Hand h : {Hand::Left, Hand::Right}) {
    const std::string base = std::string(hand_path(h)) + "/";
    for (const auto& c : s.both) out.insert(base + c);
    for (const auto& c : h == Hand::Left ? s.left_only : s.right_only) out.insert(base + c);
  }
  return out;
}

/// Whether a component can feed an action of this type (spec section 6.3.2: a boolean source
/// converts to a float action and a float one to a boolean through the runtime's threshold).
bool fits(OpenXrActionType type, const std::string& path) {
  const auto ends = [&](const char* s) { return path.ends_with(s); };
  switch (type) {
    case OpenXrActionType::Pose: return ends("/pose");
    case OpenXrActionType::Vibration: return ends("/output/haptic");
    case OpenXrActionType::Vector2: return ends("/thumbstick") || ends("/trackpad");
    case OpenXrActionType::Float: return ends("/value") || ends("/click");
    case OpenXrActionType::Boolean: return ends("/click") || ends("/value");
  }
  return false;
}

TEST(OpenXrBindings, TheFiveProfilesAreSuggested) {
  std::set<std::string> suggested;
  for (const auto& p : openxr_suggested_bindings()) suggested.insert(p.profile);
  std::set<std::string> expected;
  for (const auto& s : spec_profiles()) expected.insert(s.profile);
  EXPECT_EQ(suggested, expected);
}

TEST(OpenXrBindings, EveryPathExistsOnItsProfileAndHandAndFitsItsAction) {
  for (const auto& p : openxr_suggested_bindings()) {
    const SpecProfile* spec = nullptr;
    for (const auto& s : spec_profiles())
      if (p.profile == s.profile) spec = &s;
    ASSERT_NE(spec, nullptr) << p.profile;
    const std::set<std::string> allowed = allowed_paths(*spec);
    std::set<std::pair<int, std::string>> seen;
    for (const OpenXrBinding& b : p.bindings) {
      EXPECT_TRUE(allowed.count(b.path)) << p.profile << ": " << b.path << " is not a component";
      EXPECT_TRUE(b.path.starts_with(std::string(hand_path(b.hand)) + "/")) << b.path;
      EXPECT_TRUE(fits(openxr_action(b.action).type, b.path))
          << p.profile << ": " << b.path << " cannot feed action " << openxr_action(b.action).name;
      EXPECT_TRUE(seen.insert({static_cast<int>(b.action), b.path}).second) << "twice: " << b.path;
    }
  }
}

TEST(OpenXrBindings, EveryProfileBindsTheRayTheTriggerAndTheHapticOnBothHands) {
  for (const auto& p : openxr_suggested_bindings()) {
    for (const Hand h : {Hand::Left, Hand::Right}) {
      for (const OpenXrAction a :
           {OpenXrAction::Aim, OpenXrAction::Trigger, OpenXrAction::Haptic}) {
        bool found = false;
        for (const OpenXrBinding& b : p.bindings) found |= b.action == a && b.hand == h;
        EXPECT_TRUE(found) << p.profile << " " << hand_path(h) << ": " << openxr_action(a).name;
      }
    }
  }
}

TEST(OpenXrBindings, ProfilesWithSticksAndButtonsBindEveryEditorControl) {
  // Touch, Index and WMR have a stick, two buttons a hand (or a pad click) and a squeeze: every
  // control of the editor's binding table (app/editor/bindings.h) is reachable.
  for (const auto& p : openxr_suggested_bindings()) {
    if (p.profile.ends_with("simple_controller") || p.profile.ends_with("vive_controller"))
      continue;
    std::set<std::pair<int, int>> bound;
    for (const OpenXrBinding& b : p.bindings)
      bound.insert({static_cast<int>(b.action), static_cast<int>(b.hand)});
    for (const OpenXrAction a : {OpenXrAction::Squeeze, OpenXrAction::Thumbstick,
                                 OpenXrAction::ThumbstickClick, OpenXrAction::Primary}) {
      EXPECT_TRUE(bound.count({static_cast<int>(a), 0})) << p.profile << " left " << int(a);
      EXPECT_TRUE(bound.count({static_cast<int>(a), 1})) << p.profile << " right " << int(a);
    }
  }
}

TEST(OpenXrBindings, ActionNamesFollowOpenXrsRules) {
  // xrCreateAction: lower-case letters, digits, '-', '_', '.'; unique; at most 63 characters.
  const std::regex rule("[a-z0-9_.-]{1,63}");
  std::set<std::string_view> names;
  for (const OpenXrActionSpec& a : openxr_actions()) {
    EXPECT_TRUE(std::regex_match(std::string(a.name), rule)) << a.name;
    EXPECT_TRUE(names.insert(a.name).second) << a.name;
    EXPECT_EQ(&openxr_action(a.action), &a) << a.name;  // the table is in enum order
  }
  EXPECT_TRUE(std::regex_match(std::string(kOpenXrActionSetName), rule));
}

TEST(OpenXrBindings, TableHasARowPerVdfxHandPathAndAColumnPerProfile) {
  const std::string table = openxr_bindings_table();
  for (const std::string& path : action_paths()) {
    if (!path.starts_with("/user/hand/") || path.ends_with("/tracked") ||
        path.ends_with("/grip/pose") || path.ends_with("/thumbstick/x") ||
        path.ends_with("/thumbstick/y"))
      continue;  // tracked is the aim pose's validity; grip = aim; x, y are the stick's halves
    EXPECT_NE(table.find("`" + path + "`"), std::string::npos) << path;
  }
  EXPECT_NE(table.find("| `/user/hand/right/input/a/click` | - | input/a/click | input/a/click | "
                       "input/menu/click | input/trackpad/click |"),
            std::string::npos)
      << table;
}

TEST(OpenXrBindings, DocsShowTheTableTheCodeSuggests) {
  std::ifstream in(std::string(VDFX_SOURCE_DIR) + "/docs/openxr.md");
  ASSERT_TRUE(in) << "docs/openxr.md";
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find(openxr_bindings_table()), std::string::npos)
      << "docs/openxr.md's binding table differs from the code's; the code's:\n"
      << openxr_bindings_table();
}

}  // namespace
}  // namespace vdfx::xr
