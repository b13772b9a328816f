/// @file
/// @brief Head-mounted display profiles: per-eye panel and field of view, IPD, refresh rate and
/// the eyepiece lens, loaded from JSON files in xr/headset/profiles/ (format:
/// docs/hmd-profiles.md).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "effects/lens_model.h"

namespace vdfx::xr {

enum class Eye { Left = 0, Right = 1 };
inline constexpr std::array<Eye, 2> kEyes{Eye::Left, Eye::Right};
std::string_view eye_name(Eye eye);

/// OpenXR-style field of view (XrFovf) in degrees: angle_left and angle_down are normally
/// negative; each in (-90, 90), left < right, down < up.
struct FovDeg {
  double angle_left = -45.0;
  double angle_right = 45.0;
  double angle_up = 45.0;
  double angle_down = -45.0;

  /// The tangents of the four angles, in the lens model's convention.
  effects::TanRect tangents() const;
};

struct EyeProfile {
  int width = 0;  //!< panel viewport of this eye, pixels (the eye image has the same size)
  int height = 0;
  FovDeg fov;
  /// Optical centre in the eye's viewport, normalised [0, 1], x right, y down. It follows from
  /// the FOV (the panel and the image share one linear map); the loader checks they agree.
  std::array<double, 2> lens_centre{0.5, 0.5};
};

struct HmdProfile {
  std::string name;
  std::string description;
  std::string source;  //!< file it was loaded from
  double refresh_hz = 90.0;
  double ipd_m = 0.063;
  effects::LensParams lens;
  std::array<EyeProfile, 2> eyes;

  const EyeProfile& eye(Eye e) const { return eyes[static_cast<int>(e)]; }
  /// The lens geometry of one eye, for the pre-distortion and the through-the-lens simulation.
  effects::EyeLens eye_lens(Eye e) const;
};

/// The largest profile file read (the bundled ones are about 1 KiB).
inline constexpr std::uintmax_t kMaxHmdProfileBytes = std::uintmax_t{1} << 20;

/// Where named profiles are looked up: $VDFX_HMD_PROFILE_DIR when set, else the source tree's
/// xr/headset/profiles (VDFX_SOURCE_DIR).
std::filesystem::path hmd_profile_dir();

/// Loads `--hmd NAME|FILE`: a value naming an existing file, or containing '/' or ending in
/// ".json", is a path; anything else is a profile name in hmd_profile_dir(). Throws
/// io::InputError listing every problem (file, JSON pointer, what is wrong).
HmdProfile load_hmd_profile(std::string_view name_or_path);

/// Validates and converts a parsed profile; `source` names the file in error messages.
HmdProfile parse_hmd_profile(const nlohmann::json& doc, const std::string& source);

/// Parses and validates a profile's text (as a sidecar's: line and column of a syntax error, NUL
/// bytes and duplicate keys refused); `source` names the file in error messages.
HmdProfile parse_hmd_profile_text(std::string_view text, const std::string& source);

/// Names of the profiles in hmd_profile_dir(), sorted.
std::vector<std::string> list_hmd_profiles();

}  // namespace vdfx::xr
