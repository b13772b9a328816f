/// @file
/// @brief The simulated runtime's action system driven by a script: a trigger press reaches the
/// actions bound to it in each of the five interaction profiles, changes are reported once, pose
/// actions follow the scripted controller, haptics are recorded, and bad bindings are refused.
#include <gtest/gtest.h>

#include <cstring>

#include "tests/openxr/runtime_test_fixture.h"
#include "tests/openxr/xr_test_app.h"

namespace vdfx::test_runtime {
namespace {

XrPath path(XrTestApp& app, const char* s) {
  XrPath p = XR_NULL_PATH;
  XR_EXPECT_OK(xrStringToPath(app.instance, s, &p));
  return p;
}

XrActionSet make_set(XrTestApp& app, const char* name) {
  XrActionSetCreateInfo info{};
  info.type = XR_TYPE_ACTION_SET_CREATE_INFO;
  std::strcpy(info.actionSetName, name);
  std::strcpy(info.localizedActionSetName, name);
  XrActionSet set = XR_NULL_HANDLE;
  XR_EXPECT_OK(xrCreateActionSet(app.instance, &info, &set));
  return set;
}

XrResult make_action(XrTestApp& app, XrActionSet set, const char* name, XrActionType type,
                     XrAction* action, bool both_hands = true) {
  XrActionCreateInfo info{};
  info.type = XR_TYPE_ACTION_CREATE_INFO;
  std::strcpy(info.actionName, name);
  std::strcpy(info.localizedActionName, name);
  info.actionType = type;
  const XrPath hands[2] = {path(app, "/user/hand/left"), path(app, "/user/hand/right")};
  info.countSubactionPaths = both_hands ? 2 : 0;
  info.subactionPaths = hands;
  return xrCreateAction(set, &info, action);
}

XrResult suggest(XrTestApp& app, const char* profile,
                 const std::vector<std::pair<XrAction, const char*>>& bindings) {
  std::vector<XrActionSuggestedBinding> b;
  for (const auto& [action, p] : bindings) b.push_back({action, path(app, p)});
  XrInteractionProfileSuggestedBinding info{};
  info.type = XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING;
  info.interactionProfile = path(app, profile);
  info.countSuggestedBindings = static_cast<uint32_t>(b.size());
  info.suggestedBindings = b.data();
  return xrSuggestInteractionProfileBindings(app.instance, &info);
}

void attach(XrTestApp& app, XrActionSet set) {
  XrSessionActionSetsAttachInfo info{};
  info.type = XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO;
  info.countActionSets = 1;
  info.actionSets = &set;
  XR_EXPECT_OK(xrAttachSessionActionSets(app.session, &info));
}

XrResult sync(XrTestApp& app, XrActionSet set) {
  const XrActiveActionSet active{set, XR_NULL_PATH};
  XrActionsSyncInfo info{};
  info.type = XR_TYPE_ACTIONS_SYNC_INFO;
  info.countActiveActionSets = 1;
  info.activeActionSets = &active;
  return xrSyncActions(app.session, &info);
}

XrActionStateFloat float_state(XrTestApp& app, XrAction a, const char* subaction = nullptr) {
  XrActionStateGetInfo info{XR_TYPE_ACTION_STATE_GET_INFO, nullptr, a,
                            subaction ? path(app, subaction) : XR_NULL_PATH};
  XrActionStateFloat s{};
  s.type = XR_TYPE_ACTION_STATE_FLOAT;
  XR_EXPECT_OK(xrGetActionStateFloat(app.session, &info, &s));
  return s;
}

XrActionStateBoolean bool_state(XrTestApp& app, XrAction a) {
  XrActionStateGetInfo info{XR_TYPE_ACTION_STATE_GET_INFO, nullptr, a, XR_NULL_PATH};
  XrActionStateBoolean s{};
  s.type = XR_TYPE_ACTION_STATE_BOOLEAN;
  XR_EXPECT_OK(xrGetActionStateBoolean(app.session, &info, &s));
  return s;
}

/// Begins the session and runs frame 0, which makes it FOCUSED.
void focus(XrTestApp& app) {
  app.poll_states();
  XR_EXPECT_OK(app.begin_session());
  app.empty_frame();
  ASSERT_EQ(app.poll_states().back(), XR_SESSION_STATE_FOCUSED);
}

/// The right hand with its trigger at `trigger` (and the stick at `stick`).
ScriptLine right_trigger(std::int64_t t_ns, double trigger, std::array<double, 2> stick = {0, 0}) {
  ScriptLine l{t_ns};
  HandSample h;
  h.trigger = trigger;
  h.stick = stick;
  l.right = h;
  l.left = HandSample{};
  l.left->p = {-0.2, 1.3, -0.3};
  return l;
}

class Actions : public RuntimeTest {};

TEST_F(Actions, AScriptedTriggerPressIsReportedOnceAtItsFrame) {
  // The right trigger goes to 0.8 at 50 ms: frame 5 (55.6 ms) is the first to see it. The last
  // sample keeps the script (and the session's focus) going past the frames looked at.
  script({right_trigger(0, 0.0), right_trigger(50'000'000, 0.8), right_trigger(200'000'000, 0.8)});
  XrTestApp app;
  ASSERT_TRUE(app.start());
  const XrActionSet set = make_set(app, "test");
  XrAction value = XR_NULL_HANDLE, press = XR_NULL_HANDLE;
  XR_EXPECT_OK(make_action(app, set, "trigger_value", XR_ACTION_TYPE_FLOAT_INPUT, &value));
  XR_EXPECT_OK(make_action(app, set, "trigger_press", XR_ACTION_TYPE_BOOLEAN_INPUT, &press));
  XR_EXPECT_OK(suggest(app, "/interaction_profiles/oculus/touch_controller",
                       {{value, "/user/hand/right/input/trigger/value"},
                        {value, "/user/hand/left/input/trigger/value"},
                        {press, "/user/hand/right/input/trigger"}}));  // identifier only
  attach(app, set);
  focus(app);  // frame 0
  for (int k = 1; k <= 7; ++k) {
    app.empty_frame();  // frame k: the session's time is frame k's
    EXPECT_EQ(sync(app, set), XR_SUCCESS);
    const XrActionStateFloat v = float_state(app, value);
    const XrActionStateBoolean b = bool_state(app, press);
    EXPECT_TRUE(v.isActive);
    EXPECT_FLOAT_EQ(v.currentState, k >= 5 ? 0.8f : 0.0f) << k;
    EXPECT_EQ(b.currentState, k >= 5 ? XR_TRUE : XR_FALSE) << k;  // above half way
    EXPECT_EQ(v.changedSinceLastSync, k == 5 ? XR_TRUE : XR_FALSE) << k;
    EXPECT_EQ(b.changedSinceLastSync, k == 5 ? XR_TRUE : XR_FALSE) << k;
    if (k >= 5) {
      EXPECT_EQ(v.lastChangeTime, frame_time(5));
    }
  }
  // Per hand: the left trigger is not pressed.
  EXPECT_FLOAT_EQ(float_state(app, value, "/user/hand/left").currentState, 0.0f);
  EXPECT_FLOAT_EQ(float_state(app, value, "/user/hand/right").currentState, 0.8f);
}

TEST_F(Actions, OutsideFocusEveryActionIsInactive) {
  XrTestApp app;
  ASSERT_TRUE(app.start());
  const XrActionSet set = make_set(app, "test");
  XrAction value = XR_NULL_HANDLE;
  XR_EXPECT_OK(make_action(app, set, "trigger_value", XR_ACTION_TYPE_FLOAT_INPUT, &value));
  XR_EXPECT_OK(suggest(app, "/interaction_profiles/khr/simple_controller",
                       {{value, "/user/hand/right/input/select/click"}}));
  attach(app, set);
  EXPECT_EQ(sync(app, set), XR_SESSION_NOT_FOCUSED);
  EXPECT_FALSE(float_state(app, value).isActive);
}

struct ProfileCase {
  const char* name;
  const char* profile;
  const char* trigger;  //!< what the script's trigger drives there
  const char* stick;    //!< what its stick drives ("" none)
};

const ProfileCase kProfiles[] = {
    {"simple", "khr/simple_controller", "/user/hand/right/input/select/click", ""},
    {"touch", "oculus/touch_controller", "/user/hand/right/input/trigger/value",
     "/user/hand/right/input/thumbstick"},
    {"index", "valve/index_controller", "/user/hand/right/input/trigger/value",
     "/user/hand/right/input/thumbstick"},
    {"vive", "htc/vive_controller", "/user/hand/right/input/trigger/value",
     "/user/hand/right/input/trackpad"},
    {"wmr", "microsoft/motion_controller", "/user/hand/right/input/trigger/value",
     "/user/hand/right/input/thumbstick"},
};

class ActionsPerProfile : public RuntimeTest, public ::testing::WithParamInterface<ProfileCase> {};

TEST_P(ActionsPerProfile, TheScriptDrivesTheControllersOwnProfile) {
  const ProfileCase& c = GetParam();
  set("VDFX_TEST_RUNTIME_CONTROLLER", c.profile);
  script({right_trigger(0, 1.0, {0.5, -0.25})});
  XrTestApp app;
  ASSERT_TRUE(app.start());
  const XrActionSet set = make_set(app, "test");
  XrAction trigger = XR_NULL_HANDLE, stick = XR_NULL_HANDLE, aim = XR_NULL_HANDLE;
  XR_EXPECT_OK(make_action(app, set, "trigger", XR_ACTION_TYPE_FLOAT_INPUT, &trigger));
  XR_EXPECT_OK(make_action(app, set, "stick", XR_ACTION_TYPE_VECTOR2F_INPUT, &stick));
  XR_EXPECT_OK(make_action(app, set, "aim", XR_ACTION_TYPE_POSE_INPUT, &aim));
  std::vector<std::pair<XrAction, const char*>> bindings{{trigger, c.trigger},
                                                         {aim, "/user/hand/right/input/aim/pose"}};
  if (*c.stick) bindings.emplace_back(stick, c.stick);
  const std::string profile = std::string("/interaction_profiles/") + c.profile;
  XR_EXPECT_OK(suggest(app, profile.c_str(), bindings));
  attach(app, set);
  // The controllers' own profile is current, and the app is told.
  XrInteractionProfileState current{};
  current.type = XR_TYPE_INTERACTION_PROFILE_STATE;
  XR_EXPECT_OK(
      xrGetCurrentInteractionProfile(app.session, path(app, "/user/hand/right"), &current));
  EXPECT_EQ(current.interactionProfile, path(app, profile.c_str()));
  focus(app);
  XR_EXPECT_OK(sync(app, set));
  EXPECT_FLOAT_EQ(float_state(app, trigger).currentState, 1.0f);
  XrActionStateGetInfo info{XR_TYPE_ACTION_STATE_GET_INFO, nullptr, stick, XR_NULL_PATH};
  XrActionStateVector2f v{};
  v.type = XR_TYPE_ACTION_STATE_VECTOR2F;
  XR_EXPECT_OK(xrGetActionStateVector2f(app.session, &info, &v));
  EXPECT_EQ(v.isActive, *c.stick ? XR_TRUE : XR_FALSE);
  if (*c.stick) {
    EXPECT_FLOAT_EQ(v.currentState.x, 0.5f);
    EXPECT_FLOAT_EQ(v.currentState.y, -0.25f);
  }
  // Bound sources name the full input path, and the runtime names them for people.
  XrBoundSourcesForActionEnumerateInfo enumerate{XR_TYPE_BOUND_SOURCES_FOR_ACTION_ENUMERATE_INFO,
                                                 nullptr, aim};
  uint32_t n = 0;
  XR_EXPECT_OK(xrEnumerateBoundSourcesForAction(app.session, &enumerate, 0, &n, nullptr));
  ASSERT_EQ(n, 1u);
  XrPath source = XR_NULL_PATH;
  XR_EXPECT_OK(xrEnumerateBoundSourcesForAction(app.session, &enumerate, 1, &n, &source));
  EXPECT_EQ(source, path(app, "/user/hand/right/input/aim/pose"));
  XrInputSourceLocalizedNameGetInfo name_info{
      XR_TYPE_INPUT_SOURCE_LOCALIZED_NAME_GET_INFO, nullptr, source,
      XR_INPUT_SOURCE_LOCALIZED_NAME_USER_PATH_BIT | XR_INPUT_SOURCE_LOCALIZED_NAME_COMPONENT_BIT};
  char name[128] = {};
  XR_EXPECT_OK(xrGetInputSourceLocalizedName(app.session, &name_info, sizeof name, &n, name));
  EXPECT_STREQ(name, "Right Hand Aim Pose");
}

INSTANTIATE_TEST_SUITE_P(Profiles, ActionsPerProfile, ::testing::ValuesIn(kProfiles),
                         [](const auto& info) { return std::string(info.param.name); });

TEST_F(Actions, TheSimpleControllerStandsInWhenTheDevicesProfileIsNotSuggested) {
  script({right_trigger(0, 1.0)});
  XrTestApp app;  // the controllers are Touch (the default)
  ASSERT_TRUE(app.start());
  const XrActionSet set = make_set(app, "test");
  XrAction select = XR_NULL_HANDLE;
  XR_EXPECT_OK(make_action(app, set, "select", XR_ACTION_TYPE_BOOLEAN_INPUT, &select));
  XR_EXPECT_OK(suggest(app, "/interaction_profiles/khr/simple_controller",
                       {{select, "/user/hand/right/input/select/click"}}));
  attach(app, set);
  XrInteractionProfileState current{};
  current.type = XR_TYPE_INTERACTION_PROFILE_STATE;
  XR_EXPECT_OK(xrGetCurrentInteractionProfile(app.session, path(app, "/user/hand/left"), &current));
  EXPECT_EQ(current.interactionProfile, path(app, "/interaction_profiles/khr/simple_controller"));
  focus(app);
  XR_EXPECT_OK(sync(app, set));
  EXPECT_EQ(bool_state(app, select).currentState, XR_TRUE);
}

TEST_F(Actions, AnActionSpaceFollowsTheScriptedAimAndIsLostWithTheHand) {
  ScriptLine a = right_trigger(0, 0.0);
  a.right->p = {0.3, 1.2, -0.4};
  a.right->q = {std::cos(0.25), std::sin(0.25), 0.0, 0.0};  // pitched up 0.5 rad
  ScriptLine b{50'000'000};                                 // from 50 ms no hand is tracked
  script({a, b});
  XrTestApp app;
  ASSERT_TRUE(app.start());
  const XrActionSet set = make_set(app, "test");
  XrAction aim = XR_NULL_HANDLE;
  XR_EXPECT_OK(make_action(app, set, "aim", XR_ACTION_TYPE_POSE_INPUT, &aim));
  XR_EXPECT_OK(suggest(app, "/interaction_profiles/oculus/touch_controller",
                       {{aim, "/user/hand/right/input/aim/pose"}}));
  attach(app, set);
  XrActionSpaceCreateInfo info{};
  info.type = XR_TYPE_ACTION_SPACE_CREATE_INFO;
  info.action = aim;
  info.subactionPath = path(app, "/user/hand/right");
  info.poseInActionSpace = XrTestApp::identity();
  XrSpace hand = XR_NULL_HANDLE;
  XR_EXPECT_OK(xrCreateActionSpace(app.session, &info, &hand));
  const XrSpace local = app.reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL);
  focus(app);
  XR_EXPECT_OK(sync(app, set));
  XrSpaceLocation where{XR_TYPE_SPACE_LOCATION, nullptr, 0, {}};
  XR_EXPECT_OK(xrLocateSpace(hand, local, frame_time(1), &where));
  EXPECT_NE(where.locationFlags & XR_SPACE_LOCATION_POSITION_VALID_BIT, 0u);
  EXPECT_NEAR(where.pose.position.x, 0.3, 1e-6);
  EXPECT_NEAR(where.pose.position.y, 1.2, 1e-6);
  EXPECT_NEAR(where.pose.orientation.x, std::sin(0.25), 1e-6);
  XR_EXPECT_OK(xrLocateSpace(hand, local, frame_time(5), &where));
  EXPECT_EQ(where.locationFlags, 0u);
  XR_EXPECT_OK(xrDestroySpace(hand));
}

TEST_F(Actions, HapticsReachTheReadBackFolder) {
  XrTestApp app;
  ASSERT_TRUE(app.start());
  const XrActionSet set = make_set(app, "test");
  XrAction buzz = XR_NULL_HANDLE;
  XR_EXPECT_OK(make_action(app, set, "buzz", XR_ACTION_TYPE_VIBRATION_OUTPUT, &buzz));
  XR_EXPECT_OK(
      suggest(app, "/interaction_profiles/oculus/touch_controller",
              {{buzz, "/user/hand/left/output/haptic"}, {buzz, "/user/hand/right/output/haptic"}}));
  attach(app, set);
  focus(app);
  XR_EXPECT_OK(sync(app, set));
  XrHapticActionInfo info{XR_TYPE_HAPTIC_ACTION_INFO, nullptr, buzz, path(app, "/user/hand/right")};
  XrHapticVibration pulse{XR_TYPE_HAPTIC_VIBRATION, nullptr, 30'000'000, XR_FREQUENCY_UNSPECIFIED,
                          0.6f};
  XR_EXPECT_OK(xrApplyHapticFeedback(app.session, &info,
                                     reinterpret_cast<const XrHapticBaseHeader*>(&pulse)));
  info.subactionPath = XR_NULL_PATH;
  XR_EXPECT_OK(xrStopHapticFeedback(app.session, &info));
  XR_EXPECT_OK(xrDestroySession(app.session));
  app.session = XR_NULL_HANDLE;
  const auto haptics = session_json().at("haptics");
  ASSERT_EQ(haptics.size(), 2u);
  EXPECT_EQ(haptics[0].at("action"), "buzz");
  EXPECT_EQ(haptics[0].at("subaction"), "/user/hand/right");
  EXPECT_EQ(haptics[0].at("outputs"), nlohmann::json::array({"/user/hand/right/output/haptic"}));
  EXPECT_EQ(haptics[0].at("duration_ns"), 30'000'000);
  EXPECT_FLOAT_EQ(haptics[0].at("amplitude").get<float>(), 0.6f);
  EXPECT_EQ(haptics[0].at("time_ns"), frame_time(0));
  EXPECT_EQ(haptics[1].at("stop"), true);
  EXPECT_EQ(haptics[1].at("outputs").size(), 2u);
}

class ActionsWithoutLayer : public RuntimeTest {};

TEST_F(ActionsWithoutLayer, BadNamesBindingsAndUsesAreRefused) {
  without_layer();  // the layer checks some of these itself
  XrTestApp app;
  ASSERT_TRUE(app.start());
  const XrActionSet set = make_set(app, "test");
  XrAction value = XR_NULL_HANDLE, pose = XR_NULL_HANDLE, other = XR_NULL_HANDLE;
  XR_EXPECT_OK(make_action(app, set, "value", XR_ACTION_TYPE_FLOAT_INPUT, &value));
  XR_EXPECT_OK(make_action(app, set, "pose", XR_ACTION_TYPE_POSE_INPUT, &pose, false));
  EXPECT_EQ(make_action(app, set, "value", XR_ACTION_TYPE_FLOAT_INPUT, &other),
            XR_ERROR_NAME_DUPLICATED);
  EXPECT_EQ(make_action(app, set, "Capital", XR_ACTION_TYPE_FLOAT_INPUT, &other),
            XR_ERROR_NAME_INVALID);
  XrPath p = XR_NULL_PATH;
  EXPECT_EQ(xrStringToPath(app.instance, "/user/hand/left/", &p), XR_ERROR_PATH_FORMAT_INVALID);
  EXPECT_EQ(xrStringToPath(app.instance, "user/hand", &p), XR_ERROR_PATH_FORMAT_INVALID);
  const char* touch = "/interaction_profiles/oculus/touch_controller";
  // A/B are the right Touch controller's, X/Y the left's.
  EXPECT_EQ(suggest(app, touch, {{value, "/user/hand/left/input/a/click"}}),
            XR_ERROR_PATH_UNSUPPORTED);
  EXPECT_EQ(suggest(app, touch, {{pose, "/user/hand/left/input/trigger/value"}}),
            XR_ERROR_PATH_UNSUPPORTED);  // a pose from a trigger
  EXPECT_EQ(suggest(app, "/interaction_profiles/vdfx/imaginary_controller",
                    {{value, "/user/hand/left/input/trigger/value"}}),
            XR_ERROR_PATH_UNSUPPORTED);
  XR_EXPECT_OK(suggest(app, touch,
                       {{value, "/user/hand/left/input/x/click"},  // a float from a button: 0 or 1
                        {pose, "/user/hand/left/input/grip"}}));   // the identifier: grip/pose
  attach(app, set);
  EXPECT_EQ(make_action(app, set, "late", XR_ACTION_TYPE_FLOAT_INPUT, &other),
            XR_ERROR_ACTIONSETS_ALREADY_ATTACHED);
  EXPECT_EQ(suggest(app, touch, {{value, "/user/hand/left/input/y/click"}}),
            XR_ERROR_ACTIONSETS_ALREADY_ATTACHED);
  XrActionStateGetInfo info{XR_TYPE_ACTION_STATE_GET_INFO, nullptr, value, XR_NULL_PATH};
  XrActionStateBoolean b{};
  b.type = XR_TYPE_ACTION_STATE_BOOLEAN;
  EXPECT_EQ(xrGetActionStateBoolean(app.session, &info, &b), XR_ERROR_ACTION_TYPE_MISMATCH);
  info.subactionPath = path(app, "/user/head");
  XrActionStateFloat f{};
  f.type = XR_TYPE_ACTION_STATE_FLOAT;
  EXPECT_EQ(xrGetActionStateFloat(app.session, &info, &f), XR_ERROR_PATH_UNSUPPORTED);
}

}  // namespace
}  // namespace vdfx::test_runtime
