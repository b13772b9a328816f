/// @file
/// @brief parse_sidecar and the validate_* entry points. Effect parameters are checked from the
/// effect specs (effects/effect_types.h), never by per-effect code, so a new effect type needs
/// no change here.
#include "io/sidecar_validate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "effects/interpolation_check.h"
#include "effects/rbf_windows.h"
#include "io/excerpt.h"
#include "io/input_file.h"
#include "io/json_text.h"
#include "io/sidecar_anchor.h"
#include "io/sidecar_checker.h"
#include "io/sidecar_flare.h"
#include "io/sidecar_grain.h"

namespace vdfx::io {

using nlohmann::json;
using namespace detail;

std::string Problem::to_string() const {
  return file + ": " + (pointer.empty() ? std::string("(document)") : pointer) + ": " + message;
}

std::string SidecarReport::to_string() const {
  std::string s;
  for (const Problem& p : problems) s += p.to_string() + "\n";
  return s;
}

namespace {

/// A derived value for messages: three significant digits ("2.4e+201", "0.8").
std::string short_num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

constexpr std::int64_t kIntMax = std::numeric_limits<int>::max();
constexpr double kDoubleMax = std::numeric_limits<double>::max();
const Range kAnyNumber{-kDoubleMax, kDoubleMax, false, false};  // finite: Checker::number

/// "layout" and "coverage" (optional: old files are mono 360); the layout must split the
/// recorded frame size into two whole halves.
void read_stereo(Checker& c, const json& obj, const std::string& ptr, VideoInfo& out) {
  if (const json* p = c.member(obj, ptr, "layout", false)) {
    if (auto s = c.string(*p, ptr + "/layout")) {
      out.layout = effects::stereo_mode_from_name(*s);
      if (!out.layout)
        c.error(ptr + "/layout", "unknown layout \"" + excerpt(*s) +
                                     "\" (expected: mono, top-bottom, left-right, right-left)");
    }
  }
  if (const json* p = c.member(obj, ptr, "coverage", false)) {
    if (auto i = c.integer(*p, ptr + "/coverage", std::numeric_limits<std::int64_t>::min(),
                           std::numeric_limits<std::int64_t>::max(), "360 or 180")) {
      if (*i == 360 || *i == 180)
        out.coverage_deg = static_cast<int>(*i);
      else
        c.error(ptr + "/coverage", "coverage " + std::to_string(*i) +
                                       (*i <= 0 ? " covers nothing" : " is not supported") +
                                       ": expected 360 or 180 (degrees of azimuth)");
    }
  }
  if (const auto problem = effects::layout_problem(
          {out.layout.value_or(effects::StereoMode::Mono), 360}, out.width, out.height);
      problem && out.layout)
    c.error(ptr + "/layout", *problem + " (video.width and video.height)");
}

void read_video(Checker& c, const json& v, const std::string& ptr, VideoInfo& out) {
  const json* obj = c.object(v, ptr);
  if (!obj) return;
  c.only_keys(*obj, ptr, {"path", "fps", "frames", "width", "height", "layout", "coverage"});
  if (const json* p = c.member(*obj, ptr, "path")) {
    if (auto s = c.string(*p, ptr + "/path")) {
      if (s->empty()) c.error(ptr + "/path", "empty path");
      out.path = *s;
    }
  }
  if (const json* p = c.member(*obj, ptr, "fps"))
    if (auto d = c.number(*p, ptr + "/fps", {0.0, std::numeric_limits<double>::max(), true, false}))
      out.fps = *d;
  if (const json* p = c.member(*obj, ptr, "frames"))
    if (auto i = c.integer(*p, ptr + "/frames", 1, std::numeric_limits<std::int64_t>::max(),
                           "[1, 2^63)"))
      out.frames = *i;
  const std::string int_range = "[1, " + std::to_string(kIntMax) + "]";
  if (const json* p = c.member(*obj, ptr, "width"))
    if (auto i = c.integer(*p, ptr + "/width", 1, kIntMax, int_range))
      out.width = static_cast<int>(*i);
  if (const json* p = c.member(*obj, ptr, "height"))
    if (auto i = c.integer(*p, ptr + "/height", 1, kIntMax, int_range))
      out.height = static_cast<int>(*i);
  read_stereo(c, *obj, ptr, out);
}

void read_interpolation(Checker& c, const json& v, const std::string& ptr,
                        effects::InterpolationSettings& out) {
  const json* obj = c.object(v, ptr);
  if (!obj) return;
  c.only_keys(*obj, ptr, {"exponent", "time_scale", "distance", "outside_span", "reach_s"});
  // The ranges are effects/interpolation_check.h's: the RBF kernel and the editor ask it too.
  if (const json* p = c.member(*obj, ptr, "exponent"))
    if (auto d = c.number(*p, ptr + "/exponent", kAnyNumber)) {
      if (auto why = effects::exponent_problem(*d))
        c.error(ptr + "/exponent", *why);
      else
        out.exponent = *d;
    }
  if (const json* p = c.member(*obj, ptr, "time_scale"))
    if (auto d = c.number(*p, ptr + "/time_scale", kAnyNumber)) {
      if (auto why = effects::time_scale_problem(*d))
        c.error(ptr + "/time_scale", *why);
      else
        out.time_scale = *d;
    }
  // Extension of format 1: optional, automatic when absent (docs/sidecar.md).
  if (const json* p = c.member(*obj, ptr, "reach_s", /*required=*/false))
    if (auto d = c.number(*p, ptr + "/reach_s", kAnyNumber)) {
      if (auto why = effects::reach_problem(*d))
        c.error(ptr + "/reach_s", *why);
      else
        out.reach_s = *d;
    }
  // Extension of format 1: optional, chordal when absent (docs/sidecar.md).
  if (const json* p = c.member(*obj, ptr, "distance", /*required=*/false)) {
    if (auto s = c.string(*p, ptr + "/distance")) {
      if (*s == "chordal")
        out.distance = effects::AngularDistance::Chordal;
      else if (*s == "geodesic")
        out.distance = effects::AngularDistance::Geodesic;
      else
        c.error(ptr + "/distance",
                "unknown distance \"" + excerpt(*s) + "\" (expected chordal or geodesic)");
    }
  }
  // Extension of format 1: optional, hold when absent (docs/sidecar.md).
  if (const json* p = c.member(*obj, ptr, "outside_span", /*required=*/false)) {
    if (auto s = c.string(*p, ptr + "/outside_span")) {
      if (*s == "hold")
        out.outside = effects::TimeOutside::Hold;
      else if (*s == "extrapolate")
        out.outside = effects::TimeOutside::Extrapolate;
      else
        c.error(ptr + "/outside_span",
                "unknown value \"" + excerpt(*s) + "\" (expected hold or extrapolate)");
    }
  }
}

/// Reads params against the effect's spec: exactly the spec's names, arrays of the spec's size.
void read_params(Checker& c, const json& v, const std::string& ptr, const effects::EffectSpec& spec,
                 std::vector<double>& out) {
  out = spec.neutral();
  const json* obj = c.object(v, ptr);
  if (!obj) return;
  for (const auto& [k, _] : obj->items()) {
    bool known = false;
    std::string names;
    for (const auto& ps : spec.params) {
      known = known || ps.name == k;
      names += (names.empty() ? "" : ", ") + std::string(ps.name);
    }
    if (!known)
      c.error(ptr + "/" + excerpt(json_pointer_token(k)),
              "unknown parameter \"" + excerpt(k) + "\" for effect " + std::string(spec.name) +
                  " (expected: " + names + ")");
  }
  std::size_t offset = 0;
  for (const auto& ps : spec.params) {
    const std::string name(ps.name);
    const std::string pp = ptr + "/" + json_pointer_token(name);
    const Range range{ps.min, ps.max, false, false};
    if (const json* p = c.member(*obj, ptr, name.c_str())) {
      if (ps.size == 1) {
        if (auto d = c.number(*p, pp, range)) out[offset] = *d;
      } else if (!p->is_array()) {
        c.error(pp, "expected an array of " + std::to_string(ps.size) + " numbers, found " +
                        type_name(*p));
      } else if (p->size() != static_cast<std::size_t>(ps.size)) {
        c.error(pp, "expected an array of " + std::to_string(ps.size) + " numbers, found " +
                        std::to_string(p->size()));
      } else {
        for (int i = 0; i < ps.size; ++i)
          if (auto d =
                  c.number((*p)[static_cast<std::size_t>(i)], pp + "/" + std::to_string(i), range))
            out[offset + static_cast<std::size_t>(i)] = *d;
      }
    }
    offset += static_cast<std::size_t>(ps.size);
  }
}

void read_keyframe(Checker& c, const json& v, const std::string& ptr,
                   const effects::EffectSpec* spec, std::optional<std::int64_t> frames,
                   effects::Keyframe& out) {
  const json* obj = c.object(v, ptr);
  if (!obj) return;
  c.only_keys(*obj, ptr, {"azimuth_deg", "altitude_deg", "frame", "params"});
  if (const json* p = c.member(*obj, ptr, "azimuth_deg"))
    if (auto d = c.number(*p, ptr + "/azimuth_deg", {-180.0, 180.0, true, false}))
      out.direction.azimuth_deg = *d;
  if (const json* p = c.member(*obj, ptr, "altitude_deg"))
    if (auto d = c.number(*p, ptr + "/altitude_deg", {-90.0, 90.0, false, false}))
      out.direction.altitude_deg = *d;
  if (const json* p = c.member(*obj, ptr, "frame")) {
    // Without a valid frame count only the lower bound can be checked.
    const std::int64_t hi = frames ? *frames - 1 : std::numeric_limits<std::int64_t>::max();
    const std::string text = frames ? "[0, " + std::to_string(*frames) + ") (video.frames is " +
                                          std::to_string(*frames) + ")"
                                    : std::string("[0, video.frames)");
    if (auto i = c.integer(*p, ptr + "/frame", 0, hi, text)) out.frame = *i;
  }
  if (const json* p = c.member(*obj, ptr, "params")) {
    if (spec)
      read_params(c, *p, ptr + "/params", *spec, out.params);
    else
      c.object(*p, ptr + "/params");
  }
}

std::string known_types() {
  std::string s;
  for (const auto& spec : effects::all_effect_specs())
    s += (s.empty() ? "" : ", ") + std::string(spec.name);
  return s + ", " + kFlareTypeName + ", " + kGrainTypeName;
}

void read_effect(Checker& c, const json& v, const std::string& ptr,
                 std::optional<std::int64_t> frames,
                 std::map<effects::EffectType, std::string>& seen, effects::EffectTrack& out) {
  const json* obj = c.object(v, ptr);
  if (!obj) return;
  c.only_keys(*obj, ptr, {"type", "anchor", "interpolation", "keyframes"});
  read_anchor(c, *obj, ptr, out.anchor);
  const effects::EffectSpec* spec = nullptr;
  if (const json* p = c.member(*obj, ptr, "type")) {
    if (auto s = c.string(*p, ptr + "/type")) {
      if (auto t = effects::effect_type_from_name(*s)) {
        spec = &effects::effect_spec(*t);
        out.type = *t;
        if (auto [it, inserted] = seen.emplace(*t, ptr); !inserted)
          c.error(ptr + "/type", "effect type \"" + excerpt(*s) + "\" appears twice (first at " +
                                     it->second + "); each effect has one keyframe set");
      } else {
        c.error(ptr + "/type",
                "unknown effect type \"" + excerpt(*s) + "\" (known: " + known_types() + ")");
      }
    }
  }
  read_interpolation_override(c, *obj, ptr, out.interpolation);
  if (const json* p = c.member(*obj, ptr, "keyframes")) {
    const std::string kp = ptr + "/keyframes";
    if (!p->is_array()) {
      c.error(kp, std::string("expected an array, found ") + type_name(*p));
      return;
    }
    if (!keyframe_count_ok(c, *p, kp)) return;
    out.keyframes.resize(p->size());
    for (std::size_t i = 0; i < p->size(); ++i)
      read_keyframe(c, (*p)[i], kp + "/" + std::to_string(i), spec, frames, out.keyframes[i]);
  }
}

/// True when some problem was reported at `ptr` or below it.
bool has_problem_at(const std::vector<Problem>& problems, std::size_t first,
                    const std::string& ptr) {
  for (std::size_t i = first; i < problems.size(); ++i)
    if (problems[i].pointer == ptr || problems[i].pointer.rfind(ptr + "/", 0) == 0) return true;
  return false;
}

/// An entry's own interpolation settings and where they are ("/effects/3/interpolation").
using Override = std::pair<std::string, effects::InterpolationSettings>;

/// The values the maths derives from fps, frames and time_scale must stay finite and usable:
/// one frame is 24 / fps * time_scale apart in the RBF distance (contract). Checked for the
/// file's interpolation and each entry's own (effects, flares, grains), once those fields are
/// themselves valid.
void check_time_scaling(Checker& c, const Sidecar& s, const std::vector<Override>& overrides,
                        const std::vector<Problem>& problems, std::size_t first) {
  if (has_problem_at(problems, first, "/video/fps") ||
      has_problem_at(problems, first, "/video/frames") || s.video.frames < 2)
    return;  // one frame: there is no time axis to scale
  const double gaps = static_cast<double>(s.video.frames - 1);
  const auto check = [&](const effects::InterpolationSettings& in, const std::string& ptr,
                         bool own) {
    if (has_problem_at(problems, first, ptr)) return;
    const double step = 24.0 / s.video.fps * in.time_scale;
    const double span = gaps * step;
    // The remedy names the value at the pointer: fps for the file's interpolation, the
    // effect's own time_scale for an override.
    const std::string blame = own ? ptr + "/time_scale" : "/video/fps";
    const std::string what =
        "one frame is 24 / fps * time_scale = " + short_num(step) + " apart in the RBF distance";
    if (!(span <= kMaxScaledTimeSpan)) {  // also catches inf and NaN
      const std::string fix = own ? "time_scale must be at most " +
                                        short_num(kMaxScaledTimeSpan * s.video.fps / (24.0 * gaps))
                                  : "fps must be at least " +
                                        short_num(24.0 * in.time_scale * gaps / kMaxScaledTimeSpan);
      c.error(blame, what + ", the clip's " + std::to_string(s.video.frames) + " frames " +
                         short_num(span) + ": beyond " + short_num(kMaxScaledTimeSpan) +
                         ", where its distances overflow (" + fix + ")");
    } else if (!(step >= kMinScaledFrameStep)) {
      const std::string fix =
          own ? "time_scale must be at least " + short_num(kMinScaledFrameStep * s.video.fps / 24.0)
              : "fps must be at most " + short_num(24.0 * in.time_scale / kMinScaledFrameStep);
      c.error(blame, what + ": below " + short_num(kMinScaledFrameStep) +
                         ", where keyframes one frame apart are no longer told apart (" + fix +
                         ")");
    }
  };
  check(s.interpolation, "/interpolation", false);
  for (const auto& [ptr, settings] : overrides) check(settings, ptr, true);
}

/// Where an entry is ("/effects/3") and what it is: 0 a stack effect, 1 a flare, 2 a grain.
using KeyedAt = std::pair<std::string, int>;

/// An entry with keyframes, where it is ("/effects/3") and its own settings, if any.
struct KeyedEntry {
  std::string ptr;
  const std::vector<effects::Keyframe>* keyframes;
  std::optional<effects::InterpolationSettings> own;
};

/// Each entry's keyframes must fit local interpolation's windows (effects/rbf_windows.h: no
/// window holds more keyframes than one dense solve takes), once fps, the settings and the
/// keyframes' frames are themselves valid.
void check_windows(Checker& c, const Sidecar& s, const std::vector<KeyedAt>& keyed,
                   const std::vector<Problem>& problems, std::size_t first) {
  if (has_problem_at(problems, first, "/video/fps") ||
      has_problem_at(problems, first, "/interpolation"))
    return;
  std::vector<KeyedEntry> entries;
  std::size_t next[3] = {0, 0, 0};
  for (const auto& [ptr, kind] : keyed) {
    const std::size_t i = next[kind]++;
    if (kind == 1)
      entries.push_back({ptr, &s.flares[i].keyframes, s.flares[i].interpolation});
    else if (kind == 2)
      entries.push_back({ptr, &s.grains[i].keyframes, s.grains[i].interpolation});
    else
      entries.push_back({ptr, &s.effects[i].keyframes, s.effects[i].interpolation});
  }
  for (const KeyedEntry& e : entries) {
    if (has_problem_at(problems, first, e.ptr)) continue;
    std::vector<std::int64_t> frames;
    frames.reserve(e.keyframes->size());
    for (const effects::Keyframe& k : *e.keyframes) frames.push_back(k.frame);
    std::sort(frames.begin(), frames.end());
    if (const auto why =
            effects::window_problem(e.own.value_or(s.interpolation), s.video.fps, frames))
      c.error(e.ptr + "/keyframes", *why);
  }
}

}  // namespace

namespace detail {

bool keyframe_count_ok(Checker& c, const json& keyframes, const std::string& ptr) {
  if (keyframes.size() <= kMaxKeyframesPerEffect) return true;
  c.error(ptr, std::to_string(keyframes.size()) + " keyframes, more than the " +
                   std::to_string(kMaxKeyframesPerEffect) + " an effect may have");
  return false;
}

void read_interpolation_override(Checker& c, const json& entry, const std::string& ptr,
                                 std::optional<effects::InterpolationSettings>& out) {
  if (const json* p = c.member(entry, ptr, "interpolation", /*required=*/false)) {
    effects::InterpolationSettings s;
    read_interpolation(c, *p, ptr + "/interpolation", s);
    out = s;
  }
}

void read_keyframe_place(Checker& c, const json& v, const std::string& ptr,
                         std::optional<std::int64_t> frames, effects::Keyframe& out) {
  read_keyframe(c, v, ptr, nullptr, frames, out);
}

void read_scalar_keyframes(Checker& c, const json& v, const std::string& ptr,
                           std::optional<std::int64_t> frames,
                           std::span<const effects::ParamSpec> specs,
                           std::vector<effects::Keyframe>& out) {
  if (!v.is_array()) {
    c.error(ptr, std::string("expected an array, found ") + detail::type_name(v));
    return;
  }
  if (!keyframe_count_ok(c, v, ptr)) return;
  std::vector<std::string> names;
  for (const effects::ParamSpec& s : specs) names.emplace_back(s.name);
  out.resize(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string kp = ptr + "/" + std::to_string(i);
    effects::Keyframe& k = out[i];
    read_keyframe_place(c, v[i], kp, frames, k);
    k.params.clear();
    for (const effects::ParamSpec& s : specs) k.params.push_back(s.neutral);
    if (!v[i].is_object()) continue;
    const auto params = v[i].find("params");
    if (params == v[i].end() || !params->is_object()) continue;  // reported above
    const std::string pp = kp + "/params";
    c.only_keys(*params, pp, names);
    for (std::size_t j = 0; j < specs.size(); ++j)
      if (const json* p = c.member(*params, pp, names[j].c_str()))
        if (auto d = c.number(*p, pp + "/" + names[j], {specs[j].min, specs[j].max, false, false}))
          k.params[j] = *d;
  }
}

}  // namespace detail

namespace {

/// What reading the entries gathers for the checks across fields.
struct EntryRefs {
  std::vector<Override> overrides;
  std::vector<KeyedAt> keyed;
  std::vector<AnchorAt> anchors;
};

/// Reads /effects: stack effects, flares and grains, each by its own reader.
void read_entries(Checker& c, const json& entries, std::optional<std::int64_t> frames, Sidecar& out,
                  EntryRefs& refs) {
  if (!entries.is_array()) {
    c.error("/effects", std::string("expected an array, found ") + type_name(entries));
    return;
  }
  std::map<effects::EffectType, std::string> seen;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const std::string ep = "/effects/" + std::to_string(i);
    // Extension types (several may coexist) have readers of their own.
    const std::optional<effects::InterpolationSettings>* own = nullptr;
    const effects::Anchor* anchor = nullptr;
    int kind = 0;
    if (is_flare_entry(entries[i])) {
      read_flare(c, entries[i], ep, frames, out.flares.emplace_back());
      own = &out.flares.back().interpolation;
      anchor = &out.flares.back().anchor;
      kind = 1;
    } else if (is_grain_entry(entries[i])) {
      read_grain(c, entries[i], ep, frames, out.grains.emplace_back());
      own = &out.grains.back().interpolation;
      anchor = &out.grains.back().anchor;
      kind = 2;
    } else {
      read_effect(c, entries[i], ep, frames, seen, out.effects.emplace_back());
      own = &out.effects.back().interpolation;
      anchor = &out.effects.back().anchor;
    }
    if (*own) refs.overrides.emplace_back(ep + "/interpolation", **own);
    refs.keyed.emplace_back(ep, kind);
    if (!anchor->is_video()) refs.anchors.emplace_back(ep + "/anchor", *anchor);
  }
}

}  // namespace

