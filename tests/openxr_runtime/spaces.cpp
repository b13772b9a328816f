/// @file
/// @brief Tracking at a time, reference and action spaces, xrLocateSpace and xrLocateViews.
#include <algorithm>

#include "tests/openxr_runtime/action_state.h"
#include "tests/openxr_runtime/entry_points.h"
#include "tests/openxr_runtime/tracking.h"

namespace vdfx::test_runtime {
namespace {

/// Without a script: standing still, head at 1.6 m, hands resting in front (the contract's
/// example recording's poses), nothing pressed.
const ScriptHand& resting_hand(int hand) {
  static const ScriptHand hands[2] = {
      {{{1.0, 0.0, 0.0, 0.0}, {-0.2, 1.3, -0.3}}, 0.0, 0.0, {0.0, 0.0}, false, false, false, false},
      {{{1.0, 0.0, 0.0, 0.0}, {0.2, 1.3, -0.3}}, 0.0, 0.0, {0.0, 0.0}, false, false, false, false}};
  return hands[hand];
}

const ScriptSample* sample_at(const Instance& inst, XrTime time) {
  return inst.script->at(time - kClockOriginNs);
}

constexpr XrSpaceLocationFlags kAllLocationFlags =
    XR_SPACE_LOCATION_ORIENTATION_VALID_BIT | XR_SPACE_LOCATION_POSITION_VALID_BIT |
    XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT | XR_SPACE_LOCATION_POSITION_TRACKED_BIT;

}  // namespace

std::optional<Pose> head_pose(const Instance& inst, XrTime time) {
  if (!inst.script) return Pose{glm::dquat(1.0, 0.0, 0.0, 0.0), glm::dvec3(0.0, 1.6, 0.0)};
  const ScriptSample* s = sample_at(inst, time);
  if (!s) return std::nullopt;
  return from_script(s->head);
}

const ScriptHand* hand_state(const Instance& inst, int hand, XrTime time) {
  if (!inst.script) return &resting_hand(hand);
  const ScriptSample* s = sample_at(inst, time);
  if (!s) return nullptr;
  const auto& h = hand == 0 ? s->left : s->right;
  return h ? &*h : nullptr;
}

std::optional<Pose> eye_pose(const Instance& inst, int eye, XrTime time) {
  const auto head = head_pose(inst, time);
  if (!head) return std::nullopt;
  const double x = (eye == 0 ? -0.5 : 0.5) * inst.hmd.ipd_m;
  return compose(*head, Pose{glm::dquat(1.0, 0.0, 0.0, 0.0), glm::dvec3(x, 0.0, 0.0)});
}

std::optional<Pose> space_pose(const Instance& inst, const Session& s, const Space& space,
                               XrTime time) {
  std::optional<Pose> origin;
  if (!space.is_action) {
    if (space.reference_type == XR_REFERENCE_SPACE_TYPE_VIEW) {
      origin = head_pose(inst, time);
    } else {
      origin = Pose{};
    }
  } else {
    const auto hand = pose_action_hand(inst, s, *space.action, space.subaction);
    const ScriptHand* h = hand ? hand_state(inst, *hand, time) : nullptr;
    if (h) origin = from_script(h->aim);
  }
  if (!origin) return std::nullopt;
  return compose(*origin, space.offset);
}

std::string space_name(const Space& space) {
  if (space.is_action) return "action:" + space.action->name;
  switch (space.reference_type) {
    case XR_REFERENCE_SPACE_TYPE_VIEW: return "VIEW";
    case XR_REFERENCE_SPACE_TYPE_LOCAL: return "LOCAL";
    case XR_REFERENCE_SPACE_TYPE_STAGE: return "STAGE";
    default: return "UNKNOWN";
  }
}

namespace api {

XRAPI_ATTR XrResult XRAPI_CALL xrEnumerateReferenceSpaces(XrSession session, uint32_t capacity,
                                                          uint32_t* count,
                                                          XrReferenceSpaceType* spaces) {
  constexpr const char* fn = "xrEnumerateReferenceSpaces";
  return guarded(fn, [&] {
    if (!find_session(session)) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown session");
    static constexpr XrReferenceSpaceType kTypes[] = {
        XR_REFERENCE_SPACE_TYPE_VIEW, XR_REFERENCE_SPACE_TYPE_LOCAL, XR_REFERENCE_SPACE_TYPE_STAGE};
    return two_call(fn, capacity, count, spaces, 3, [](XrReferenceSpaceType& t, std::size_t i) {
      t = kTypes[i];
      return XR_SUCCESS;
    });
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrCreateReferenceSpace(XrSession session,
                                                      const XrReferenceSpaceCreateInfo* info,
                                                      XrSpace* space) {
  constexpr const char* fn = "xrCreateReferenceSpace";
  return guarded(fn, [&] {
    Session* s = find_session(session);
    if (!s) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown session");
    const XrResult r = check_struct(fn, "createInfo", info, XR_TYPE_REFERENCE_SPACE_CREATE_INFO);
    if (XR_FAILED(r)) return r;
    if (!space) return fail(fn, XR_ERROR_VALIDATION_FAILURE, "space is null");
    const auto type = info->referenceSpaceType;
    if (type != XR_REFERENCE_SPACE_TYPE_VIEW && type != XR_REFERENCE_SPACE_TYPE_LOCAL &&
        type != XR_REFERENCE_SPACE_TYPE_STAGE) {
      return fail(fn, XR_ERROR_REFERENCE_SPACE_UNSUPPORTED,
                  "reference space type " + std::to_string(type));
    }
    if (!is_valid_pose(info->poseInReferenceSpace)) {
      return fail(fn, XR_ERROR_POSE_INVALID, "poseInReferenceSpace is not a rigid pose");
    }
    auto created = std::make_unique<Space>();
    created->reference_type = type;
    created->offset = from_xr(info->poseInReferenceSpace);
    *space = to_handle<XrSpace>(created.get());
    s->spaces.push_back(std::move(created));
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrGetReferenceSpaceBoundsRect(XrSession session,
                                                             XrReferenceSpaceType type,
                                                             XrExtent2Df* bounds) {
  constexpr const char* fn = "xrGetReferenceSpaceBoundsRect";
  return guarded(fn, [&] {
    if (!find_session(session)) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown session");
    if (!bounds) return fail(fn, XR_ERROR_VALIDATION_FAILURE, "bounds is null");
    if (type != XR_REFERENCE_SPACE_TYPE_VIEW && type != XR_REFERENCE_SPACE_TYPE_LOCAL &&
        type != XR_REFERENCE_SPACE_TYPE_STAGE) {
      return fail(fn, XR_ERROR_REFERENCE_SPACE_UNSUPPORTED, "unknown reference space type");
    }
    *bounds = {0.0f, 0.0f};
    return XR_SPACE_BOUNDS_UNAVAILABLE;  // a play area is not simulated
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrCreateActionSpace(XrSession session,
                                                   const XrActionSpaceCreateInfo* info,
                                                   XrSpace* space) {
  constexpr const char* fn = "xrCreateActionSpace";
  return guarded(fn, [&] {
    Session* s = find_session(session);
    if (!s) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown session");
    const XrResult r = check_struct(fn, "createInfo", info, XR_TYPE_ACTION_SPACE_CREATE_INFO);
    if (XR_FAILED(r)) return r;
    if (!space) return fail(fn, XR_ERROR_VALIDATION_FAILURE, "space is null");
    Action* action = find_action(info->action);
    if (!action) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown action");
    if (action->type != XR_ACTION_TYPE_POSE_INPUT) {
      return fail(fn, XR_ERROR_ACTION_TYPE_MISMATCH, action->name + " is not a pose action");
    }
    if (info->subactionPath != XR_NULL_PATH &&
        std::find(action->subactions.begin(), action->subactions.end(), info->subactionPath) ==
            action->subactions.end()) {
      return fail(fn, XR_ERROR_PATH_UNSUPPORTED,
                  "subactionPath " + live_instance()->paths.name(info->subactionPath) +
                      " is not one of " + action->name + "'s");
    }
    if (!is_valid_pose(info->poseInActionSpace)) {
      return fail(fn, XR_ERROR_POSE_INVALID, "poseInActionSpace is not a rigid pose");
    }
    auto created = std::make_unique<Space>();
    created->is_action = true;
    created->action = action;
    created->subaction = info->subactionPath;
    created->offset = from_xr(info->poseInActionSpace);
    *space = to_handle<XrSpace>(created.get());
    s->spaces.push_back(std::move(created));
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrDestroySpace(XrSpace space) {
  return guarded("xrDestroySpace", [&] {
    Space* sp = find_space(space);
    if (!sp) return fail("xrDestroySpace", XR_ERROR_HANDLE_INVALID, "unknown space");
    std::erase_if(live_instance()->session->spaces, [&](const auto& p) { return p.get() == sp; });
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrLocateSpace(XrSpace space, XrSpace baseSpace, XrTime time,
                                             XrSpaceLocation* location) {
  constexpr const char* fn = "xrLocateSpace";
  return guarded(fn, [&] {
    Space* sp = find_space(space);
    Space* base = find_space(baseSpace);
    if (!sp || !base) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown space or baseSpace");
    const XrResult r =
        check_struct(fn, "location", location, XR_TYPE_SPACE_LOCATION, {XR_TYPE_SPACE_VELOCITY});
    if (XR_FAILED(r)) return r;
    if (time <= 0) return fail(fn, XR_ERROR_TIME_INVALID, "time must be positive");
    const Instance& inst = *live_instance();
    const auto a = space_pose(inst, *inst.session, *sp, time);
    const auto b = space_pose(inst, *inst.session, *base, time);
    location->locationFlags = 0;
    location->pose = to_xr(Pose{});
    if (a && b) {
      location->locationFlags = kAllLocationFlags;
      location->pose = to_xr(compose(inverse(*b), *a));
    }
    for (auto* n = static_cast<XrBaseOutStructure*>(location->next); n; n = n->next) {
      auto* v = reinterpret_cast<XrSpaceVelocity*>(n);  // the only type the check allowed
      v->velocityFlags = 0;                             // velocities are not simulated
      v->linearVelocity = {0.0f, 0.0f, 0.0f};
      v->angularVelocity = {0.0f, 0.0f, 0.0f};
    }
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrLocateViews(XrSession session, const XrViewLocateInfo* info,
                                             XrViewState* viewState, uint32_t capacity,
                                             uint32_t* count, XrView* views) {
  constexpr const char* fn = "xrLocateViews";
  return guarded(fn, [&] {
    Session* s = find_session(session);
    if (!s) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown session");
    XrResult r = check_struct(fn, "viewLocateInfo", info, XR_TYPE_VIEW_LOCATE_INFO);
    if (XR_SUCCEEDED(r)) r = check_struct(fn, "viewState", viewState, XR_TYPE_VIEW_STATE);
    if (XR_FAILED(r)) return r;
    if (info->viewConfigurationType != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO) {
      return fail(fn, XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED, "stereo only");
    }
    Space* base = find_space(info->space);
    if (!base) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown space");
    if (info->displayTime <= 0)
      return fail(fn, XR_ERROR_TIME_INVALID, "displayTime must be positive");
    const Instance& inst = *live_instance();
    const auto base_pose = space_pose(inst, *s, *base, info->displayTime);
    const auto left = eye_pose(inst, 0, info->displayTime);
    const auto right = eye_pose(inst, 1, info->displayTime);
    const bool located = base_pose && left && right;
    viewState->viewStateFlags = 0;
    if (located) {
      viewState->viewStateFlags =
          XR_VIEW_STATE_ORIENTATION_VALID_BIT | XR_VIEW_STATE_POSITION_VALID_BIT |
          XR_VIEW_STATE_ORIENTATION_TRACKED_BIT | XR_VIEW_STATE_POSITION_TRACKED_BIT;
    }
    return two_call(fn, capacity, count, views, 2, [&](XrView& v, std::size_t i) {
      const XrResult c = check_struct(fn, "views[i]", &v, XR_TYPE_VIEW);
      if (XR_FAILED(c)) return c;
      const HmdEye& eye = inst.hmd.eyes[i];
      v.fov = {static_cast<float>(eye.angle_left), static_cast<float>(eye.angle_right),
               static_cast<float>(eye.angle_up), static_cast<float>(eye.angle_down)};
      v.pose = to_xr(located ? compose(inverse(*base_pose), i == 0 ? *left : *right) : Pose{});
      return XR_SUCCESS;
    });
  });
}

}  // namespace api
}  // namespace vdfx::test_runtime
