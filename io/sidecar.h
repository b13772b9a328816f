/// @file
/// @brief The sidecar file, format 1 (contract: "Sidecar file, format 1"): data model, reading,
/// writing. Validation with every problem listed is in io/sidecar_validate.h.
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "effects/flare.h"
#include "effects/grain.h"
#include "effects/keyframe.h"

namespace vdfx::io {

/// The video a sidecar belongs to, as recorded when it was authored.
struct VideoInfo {
  std::string path;         //!< as written in the file (relative paths are relative to the sidecar)
  double fps = 30.0;        //!< > 0
  std::int64_t frames = 1;  //!< >= 1; keyframe frames lie in [0, frames)
  int width = 1;            //!< > 0
  int height = 1;           //!< > 0
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
  bool operator==(const Sidecar&) const = default;
};

/// A new, empty sidecar for a video, as vdfx starts one: the author's time scale
/// (effects::kAuthorTimeScale, docs/interpolation.md "Time") instead of the paper's c = 1.
Sidecar new_sidecar(VideoInfo video);

inline constexpr const char* kSidecarFormat = "vdfx.sidecar";
inline constexpr int kSidecarVersion = 1;

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

/// An "interpolation" object (the file's default or an effect's override).
nlohmann::ordered_json interpolation_to_json(const effects::InterpolationSettings& settings);

/// The text write_sidecar() writes: 2-space indented JSON in the contract's key order, shortest
/// round-trip doubles, a final newline. write -> read -> write gives identical bytes.
std::string format_sidecar(const Sidecar& sidecar);

/// Writes format_sidecar(sidecar) atomically (io/atomic_file.h). Throws io::InputError naming the
/// file when it cannot be written. Does not validate: callers write what they built.
void write_sidecar(const std::filesystem::path& path, const Sidecar& sidecar);

}  // namespace vdfx::io