Sidecar parse_sidecar(const json& document, const std::string& file_for_messages,
                      std::vector<Problem>& problems) {
  Sidecar out;
  const std::size_t first_problem = problems.size();
  Checker c(file_for_messages, problems);
  const json* root = c.object(document, "");
  if (!root) return out;
  c.only_keys(*root, "",
              {"format", "version", "video", "interpolation", "effects", "camera", "tracks"});

  // A file that is not a vdfx sidecar at all gets one clear message, not a cascade.
  const json* format = c.member(*root, "", "format");
  if (format) {
    if (auto s = c.string(*format, "/format"); s && *s != kSidecarFormat) {
      c.error("/format",
              "expected \"" + std::string(kSidecarFormat) + "\", found \"" + excerpt(*s) + "\"");
      return out;
    }
  }
  if (const json* p = c.member(*root, "", "version")) {
    if (auto v = c.integer(*p, "/version", kSidecarVersion, kSidecarVersion,
                           "(only version " + std::to_string(kSidecarVersion) + " is known)");
        !v)
      return out;  // another version's fields mean other things: do not guess
  }

  if (const json* p = c.member(*root, "", "video")) read_video(c, *p, "/video", out.video);
  // Keyframe frames are checked against video.frames only when that is itself valid (its own
  // problem is already reported above).
  std::optional<std::int64_t> frames;
  if (const auto v = root->find("video");
      v != root->end() && v->is_object() && v->contains("frames")) {
    std::vector<Problem> scratch;
    Checker quiet(file_for_messages, scratch);
    frames = quiet.integer(v->at("frames"), "", 1, std::numeric_limits<std::int64_t>::max(), "");
  }

  if (const json* p = c.member(*root, "", "interpolation"))
    read_interpolation(c, *p, "/interpolation", out.interpolation);
  // Frames of reference (optional: contract "Frames of reference").
  if (const json* p = c.member(*root, "", "camera", /*required=*/false))
    read_camera(c, *p, frames, out.camera);
  if (const json* p = c.member(*root, "", "tracks", /*required=*/false))
    read_tracks(c, *p, frames, out.tracks);

  EntryRefs refs;
  if (const json* p = c.member(*root, "", "effects")) read_entries(c, *p, frames, out, refs);
  // Checks across fields, each in a function of its own.
  check_time_scaling(c, out, refs.overrides, problems, first_problem);
  check_windows(c, out, refs.keyed, problems, first_problem);
  check_anchors(c, out, refs.anchors);
  return out;
}

SidecarReport validate_sidecar_text(std::string_view text, const std::string& file_for_messages) {
  SidecarReport report;
  JsonText parsed = parse_json_text(text);
  for (const JsonTextError& e : parsed.errors) {
    std::string msg = e.message;
    if (e.line > 0)
      msg = "line " + std::to_string(e.line) + ", column " + std::to_string(e.column) + ": " + msg;
    report.problems.push_back({file_for_messages, e.pointer, msg});
  }
  if (parsed.value.is_discarded()) return report;
  Sidecar s = parse_sidecar(parsed.value, file_for_messages, report.problems);
  if (report.problems.empty()) report.sidecar = std::move(s);
  return report;
}

SidecarReport validate_sidecar_file(const std::filesystem::path& path) {
  std::string why;
  const std::optional<std::string> text =
      try_read_input_file(path, kMaxSidecarBytes, "a sidecar", why);
  if (!text) {
    SidecarReport r;
    r.problems.push_back({path.string(), "", why});
    return r;
  }
  return validate_sidecar_text(*text, path.string());
}

}  // namespace vdfx::io
