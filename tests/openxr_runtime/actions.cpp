/// @file
/// @brief The action system (spec chapter 11): action sets and actions, suggested bindings for
/// the five interaction profiles, attaching, xrSyncActions reading the script at the session's
/// time, action states, bound sources and their names, haptics (recorded for tests).
///
/// The simulated controllers are VDFX_TEST_RUNTIME_CONTROLLER (default oculus/touch_controller);
/// its profile is active when the app suggested bindings for it, else khr/simple_controller
/// when suggested (runtimes emulate it), else none. No priority arbitration between sets.
#include <algorithm>
#include <cstring>

#include "tests/openxr_runtime/action_state.h"
#include "tests/openxr_runtime/capture.h"
#include "tests/openxr_runtime/entry_points.h"
#include "tests/openxr_runtime/interaction_profiles.h"
#include "tests/openxr_runtime/session_state.h"
#include "tests/openxr_runtime/tracking.h"

namespace vdfx::test_runtime {
namespace {

constexpr const char* kHandPaths[2] = {"/user/hand/left", "/user/hand/right"};
constexpr const char* kTopLevelPaths[] = {"/user/hand/left", "/user/hand/right", "/user/head",
                                          "/user/gamepad", "/user/treadmill"};

bool is_top_level_user_path(const std::string& p) {
  for (const char* t : kTopLevelPaths) {
    if (p == t) return true;
  }
  return false;
}

/// The fixed-size name field holds a NUL-terminated name of the allowed characters.
bool is_valid_name(const char* name, std::size_t size) {
  const void* end = std::memchr(name, '\0', size);
  if (!end || name[0] == '\0') return false;
  for (const char* c = name; *c; ++c) {
    const bool ok =
        (*c >= 'a' && *c <= 'z') || (*c >= '0' && *c <= '9') || *c == '-' || *c == '_' || *c == '.';
    if (!ok) return false;
  }
  return true;
}

bool is_valid_localized(const char* name, std::size_t size) {
  return std::memchr(name, '\0', size) != nullptr && name[0] != '\0';
}

XrResult check_subaction(const char* fn, const Instance& inst, const Action& a, XrPath p) {
  if (p == XR_NULL_PATH) return XR_SUCCESS;
  if (!inst.paths.str(p)) return fail(fn, XR_ERROR_PATH_INVALID, "unknown subactionPath");
  if (std::find(a.subactions.begin(), a.subactions.end(), p) == a.subactions.end()) {
    return fail(fn, XR_ERROR_PATH_UNSUPPORTED,
                inst.paths.name(p) + " is not a subaction path of " + a.name);
  }
  return XR_SUCCESS;
}

/// The common checks of the action state getters and haptics.
XrResult check_action_use(const char* fn, const Instance& inst, const Action* a, XrActionType type,
                          XrPath subaction) {
  if (!a) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown action");
  if (a->type != type) {
    return fail(fn, XR_ERROR_ACTION_TYPE_MISMATCH, a->name + " has another action type");
  }
  if (!a->set->attached) {
    return fail(fn, XR_ERROR_ACTIONSET_NOT_ATTACHED, a->name + "'s action set is not attached");
  }
  return check_subaction(fn, inst, *a, subaction);
}

ActionValue value_of(const Action& a, XrPath subaction) {
  const auto it = a.values.find(subaction);
  return it == a.values.end() ? ActionValue{} : it->second;
}

bool same_value(const ActionValue& x, const ActionValue& y) {
  return x.b == y.b && x.f == y.f && x.v.x == y.v.x && x.v.y == y.v.y;
}

/// Which hands an active set lets through (the XrActiveActionSet subaction paths).
using HandFilter = std::array<bool, 2>;

/// One action's value for one subaction path from its bindings at the session's time.
ActionValue sample_action(const Instance& inst, const Session& s, const Action& a, XrPath key,
                          const HandFilter& hands) {
  ActionValue out;
  for (const Binding& b : s.bindings) {
    if (b.action != &a || !hands[b.hand]) continue;
    if (key != XR_NULL_PATH && inst.paths.name(key) != kHandPaths[b.hand]) continue;
    const ScriptHand* h = hand_state(inst, b.hand, s.now);
    if (!h) continue;  // a hand the script does not track is a controller that is off
    out.active = true;
    const ComponentValue v = component_value(*b.component, *h);
    out.b = out.b || v.b;
    if (std::abs(v.f) > std::abs(out.f)) out.f = v.f;
    if (v.v.x * v.v.x + v.v.y * v.v.y > out.v.x * out.v.x + out.v.y * out.v.y) out.v = v.v;
  }
  if (a.type == XR_ACTION_TYPE_BOOLEAN_INPUT) out.f = 0.0f;
  return out;
}

void sync_action(const Instance& inst, const Session& s, Action& a, const HandFilter* hands,
                 bool focused) {
  std::vector<XrPath> keys{XR_NULL_PATH};
  keys.insert(keys.end(), a.subactions.begin(), a.subactions.end());
  for (const XrPath key : keys) {
    ActionValue next;
    if (hands && focused) next = sample_action(inst, s, a, key, *hands);
    const ActionValue prev = value_of(a, key);
    next.changed = next.active && prev.active && !same_value(next, prev);
    next.last_change = prev.last_change;
    if (next.active && (next.changed || !prev.active)) next.last_change = s.now;
    a.values[key] = next;
  }
}

/// The profile the simulated controllers use for this app (see the file comment).
XrPath choose_profile(Instance& inst) {
  if (inst.config.controller == "none") return XR_NULL_PATH;
  const XrPath device = inst.paths.get("/interaction_profiles/" + inst.config.controller);
  if (inst.suggested.count(device)) return device;
  const XrPath simple = inst.paths.get("/interaction_profiles/khr/simple_controller");
  if (inst.suggested.count(simple)) return simple;
  return XR_NULL_PATH;
}

}  // namespace

std::optional<int> pose_action_hand(const Instance& inst, const Session& s, const Action& action,
                                    XrPath subaction) {
  if (!action.set->attached || !value_of(action, subaction).active) return std::nullopt;
  for (int hand = 0; hand < 2; ++hand) {
    if (subaction != XR_NULL_PATH && inst.paths.name(subaction) != kHandPaths[hand]) continue;
    for (const Binding& b : s.bindings) {
      if (b.action == &action && b.hand == hand) return hand;
    }
  }
  return std::nullopt;
}

namespace api {

XRAPI_ATTR XrResult XRAPI_CALL xrCreateActionSet(XrInstance instance,
                                                 const XrActionSetCreateInfo* info,
                                                 XrActionSet* actionSet) {
  constexpr const char* fn = "xrCreateActionSet";
  return guarded(fn, [&] {
    Instance* inst = find_instance(instance);
    if (!inst) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown instance");
    const XrResult r = check_struct(fn, "createInfo", info, XR_TYPE_ACTION_SET_CREATE_INFO);
    if (XR_FAILED(r)) return r;
    if (!actionSet) return fail(fn, XR_ERROR_VALIDATION_FAILURE, "actionSet is null");
    if (!is_valid_name(info->actionSetName, sizeof info->actionSetName)) {
      return fail(fn, XR_ERROR_NAME_INVALID,
                  "actionSetName is empty or has a character "
                  "other than a-z 0-9 - _ .");
    }
    if (!is_valid_localized(info->localizedActionSetName, sizeof info->localizedActionSetName)) {
      return fail(fn, XR_ERROR_LOCALIZED_NAME_INVALID, "localizedActionSetName is empty");
    }
    for (const auto& set : inst->action_sets) {
      if (set->destroyed) continue;
      if (set->name == info->actionSetName) {
        return fail(fn, XR_ERROR_NAME_DUPLICATED, set->name + " exists");
      }
      if (set->localized == info->localizedActionSetName) {
        return fail(fn, XR_ERROR_LOCALIZED_NAME_DUPLICATED, set->localized + " exists");
      }
    }
    auto set = std::make_unique<ActionSet>();
    set->name = info->actionSetName;
    set->localized = info->localizedActionSetName;
    set->priority = info->priority;
    *actionSet = to_handle<XrActionSet>(set.get());
    inst->action_sets.push_back(std::move(set));
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrDestroyActionSet(XrActionSet actionSet) {
  return guarded("xrDestroyActionSet", [&] {
    ActionSet* set = find_action_set(actionSet);
    if (!set) return fail("xrDestroyActionSet", XR_ERROR_HANDLE_INVALID, "unknown action set");
    set->destroyed = true;
    for (auto& a : set->actions) a->destroyed = true;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrCreateAction(XrActionSet actionSet, const XrActionCreateInfo* info,
                                              XrAction* action) {
  constexpr const char* fn = "xrCreateAction";
  return guarded(fn, [&] {
    ActionSet* set = find_action_set(actionSet);
    if (!set) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown action set");
    const XrResult r = check_struct(fn, "createInfo", info, XR_TYPE_ACTION_CREATE_INFO);
    if (XR_FAILED(r)) return r;
    if (!action) return fail(fn, XR_ERROR_VALIDATION_FAILURE, "action is null");
    if (set->attached) {
      return fail(fn, XR_ERROR_ACTIONSETS_ALREADY_ATTACHED, set->name + " is attached");
    }
    switch (info->actionType) {
      case XR_ACTION_TYPE_BOOLEAN_INPUT:
      case XR_ACTION_TYPE_FLOAT_INPUT:
      case XR_ACTION_TYPE_VECTOR2F_INPUT:
      case XR_ACTION_TYPE_POSE_INPUT:
      case XR_ACTION_TYPE_VIBRATION_OUTPUT: break;
      default: return fail(fn, XR_ERROR_VALIDATION_FAILURE, "not an action type");
    }
    if (!is_valid_name(info->actionName, sizeof info->actionName)) {
      return fail(fn, XR_ERROR_NAME_INVALID,
                  "actionName is empty or has a character other than "
                  "a-z 0-9 - _ .");
    }
    if (!is_valid_localized(info->localizedActionName, sizeof info->localizedActionName)) {
      return fail(fn, XR_ERROR_LOCALIZED_NAME_INVALID, "localizedActionName is empty");
    }
    for (const auto& a : set->actions) {
      if (a->destroyed) continue;
      if (a->name == info->actionName) return fail(fn, XR_ERROR_NAME_DUPLICATED, a->name);
      if (a->localized == info->localizedActionName) {
        return fail(fn, XR_ERROR_LOCALIZED_NAME_DUPLICATED, a->localized);
      }
    }
    const Instance& inst = *live_instance();
    std::vector<XrPath> subactions;
    for (uint32_t i = 0; i < info->countSubactionPaths; ++i) {
      const XrPath p = info->subactionPaths[i];
      if (!inst.paths.str(p)) return fail(fn, XR_ERROR_PATH_INVALID, "unknown subaction path");
      if (!is_top_level_user_path(inst.paths.name(p)) ||
          std::find(subactions.begin(), subactions.end(), p) != subactions.end()) {
        return fail(fn, XR_ERROR_PATH_UNSUPPORTED,
                    inst.paths.name(p) + " is not a top-level user path or is repeated");
      }
      subactions.push_back(p);
    }
    auto created = std::make_unique<Action>();
    created->set = set;
    created->name = info->actionName;
    created->localized = info->localizedActionName;
    created->type = info->actionType;
    created->subactions = std::move(subactions);
    *action = to_handle<XrAction>(created.get());
    set->actions.push_back(std::move(created));
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrDestroyAction(XrAction action) {
  return guarded("xrDestroyAction", [&] {
    Action* a = find_action(action);
    if (!a) return fail("xrDestroyAction", XR_ERROR_HANDLE_INVALID, "unknown action");
    a->destroyed = true;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrSuggestInteractionProfileBindings(
    XrInstance instance, const XrInteractionProfileSuggestedBinding* suggested) {
  constexpr const char* fn = "xrSuggestInteractionProfileBindings";
  return guarded(fn, [&] {
    Instance* inst = find_instance(instance);
    if (!inst) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown instance");
    const XrResult r = check_struct(fn, "suggestedBindings", suggested,
                                    XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING);
    if (XR_FAILED(r)) return r;
    if (suggested->countSuggestedBindings == 0 || !suggested->suggestedBindings) {
      return fail(fn, XR_ERROR_VALIDATION_FAILURE, "no bindings");
    }
    const std::string* profile_path = inst->paths.str(suggested->interactionProfile);
    if (!profile_path) return fail(fn, XR_ERROR_PATH_INVALID, "unknown interactionProfile path");
    const InteractionProfile* profile = find_interaction_profile(*profile_path);
    if (!profile) return fail(fn, XR_ERROR_PATH_UNSUPPORTED, *profile_path + " is not supported");
    std::vector<Binding> bindings;
    for (uint32_t i = 0; i < suggested->countSuggestedBindings; ++i) {
      const XrActionSuggestedBinding& sb = suggested->suggestedBindings[i];
      Action* a = find_action(sb.action);
      if (!a) return fail(fn, XR_ERROR_HANDLE_INVALID, "suggestedBindings[i].action");
      if (a->set->attached) {
        return fail(fn, XR_ERROR_ACTIONSETS_ALREADY_ATTACHED, a->set->name + " is attached");
      }
      const std::string* path = inst->paths.str(sb.binding);
      if (!path) return fail(fn, XR_ERROR_PATH_INVALID, "unknown binding path");
      const auto resolved = resolve_binding(*profile, *path, a->type);
      if (!resolved) {
        return fail(fn, XR_ERROR_PATH_UNSUPPORTED,
                    *path + " is not an input of " + *profile_path + " that can drive " + a->name);
      }
      if (!a->subactions.empty() &&
          std::find(a->subactions.begin(), a->subactions.end(),
                    inst->paths.get(kHandPaths[resolved->hand])) == a->subactions.end()) {
        return fail(fn, XR_ERROR_PATH_UNSUPPORTED,
                    *path + " is not under one of " + a->name + "'s subaction paths");
      }
      const std::string full =
          std::string(kHandPaths[resolved->hand]) + resolved->component->subpath;
      bindings.push_back({a, inst->paths.get(full), resolved->hand, resolved->component});
    }
    inst->suggested[suggested->interactionProfile] = std::move(bindings);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL
xrAttachSessionActionSets(XrSession session, const XrSessionActionSetsAttachInfo* info) {
  constexpr const char* fn = "xrAttachSessionActionSets";
  return guarded(fn, [&] {
    Session* s = find_session(session);
    if (!s) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown session");
    const XrResult r =
        check_struct(fn, "attachInfo", info, XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO);
    if (XR_FAILED(r)) return r;
    if (s->actions_attached) {
      return fail(fn, XR_ERROR_ACTIONSETS_ALREADY_ATTACHED, "action sets are attached already");
    }
    if (info->countActionSets == 0 || !info->actionSets) {
      return fail(fn, XR_ERROR_VALIDATION_FAILURE, "no action sets");
    }
    std::vector<ActionSet*> sets;
    for (uint32_t i = 0; i < info->countActionSets; ++i) {
      ActionSet* set = find_action_set(info->actionSets[i]);
      if (!set) return fail(fn, XR_ERROR_HANDLE_INVALID, "actionSets[i] is not an action set");
      sets.push_back(set);
    }
    Instance& inst = *live_instance();
    for (ActionSet* set : sets) set->attached = true;
    s->actions_attached = true;
    s->attached_sets = sets;
    s->profile = choose_profile(inst);
    if (s->profile != XR_NULL_PATH) {
      for (const Binding& b : inst.suggested[s->profile]) {
        if (b.action->set->attached && !b.action->destroyed) s->bindings.push_back(b);
      }
      XrEventDataInteractionProfileChanged e{};
      e.type = XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED;
      e.session = session;
      push_event(inst, &e, sizeof e);
      if (s->recorder) s->recorder->interaction_profile(inst.paths.name(s->profile), s->now);
    }
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrGetCurrentInteractionProfile(XrSession session,
                                                              XrPath topLevelUserPath,
                                                              XrInteractionProfileState* state) {
  constexpr const char* fn = "xrGetCurrentInteractionProfile";
  return guarded(fn, [&] {
    Session* s = find_session(session);
    if (!s) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown session");
    const XrResult r =
        check_struct(fn, "interactionProfile", state, XR_TYPE_INTERACTION_PROFILE_STATE);
    if (XR_FAILED(r)) return r;
    const Instance& inst = *live_instance();
    const std::string* user = inst.paths.str(topLevelUserPath);
    if (!user) return fail(fn, XR_ERROR_PATH_INVALID, "unknown topLevelUserPath");
    if (!is_top_level_user_path(*user)) {
      return fail(fn, XR_ERROR_PATH_UNSUPPORTED, *user + " is not a top-level user path");
    }
    if (!s->actions_attached) {
      return fail(fn, XR_ERROR_ACTIONSET_NOT_ATTACHED, "no action sets attached yet");
    }
    const bool hand = *user == kHandPaths[0] || *user == kHandPaths[1];
    state->interactionProfile = hand ? s->profile : XR_NULL_PATH;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrSyncActions(XrSession session, const XrActionsSyncInfo* info) {
  constexpr const char* fn = "xrSyncActions";
  return guarded(fn, [&] {
    Session* s = find_session(session);
    if (!s) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown session");
    const XrResult r = check_struct(fn, "syncInfo", info, XR_TYPE_ACTIONS_SYNC_INFO);
    if (XR_FAILED(r)) return r;
    if (info->countActiveActionSets > 0 && !info->activeActionSets) {
      return fail(fn, XR_ERROR_VALIDATION_FAILURE, "activeActionSets is null");
    }
    const Instance& inst = *live_instance();
    std::map<ActionSet*, HandFilter> active;
    for (uint32_t i = 0; i < info->countActiveActionSets; ++i) {
      const XrActiveActionSet& as = info->activeActionSets[i];
      ActionSet* set = find_action_set(as.actionSet);
      if (!set) return fail(fn, XR_ERROR_HANDLE_INVALID, "activeActionSets[i].actionSet");
      if (!set->attached) {
        return fail(fn, XR_ERROR_ACTIONSET_NOT_ATTACHED, set->name + " is not attached");
      }
      HandFilter& hands = active[set];
      if (as.subactionPath == XR_NULL_PATH) {
        hands = {true, true};
        continue;
      }
      const std::string* p = inst.paths.str(as.subactionPath);
      if (!p) return fail(fn, XR_ERROR_PATH_INVALID, "unknown subactionPath");
      if (!is_top_level_user_path(*p)) return fail(fn, XR_ERROR_PATH_UNSUPPORTED, *p);
      for (int h = 0; h < 2; ++h) hands[h] = hands[h] || *p == kHandPaths[h];
    }
    const bool focused = s->state == XR_SESSION_STATE_FOCUSED;
    for (ActionSet* set : s->attached_sets) {
      const auto it = active.find(set);
      for (auto& a : set->actions) {
        sync_action(inst, *s, *a, it == active.end() ? nullptr : &it->second, focused);
      }
    }
    return focused ? XR_SUCCESS : XR_SESSION_NOT_FOCUSED;
  });
}

namespace {

/// The getters share everything but the type and the fields they fill.
template <class State, class Fill>
XrResult get_state(const char* fn, XrSession session, const XrActionStateGetInfo* info,
                   State* state, XrStructureType state_type, XrActionType type, Fill&& fill) {
  return guarded(fn, [&] {
    if (!find_session(session)) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown session");
    XrResult r = check_struct(fn, "getInfo", info, XR_TYPE_ACTION_STATE_GET_INFO);
    if (XR_SUCCEEDED(r)) r = check_struct(fn, "state", state, state_type);
    if (XR_FAILED(r)) return r;
    const Action* a = find_action(info->action);
    r = check_action_use(fn, *live_instance(), a, type, info->subactionPath);
    if (XR_FAILED(r)) return r;
    fill(value_of(*a, info->subactionPath), *state);
    return XR_SUCCESS;
  });
}

}  // namespace

XRAPI_ATTR XrResult XRAPI_CALL xrGetActionStateBoolean(XrSession session,
                                                       const XrActionStateGetInfo* info,
                                                       XrActionStateBoolean* state) {
  return get_state("xrGetActionStateBoolean", session, info, state, XR_TYPE_ACTION_STATE_BOOLEAN,
                   XR_ACTION_TYPE_BOOLEAN_INPUT, [](const ActionValue& v, XrActionStateBoolean& s) {
                     s.currentState = v.active && v.b ? XR_TRUE : XR_FALSE;
                     s.changedSinceLastSync = v.changed ? XR_TRUE : XR_FALSE;
                     s.lastChangeTime = v.active ? v.last_change : 0;
                     s.isActive = v.active ? XR_TRUE : XR_FALSE;
                   });
}

XRAPI_ATTR XrResult XRAPI_CALL xrGetActionStateFloat(XrSession session,
                                                     const XrActionStateGetInfo* info,
                                                     XrActionStateFloat* state) {
  return get_state("xrGetActionStateFloat", session, info, state, XR_TYPE_ACTION_STATE_FLOAT,
                   XR_ACTION_TYPE_FLOAT_INPUT, [](const ActionValue& v, XrActionStateFloat& s) {
                     s.currentState = v.active ? v.f : 0.0f;
                     s.changedSinceLastSync = v.changed ? XR_TRUE : XR_FALSE;
                     s.lastChangeTime = v.active ? v.last_change : 0;
                     s.isActive = v.active ? XR_TRUE : XR_FALSE;
                   });
}

XRAPI_ATTR XrResult XRAPI_CALL xrGetActionStateVector2f(XrSession session,
                                                        const XrActionStateGetInfo* info,
                                                        XrActionStateVector2f* state) {
  return get_state("xrGetActionStateVector2f", session, info, state, XR_TYPE_ACTION_STATE_VECTOR2F,
                   XR_ACTION_TYPE_VECTOR2F_INPUT,
                   [](const ActionValue& v, XrActionStateVector2f& s) {
                     s.currentState = v.active ? v.v : XrVector2f{0.0f, 0.0f};
                     s.changedSinceLastSync = v.changed ? XR_TRUE : XR_FALSE;
                     s.lastChangeTime = v.active ? v.last_change : 0;
                     s.isActive = v.active ? XR_TRUE : XR_FALSE;
                   });
}

XRAPI_ATTR XrResult XRAPI_CALL xrGetActionStatePose(XrSession session,
                                                    const XrActionStateGetInfo* info,
                                                    XrActionStatePose* state) {
  return get_state("xrGetActionStatePose", session, info, state, XR_TYPE_ACTION_STATE_POSE,
                   XR_ACTION_TYPE_POSE_INPUT, [](const ActionValue& v, XrActionStatePose& s) {
                     s.isActive = v.active ? XR_TRUE : XR_FALSE;
                   });
}

XRAPI_ATTR XrResult XRAPI_CALL xrEnumerateBoundSourcesForAction(
    XrSession session, const XrBoundSourcesForActionEnumerateInfo* info, uint32_t capacity,
    uint32_t* count, XrPath* sources) {
  constexpr const char* fn = "xrEnumerateBoundSourcesForAction";
  return guarded(fn, [&] {
    Session* s = find_session(session);
    if (!s) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown session");
    const XrResult r =
        check_struct(fn, "enumerateInfo", info, XR_TYPE_BOUND_SOURCES_FOR_ACTION_ENUMERATE_INFO);
    if (XR_FAILED(r)) return r;
    const Action* a = find_action(info->action);
    if (!a) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown action");
    if (!a->set->attached) {
      return fail(fn, XR_ERROR_ACTIONSET_NOT_ATTACHED, a->name + "'s action set is not attached");
    }
    std::vector<XrPath> bound;
    for (const Binding& b : s->bindings) {
      if (b.action == a && std::find(bound.begin(), bound.end(), b.path) == bound.end()) {
        bound.push_back(b.path);
      }
    }
    return two_call(fn, capacity, count, sources, bound.size(), [&](XrPath& p, std::size_t i) {
      p = bound[i];
      return XR_SUCCESS;
    });
  });
}

XRAPI_ATTR XrResult XRAPI_CALL
xrGetInputSourceLocalizedName(XrSession session, const XrInputSourceLocalizedNameGetInfo* info,
                              uint32_t capacity, uint32_t* count, char* buffer) {
  constexpr const char* fn = "xrGetInputSourceLocalizedName";
  return guarded(fn, [&] {
    Session* s = find_session(session);
    if (!s) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown session");
    const XrResult r =
        check_struct(fn, "getInfo", info, XR_TYPE_INPUT_SOURCE_LOCALIZED_NAME_GET_INFO);
    if (XR_FAILED(r)) return r;
    constexpr XrInputSourceLocalizedNameFlags all =
        XR_INPUT_SOURCE_LOCALIZED_NAME_USER_PATH_BIT |
        XR_INPUT_SOURCE_LOCALIZED_NAME_INTERACTION_PROFILE_BIT |
        XR_INPUT_SOURCE_LOCALIZED_NAME_COMPONENT_BIT;
    if (info->whichComponents == 0 || (info->whichComponents & ~all)) {
      return fail(fn, XR_ERROR_VALIDATION_FAILURE, "whichComponents");
    }
    if (!s->actions_attached) return fail(fn, XR_ERROR_ACTIONSET_NOT_ATTACHED, "attach first");
    const Instance& inst = *live_instance();
    if (!inst.paths.str(info->sourcePath)) return fail(fn, XR_ERROR_PATH_INVALID, "sourcePath");
    const Binding* source = nullptr;
    for (const Binding& b : s->bindings) {
      if (b.path == info->sourcePath) source = &b;
    }
    if (!source) {
      return fail(fn, XR_ERROR_PATH_UNSUPPORTED,
                  inst.paths.name(info->sourcePath) + " is not a bound source");
    }
    std::string name;
    const auto add = [&](const std::string& part) { name += (name.empty() ? "" : " ") + part; };
    if (info->whichComponents & XR_INPUT_SOURCE_LOCALIZED_NAME_USER_PATH_BIT) {
      add(source->hand == 0 ? "Left Hand" : "Right Hand");
    }
    if (info->whichComponents & XR_INPUT_SOURCE_LOCALIZED_NAME_INTERACTION_PROFILE_BIT) {
      add(find_interaction_profile(inst.paths.name(s->profile))->localized);
    }
    if (info->whichComponents & XR_INPUT_SOURCE_LOCALIZED_NAME_COMPONENT_BIT) {
      add(localized_component_name(*source->component));
    }
    return two_call_string(fn, capacity, count, buffer, name);
  });
}

namespace {

XrResult haptic(const char* fn, XrSession session, const XrHapticActionInfo* info,
                const XrHapticBaseHeader* feedback, bool stop) {
  return guarded(fn, [&] {
    Session* s = find_session(session);
    if (!s) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown session");
    XrResult r = check_struct(fn, "hapticActionInfo", info, XR_TYPE_HAPTIC_ACTION_INFO);
    if (XR_SUCCEEDED(r) && !stop) {
      r = check_struct(fn, "hapticFeedback", feedback, XR_TYPE_HAPTIC_VIBRATION);
    }
    if (XR_FAILED(r)) return r;
    const Instance& inst = *live_instance();
    const Action* a = find_action(info->action);
    r = check_action_use(fn, inst, a, XR_ACTION_TYPE_VIBRATION_OUTPUT, info->subactionPath);
    if (XR_FAILED(r)) return r;
    if (s->state != XR_SESSION_STATE_FOCUSED) return XR_SESSION_NOT_FOCUSED;
    HapticRecord h;
    for (const Binding& b : s->bindings) {
      const bool hand_ok = info->subactionPath == XR_NULL_PATH ||
                           inst.paths.name(info->subactionPath) == kHandPaths[b.hand];
      if (b.action == a && hand_ok) h.outputs.push_back(inst.paths.name(b.path));
    }
    if (h.outputs.empty() || !s->recorder) return XR_SUCCESS;  // bound to nothing: no effect
    h.time = s->now;
    h.frame = s->waits;
    h.action = a->name;
    h.subaction = inst.paths.name(info->subactionPath);
    h.stop = stop;
    if (!stop) {
      const auto* v = reinterpret_cast<const XrHapticVibration*>(feedback);
      h.duration_ns = v->duration;
      h.frequency = v->frequency;
      h.amplitude = v->amplitude;
    }
    s->recorder->haptic(std::move(h));
    return XR_SUCCESS;
  });
}

}  // namespace

XRAPI_ATTR XrResult XRAPI_CALL xrApplyHapticFeedback(XrSession session,
                                                     const XrHapticActionInfo* info,
                                                     const XrHapticBaseHeader* feedback) {
  return haptic("xrApplyHapticFeedback", session, info, feedback, false);
}

XRAPI_ATTR XrResult XRAPI_CALL xrStopHapticFeedback(XrSession session,
                                                    const XrHapticActionInfo* info) {
  return haptic("xrStopHapticFeedback", session, info, nullptr, true);
}

}  // namespace api
}  // namespace vdfx::test_runtime
