/// @file
/// @brief The session script: head and controller poses and controls over time, read from a vdfx
/// recording (`.vdrec.jsonl`, contract "Recording file, format 1", docs/input.md).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vdfx::test_runtime {

struct ScriptPose {
  std::array<double, 4> q{1.0, 0.0, 0.0, 0.0};  //!< unit quaternion [w, x, y, z]
  std::array<double, 3> p{0.0, 0.0, 0.0};       //!< metres, OpenXR axes
};

struct ScriptHand {
  ScriptPose aim;  //!< also the grip pose (vdfx records no controller model)
  double trigger = 0.0;
  double squeeze = 0.0;
  std::array<double, 2> stick{0.0, 0.0};
  bool primary = false;    //!< a (right) or x (left)
  bool secondary = false;  //!< b (right) or y (left)
  bool menu = false;       //!< left hand only
  bool stick_click = false;
};

struct ScriptSample {
  std::int64_t t_ns = 0;
  ScriptPose head;
  std::optional<ScriptHand> left;  //!< absent: not tracked
  std::optional<ScriptHand> right;
};

struct Script {
  std::string path;
  std::string hmd;                    //!< the header's "hmd" (a profile name, or "sim")
  std::vector<ScriptSample> samples;  //!< strictly increasing t_ns, at least one
  std::vector<std::string> warnings;  //!< e.g. a truncated last line that was dropped

  /// The sample in effect at script time t: the last one at or before t (step, as vdfx's
  /// replay); nullptr before the first.
  const ScriptSample* at(std::int64_t t_ns) const;
  std::int64_t end_ns() const { return samples.back().t_ns; }
};

/// Reads and checks a recording. Raw HID lines are skipped (the sample lines carry what vdfx's
/// mapping made of them). Throws std::runtime_error "FILE:LINE: /json/pointer: what".
Script read_script(const std::string& path);

}  // namespace vdfx::test_runtime
