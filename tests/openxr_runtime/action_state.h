/// @file
/// @brief What the action system tells the rest of the runtime: which hand drives a pose action.
#pragma once

#include <optional>

#include "tests/openxr_runtime/runtime.h"

namespace vdfx::test_runtime {

/// The hand (0 left, 1 right) whose pose an action space of `action` follows: the hand of
/// `subaction`, or with XR_NULL_PATH the first hand the active profile binds it to; nullopt when
/// the action is not bound or not active at the last xrSyncActions.
std::optional<int> pose_action_hand(const Instance& inst, const Session& s, const Action& action,
                                    XrPath subaction);

}  // namespace vdfx::test_runtime
