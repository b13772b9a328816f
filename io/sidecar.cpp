/// @file
/// @brief Sidecar reading and writing (format 1).
#include "io/sidecar.h"

#include <algorithm>

#include "io/atomic_file.h"
#include "io/input_error.h"
#include "io/sidecar_anchor.h"
#include "io/sidecar_flare.h"
#include "io/sidecar_grain.h"
#include "io/sidecar_validate.h"

namespace vdfx::io {

namespace {

using ordered = nlohmann::ordered_json;

ordered interpolation_json(const effects::InterpolationSettings& s) {
  ordered j;
  j["exponent"] = s.exponent;
  j["time_scale"] = s.time_scale;
  // The extension is written only when it differs from the default, so files that do not use
  // it stay plain format 1 for readers that do not know it.
  if (s.distance == effects::AngularDistance::Geodesic) j["distance"] = "geodesic";
  if (s.outside == effects::TimeOutside::Extrapolate) j["outside_span"] = "extrapolate";
  if (s.reach_s) j["reach_s"] = *s.reach_s;
  return j;
}

/// The document in the contract's key order.
ordered ordered_document(const Sidecar& s) {
  ordered doc;
  doc["format"] = kSidecarFormat;
  doc["version"] = kSidecarVersion;
  ordered video;
  video["path"] = s.video.path;
  video["fps"] = s.video.fps;
  video["frames"] = s.video.frames;
  video["width"] = s.video.width;
  video["height"] = s.video.height;
  if (s.video.layout) video["layout"] = std::string(effects::stereo_mode_name(*s.video.layout));
  if (s.video.coverage_deg) video["coverage"] = *s.video.coverage_deg;
  doc["video"] = std::move(video);
  doc["interpolation"] = interpolation_json(s.interpolation);
  ordered effects_json = ordered::array();
  for (const effects::EffectTrack& track : s.effects) {
    const effects::EffectSpec& spec = effects::effect_spec(track.type);
    ordered e;
    e["type"] = std::string(spec.name);
    detail::write_anchor(e, track.anchor);
    if (track.interpolation) e["interpolation"] = interpolation_json(*track.interpolation);
    ordered kfs = ordered::array();
    for (const effects::Keyframe& k : track.keyframes)
      kfs.push_back(keyframe_to_json(k, params_to_json(track.type, k.params)));
    e["keyframes"] = std::move(kfs);
    effects_json.push_back(std::move(e));
  }
  for (const effects::FlareEffect& f : s.flares) effects_json.push_back(flare_to_json(f));
  for (const effects::GrainEffect& g : s.grains) effects_json.push_back(grain_to_json(g));
  doc["effects"] = std::move(effects_json);
  // After the effects: a camera holds one line group per frame, and a reader looks for the
  // effects first.
  if (s.camera) doc["camera"] = detail::camera_to_json(*s.camera);
  if (!s.tracks.empty()) doc["tracks"] = detail::tracks_to_json(s.tracks);
  return doc;
}

}  // namespace

nlohmann::ordered_json keyframe_to_json(const effects::Keyframe& k, nlohmann::ordered_json params) {
  ordered kj;
  kj["azimuth_deg"] = k.direction.azimuth_deg;
  kj["altitude_deg"] = k.direction.altitude_deg;
  kj["frame"] = k.frame;
  kj["params"] = std::move(params);
  return kj;
}

nlohmann::ordered_json scalar_keyframes_to_json(const std::vector<effects::Keyframe>& keyframes,
                                                std::span<const effects::ParamSpec> specs) {
  ordered kfs = ordered::array();
  for (const effects::Keyframe& k : keyframes) {
    ordered params;
    for (std::size_t j = 0; j < specs.size(); ++j)
      params[std::string(specs[j].name)] = j < k.params.size() ? k.params[j] : specs[j].neutral;
    kfs.push_back(keyframe_to_json(k, std::move(params)));
  }
  return kfs;
}

nlohmann::ordered_json interpolation_to_json(const effects::InterpolationSettings& s) {
  return interpolation_json(s);
}

nlohmann::ordered_json params_to_json(effects::EffectType type, std::span<const double> values) {
  const effects::EffectSpec& spec = effects::effect_spec(type);
  ordered params = ordered::object();
  std::size_t offset = 0;
  for (const effects::ParamSpec& ps : spec.params) {
    const auto at = [&](std::size_t i) {
      // A malformed in-memory vector (wrong length) is written as neutral rather than read out
      // of bounds; the reader would then flag nothing, so callers validate.
      return offset + i < values.size() ? values[offset + i] : ps.neutral;
    };
    if (ps.size == 1) {
      params[std::string(ps.name)] = at(0);
    } else {
      ordered arr = ordered::array();
      for (int i = 0; i < ps.size; ++i) arr.push_back(at(static_cast<std::size_t>(i)));
      params[std::string(ps.name)] = std::move(arr);
    }
    offset += static_cast<std::size_t>(ps.size);
  }
  return params;
}

Sidecar read_sidecar(const std::filesystem::path& path) {
  SidecarReport report = validate_sidecar_file(path);
  if (!report.ok()) {
    std::string msg = report.to_string();
    if (!msg.empty() && msg.back() == '\n') msg.pop_back();
    throw InputError(msg);
  }
  return std::move(*report.sidecar);
}

nlohmann::json to_json(const Sidecar& sidecar) {
  return nlohmann::json(ordered_document(sidecar));
}

std::string format_sidecar(const Sidecar& sidecar) {
  return ordered_document(sidecar).dump(2) + "\n";
}

void write_sidecar(const std::filesystem::path& path, const Sidecar& sidecar) {
  write_file_atomic(path, format_sidecar(sidecar));
}

int rename_track(Sidecar& s, const std::string& from, const std::string& to,
                 const std::string& file) {
  const auto named = [&s](const std::string& n) {
    return std::find_if(s.tracks.begin(), s.tracks.end(),
                        [&n](const effects::SubjectTrack& t) { return t.name == n; });
  };
  const auto it = named(from);
  if (it == s.tracks.end()) {
    std::string names;
    for (const effects::SubjectTrack& t : s.tracks) names += (names.empty() ? "" : ", ") + t.name;
    throw InputError(file + ": /tracks: no track named '" + from + "' (" +
                     (names.empty() ? "it has none" : "it has " + names) + ")");
  }
  if (const auto taken = named(to); taken != s.tracks.end())
    throw InputError(file + ": /tracks/" + std::to_string(taken - s.tracks.begin()) +
                     "/name: a track named '" + to + "' is already there");
  it->name = to;
  int renamed = 0;
  const auto rename = [&](effects::Anchor& a) {
    if (a.kind != effects::Anchor::Kind::Track || a.track != from) return;
    a.track = to;
    ++renamed;
  };
  for (effects::EffectTrack& e : s.effects) rename(e.anchor);
  for (effects::FlareEffect& f : s.flares) rename(f.anchor);
  for (effects::GrainEffect& g : s.grains) rename(g.anchor);
  return renamed;
}

Sidecar new_sidecar(VideoInfo video) {
  Sidecar s;
  s.video = std::move(video);
  s.interpolation.time_scale = effects::kAuthorTimeScale;
  return s;
}

}  // namespace vdfx::io
