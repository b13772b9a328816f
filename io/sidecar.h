/// @file
/// @brief The sidecar file, format 1 (contract: "Sidecar file, format 1"): data model, reading,
/// writing. Validation with every problem listed is in io/sidecar_validate.h.
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "effects/flare.h"
#include "effects/grain.h"
#include "effects/keyframe.h"
#include "effects/stereo_layout.h"

namespace vdfx::io {

/// The video a sidecar belongs to, as recorded when it was authored.
struct VideoInfo {
  VideoInfo() = default;
  /// The five fields every sidecar has; layout and coverage not recorded.
  VideoInfo(std::string path_, double fps_, std::int64_t frames_, int width_, int height_)
      : path(std::move(path_)), fps(fps_), frames(frames_), width(width_), height(height_) {}

  std::string path;         //!< as written in the file (relative paths are relative to the sidecar)
  double fps = 30.0;        //!< > 0
  std::int64_t frames = 1;  //!< >= 1; keyframe frames lie in [0, frames)
  int width = 1;            //!< > 0
  int height = 1;           //!< > 0
  /// "layout" and "coverage" (docs/sidecar.md); absent: not recorded, read as mono and 360.
  std::optional<effects::StereoMode> layout;
  std::optional<int> coverage_deg;
  /// The layout as recorded, absent parts at their defaults.
  effects::StereoLayout stereo() const {
    return {layout.value_or(effects::StereoMode::Mono), coverage_deg.value_or(360)};
  }
  bool operator==(const VideoInfo&) const = default;
};

struct Sidecar {
  VideoInfo video;
  effects::InterpolationSettings interpolation;  //!< the file's default
  std::vector<effects::EffectTrack> effects;     //!< in file order; each type at most once
  /// "type": "flare" entries of "effects", in file order (any number; written after the stack
  /// effects: a flare is drawn after the whole stack whatever its place in the file).
  std::vector<effects::FlareEffect> flares;
  /// "type": "grain" entries, in file order (any number; written after the flares: grain is
  /// drawn after the stack and the flare whatever its place in the file).
  std::vector<effects::GrainEffect> grains;
  /// "camera" (contract: "Frames of reference"): the camera's orientation at every frame, the
  /// world anchor's rotations; absent when nobody tracked or gave it.
  std::optional<effects::CameraMotion> camera;
  /// "tracks": subjects' directions over frames, the track anchors' rotations.
  std::vector<effects::SubjectTrack> tracks;
  bool operator==(const Sidecar&) const = default;
};

/// Renames the track `from` to `to` and every anchor naming it (effects, flares, grain layers:
/// track:FROM becomes track:TO); returns how many anchors were renamed. `to` must be a valid
/// track name (the caller checks: a usage error). Throws InputError naming `file` and the JSON
/// pointer, `s` unchanged, when there is no track `from` or a track is already named `to`.
int rename_track(Sidecar& s, const std::string& from, const std::string& to,
                 const std::string& file);

/// A new, empty sidecar for a video, as vdfx starts one: the author's time scale
/// (effects::kAuthorTimeScale, docs/interpolation.md "Time") instead of the paper's c = 1.
Sidecar new_sidecar(VideoInfo video);

inline constexpr const char* kSidecarFormat = "vdfx.sidecar";
inline constexpr int kSidecarVersion = 1;
/// Bounds on the RBF's time axis, checked by the validator (docs/sidecar.md, "Derived values"):
/// one frame is 24 / fps * time_scale apart in the RBF distance. Over the whole clip that must
/// stay at most kMaxScaledTimeSpan, where d^exponent (exponent < 4) and the solve still have
/// 1e60 of headroom before overflowing to infinity and NaN (fps 1e-200 evaluated to null). One
/// frame must stay at least kMinScaledFrameStep apart, or keyframes one frame apart at one
/// direction are no longer told apart and are not reproduced (measured: exact to 1e-6 at 8e-6,
/// off by 7e-5 at 8e-7 and 3e-3 at 8e-8 with exponent 3.99).
inline constexpr double kMaxScaledTimeSpan = 1e60;
inline constexpr double kMinScaledFrameStep = 1e-5;

/// The most keyframes one effect may have (docs/reliability.md, "Limits"). Above
/// effects::kGlobalSolveMaxKeyframes an effect is interpolated locally in time, in windows of at
/// most effects::kMaxWindowKeyframes keyframes (effects/rbf_windows.h): time and memory grow
/// linearly with the count (docs/interpolation.md measures 100000 keyframes).
inline constexpr std::size_t kMaxKeyframesPerEffect = 100000;

/// The largest sidecar file read (docs/reliability.md): room for several effects at
/// kMaxKeyframesPerEffect keyframes (about 20 MB each as written), small enough to hold in memory
/// as parsed JSON a few times over.
inline constexpr std::uintmax_t kMaxSidecarBytes = std::uintmax_t{256} << 20;

/// Reads and validates a sidecar. Throws io::InputError listing every problem (one per line:
/// "FILE: POINTER: what is wrong") when the file is unreadable or invalid.
Sidecar read_sidecar(const std::filesystem::path& path);

/// The document of a sidecar. Keys are sorted (nlohmann::json is a std::map); the text written
/// by format_sidecar() keeps the contract's key order instead.
nlohmann::json to_json(const Sidecar& sidecar);

/// One effect's flat parameter vector as the sidecar's "params" object ({"stops": 1.0},
/// {"gain": [r, g, b]}, ...), in the effect spec's order.
nlohmann::ordered_json params_to_json(effects::EffectType type, std::span<const double> values);

/// One keyframe as written: azimuth_deg, altitude_deg, frame, then `params`.
nlohmann::ordered_json keyframe_to_json(const effects::Keyframe& keyframe,
                                        nlohmann::ordered_json params);

/// The "keyframes" array of an entry whose parameters are scalars (flare: intensity; grain:
/// intensity, size): each value under its spec's name, a missing one as the spec's neutral.
nlohmann::ordered_json scalar_keyframes_to_json(const std::vector<effects::Keyframe>& keyframes,
                                                std::span<const effects::ParamSpec> specs);

/// An "interpolation" object (the file's default or an effect's override).
nlohmann::ordered_json interpolation_to_json(const effects::InterpolationSettings& settings);

/// The text write_sidecar() writes: 2-space indented JSON in the contract's key order, shortest
/// round-trip doubles, a final newline. write -> read -> write gives identical bytes.
std::string format_sidecar(const Sidecar& sidecar);

/// Writes format_sidecar(sidecar) atomically (io/atomic_file.h). Throws io::InputError naming the
/// file when it cannot be written. Does not validate: callers write what they built.
void write_sidecar(const std::filesystem::path& path, const Sidecar& sidecar);

}  // namespace vdfx::io
