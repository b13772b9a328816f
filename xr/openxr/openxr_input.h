/// @file
/// @brief What the OpenXR backend reads for one poll (action states and located poses) and the
/// xr::InputState it becomes: the same fields, ranges and conventions as the sim, HID and replay
/// backends fill, so a headset session records and replays like any other.
///
/// Pure (no loader call): xr/openxr/gl/input_openxr.cpp fills an OpenXrInputSample from
/// xrSyncActions, xrGetActionState* and xrLocateSpace, and tests feed hand-made samples.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <optional>

#include "xr/input/actions.h"

namespace vdfx::xr {

/// One hand as the runtime reported it.
struct OpenXrHandSample {
  /// The aim pose in vdfx's LOCAL space, when both its orientation and position are valid.
  std::optional<Pose> aim;
  double trigger = 0.0;
  double squeeze = 0.0;
  glm::dvec2 thumbstick{0.0, 0.0};
  bool thumbstick_click = false;
  bool primary = false;
  bool secondary = false;
  bool menu = false;
};

struct OpenXrInputSample {
  std::int64_t t_ns = 0;     //!< the loop's time of the poll (not the runtime's XrTime)
  std::optional<Pose> head;  //!< VIEW located in vdfx's LOCAL, when valid
  OpenXrHandSample left, right;
};

/// The state other backends would give: a hand is tracked when its aim pose is valid (grip =
/// aim, as everywhere in vdfx); an untracked hand is HandState{} (what replay gives for a sample
/// that omits the hand); analog values are clamped to their ranges ([0, 1], [-1, 1]: runtimes may
/// overshoot by a rounding error, and the recording reader rejects values outside) and
/// quaternions normalised. Edges are left to InputBackend::poll.
InputState openxr_input_state(const OpenXrInputSample& sample);

}  // namespace vdfx::xr
