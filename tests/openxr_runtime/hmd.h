/// @file
/// @brief The headset the runtime simulates: what it reads of a vdfx HMD profile
/// (xr/headset/profiles/*.json, docs/hmd-profiles.md): views, their FOVs and sizes, IPD, refresh
/// rate.
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace vdfx::test_runtime {

struct HmdEye {
  int width = 0;  //!< recommended image size, pixels
  int height = 0;
  /// XrFovf in radians (left and down normally negative).
  double angle_left = 0, angle_right = 0, angle_up = 0, angle_down = 0;
};

struct Hmd {
  std::string name;
  std::string source;  //!< the file it was read from
  double refresh_hz = 90.0;
  double ipd_m = 0.063;
  std::array<HmdEye, 2> eyes;  //!< left, right

  /// One display period on the runtime's clock, nanoseconds (rounded).
  std::int64_t period_ns() const;
};

/// Loads a profile as vdfx's --hmd does: a value naming an existing file, containing '/' or
/// ending in ".json" is a path; anything else a name in $VDFX_HMD_PROFILE_DIR, else the source
/// tree's xr/headset/profiles. Throws std::runtime_error "FILE: /json/pointer: what" on a bad file.
Hmd load_hmd(const std::string& name_or_path);

}  // namespace vdfx::test_runtime
