/// @file
/// @brief The film-grain effect of ../shared/guide/flare-grain.md ("Film grain"): its four
/// styles, settings, keyframed parameters and refresh clock. docs/grain.md has the method.
///
/// A grain effect is not part of the six-effect stack: it is a layer drawn in world space after
/// the stack (and after the flare), one per sidecar entry; several may coexist.
/// - headset: Perlin grain on a plane plane_m ahead of the head (default 5 cm), head-anchored.
/// - surface: Perlin grain on a sphere of radius sphere_m (default 10 m) around the head, fixed
///   in world orientation (it stays put when the head turns).
/// - object_cloud: 3-D particles in a shell sphere_m .. shell x sphere_m around the head (the
///   video sphere as the object) and one surrounding volume beyond it, denser where nearer.
/// - free_cloud: 3-D particles in a cylinder (radius_m, height_m) around the head.
/// Parameters (RBF keyframes over direction and frame, like every effect): intensity 0..1
/// (neutral 0: no grain, no cost) and size 0.25..4 (neutral 1; scales grains and particles).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "effects/effect_types.h"
#include "effects/keyframe.h"

namespace vdfx::effects {

enum class GrainStyle { Headset, Surface, ObjectCloud, FreeCloud };
inline constexpr std::array<GrainStyle, 4> kGrainStyles{
    GrainStyle::Headset, GrainStyle::Surface, GrainStyle::ObjectCloud, GrainStyle::FreeCloud};

std::string_view grain_style_name(GrainStyle style);  //!< "headset", "surface", ...
std::optional<GrainStyle> grain_style_from_name(std::string_view name);
/// Particles (object_cloud, free_cloud) rather than shader noise (headset, surface).
inline bool is_volumetric(GrainStyle s) {
  return s == GrainStyle::ObjectCloud || s == GrainStyle::FreeCloud;
}

/// The settings of flare-grain.md's sidecar extension, each optional in the file.
enum class GrainSetting { RefreshMs = 0, PlaneM, SphereM, Shell, Count, RadiusM, HeightM };
inline constexpr int kGrainSettingCount = 7;

struct GrainSettingSpec {
  GrainSetting id;
  std::string_view name;  //!< sidecar name
  double min;
  double max;
  bool min_open;         //!< min itself is not accepted
  bool integer;          //!< a whole number (count)
  double default_value;  //!< for every style that reads it, unless grain_setting_default differs
};

/// All settings in sidecar order.
const std::array<GrainSettingSpec, kGrainSettingCount>& grain_setting_specs();
const GrainSettingSpec& grain_setting_spec(GrainSetting id);
/// The settings a style reads (the reader rejects the others): refresh_ms for all; headset
/// plane_m; surface sphere_m; object_cloud sphere_m, shell, count; free_cloud count, radius_m,
/// height_m.
std::span<const GrainSetting> grain_style_settings(GrainStyle style);
bool grain_style_has_setting(GrainStyle style, GrainSetting id);

/// A setting's default for a style: the spec's, except object_cloud's sphere_m (2 m: the shell
/// near enough for its particles to read as grain, docs/grain.md "Looks"; surface keeps 10 m).
double grain_setting_default(GrainStyle style, GrainSetting id);

/// The settings of one grain effect, every one at its default until set. The reader fills in
/// what the file gives; the writer writes the style's own settings, all of them.
struct GrainSettings {
  GrainSettings();                           //!< the specs' defaults
  explicit GrainSettings(GrainStyle style);  //!< the style's defaults (grain_setting_default)
  std::array<double, kGrainSettingCount> values{};
  double get(GrainSetting id) const { return values[static_cast<std::size_t>(id)]; }
  void set(GrainSetting id, double v) { values[static_cast<std::size_t>(id)] = v; }
  bool operator==(const GrainSettings&) const = default;
};

/// Keyframe parameters: [intensity, size] (sidecar "params": {"intensity", "size"}).
const std::vector<ParamSpec>& grain_param_specs();
inline constexpr int kGrainParamCount = 2;

/// One sidecar entry {"type": "grain", ...}.
struct GrainEffect {
  GrainStyle style = GrainStyle::Surface;
  std::uint64_t seed = 0;  //!< fixes every random choice (with the refresh index)
  GrainSettings settings;
  std::optional<InterpolationSettings> interpolation;  //!< overrides the file's default
  std::vector<Keyframe> keyframes;                     //!< params [intensity, size]
  Anchor anchor = {};  //!< the frame the keyframe directions are in (effects/anchor.h)
  bool operator==(const GrainEffect&) const = default;
};

/// Interpolated parameters at one view, clamped to the ranges.
struct GrainParams {
  double intensity = 0.0;  //!< 0..1; 0 draws nothing
  double size = 1.0;       //!< 0.25..4
};

/// Which grain pattern a display time shows: floor(t / period), period = refresh_ms rounded to
/// whole nanoseconds. Grains (noise phase, particle positions) change exactly when it changes.
std::int64_t grain_refresh_index(std::int64_t display_time_ns, double refresh_ms);

}  // namespace vdfx::effects
