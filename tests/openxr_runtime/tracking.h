/// @file
/// @brief Where things are at a given XrTime: the head and hands from the script (or a resting
/// pose without one), eyes from the headset's IPD, spaces relative to LOCAL.
///
/// LOCAL and STAGE are both the script's frame (vdfx's: origin on the floor under the user, head
/// at y = 1.6 m), so a script's poses come back unchanged when located in LOCAL.
#pragma once

#include <optional>
#include <string>

#include "tests/openxr_runtime/runtime.h"

namespace vdfx::test_runtime {

/// The head (VIEW's origin) in LOCAL at `time`; nullopt before the script's first sample.
std::optional<Pose> head_pose(const Instance& inst, XrTime time);

/// One hand's state at `time` (0 left, 1 right); nullptr when not tracked.
const ScriptHand* hand_state(const Instance& inst, int hand, XrTime time);

/// An eye's pose in LOCAL: the head moved by -IPD/2 (left) or +IPD/2 (right) along its x axis.
std::optional<Pose> eye_pose(const Instance& inst, int eye, XrTime time);

/// A space's pose in LOCAL at `time`; nullopt when it cannot be located (head or hand not
/// tracked, or an action space whose action is not active).
std::optional<Pose> space_pose(const Instance& inst, const Session& s, const Space& space,
                               XrTime time);

/// "VIEW", "LOCAL", "STAGE" or "action:NAME" (for the read-back JSON).
std::string space_name(const Space& space);

}  // namespace vdfx::test_runtime
