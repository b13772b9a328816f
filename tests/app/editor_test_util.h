/// @file
/// @brief Shared helpers of the editor tests: sidecars, input snapshots, temp folders.
#pragma once

#include <filesystem>
#include <string>

#include "io/sidecar.h"
#include "tests/test_files.h"
#include "xr/input/actions.h"

namespace vdfx::app::test {

/// An empty sidecar for a clip of `frames` frames at 30 fps.
inline io::Sidecar empty_sidecar(std::int64_t frames = 90) {
  io::Sidecar s;
  s.video = {"clip.mp4", 30.0, frames, 3840, 1920};
  return s;
}

/// Head looking at (az, alt); right hand tracked, aiming straight up (at no panel).
inline xr::InputState looking(double az, double alt, std::int64_t t_ns = 0) {
  xr::InputState in = xr::neutral_input_state(t_ns);
  in.head_tracked = true;
  in.head.orientation = xr::look_rotation(az, alt);
  in.right.tracked = true;
  in.right.aim = {{0.2, 1.3, -0.3}, xr::look_rotation(0.0, 89.0)};
  in.right.grip = in.right.aim;
  return in;
}

/// A fresh folder under the test output directory.
inline std::filesystem::path temp_dir(const std::string& name) {
  return test_files::fresh_dir(std::filesystem::path("editor") / name);
}

}  // namespace vdfx::app::test
