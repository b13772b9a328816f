/// @file
/// @brief Reading, writing and cross-checking the sidecar's camera, tracks and anchors.
#include "io/sidecar_anchor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace vdfx::io::detail {

namespace {

/// A quaternion is unit when its length is within this of 1 (a writer normalises in double;
/// hand-written files with 6 decimals stay well inside).
constexpr double kUnitTolerance = 1e-6;
/// Problems listed per array before the rest are counted in one line (a camera of 100,000
/// frames, all wrong, is one mistake).
constexpr std::size_t kProblemsPerArray = 10;

/// Counts the problems an array's items add and, past kProblemsPerArray, keeps only a total.
class ArrayProblems {
 public:
  ArrayProblems(Checker& c, std::string ptr) : c_(c), ptr_(std::move(ptr)) {}
  /// Whether item checks should still report (false: count only).
  bool reporting() const { return items_ < kProblemsPerArray; }
  void item_had_problem() { ++items_; }
  void finish() {
    if (items_ > kProblemsPerArray)
      c_.error(ptr_, std::to_string(items_ - kProblemsPerArray) +
                         " more items with problems (the first " +
                         std::to_string(kProblemsPerArray) + " are listed)");
  }

 private:
  Checker& c_;
  std::string ptr_;
  std::size_t items_ = 0;
};

std::string frames_text(std::optional<std::int64_t> frames) {
  return frames ? "[0, " + std::to_string(*frames) + ") (video.frames is " +
                      std::to_string(*frames) + ")"
                : std::string("[0, video.frames)");
}

/// One [w, x, y, z]; false (reported when `report`) when it is not four finite numbers of unit
/// length.
bool read_quat(Checker& c, const json& v, const std::string& ptr, bool report, effects::Quat& out) {
  std::vector<Problem> scratch;
  Checker quiet("", scratch);
  Checker& use = report ? c : quiet;
  if (!v.is_array() || v.size() != 4) {
    use.error(ptr, std::string("expected a quaternion [w, x, y, z], found ") +
                       (v.is_array() ? "an array of " + std::to_string(v.size()) : type_name(v)));
    return false;
  }
  const Range any{-std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), false,
                  false};
  for (std::size_t i = 0; i < 4; ++i) {
    const auto d = use.number(v[i], ptr + "/" + std::to_string(i), any);
    if (!d) return false;
    out[i] = *d;
  }
  const double len =
      std::sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2] + out[3] * out[3]);
  if (std::abs(len - 1.0) > kUnitTolerance) {
    use.error(ptr, "not a unit quaternion (length " + num(len) + ")");
    return false;
  }
  return true;
}

void read_point(Checker& c, const json& v, const std::string& ptr,
                std::optional<std::int64_t> frames, effects::TrackPoint& out) {
  const json* obj = c.object(v, ptr);
  if (!obj) return;
  c.only_keys(*obj, ptr, {"frame", "azimuth_deg", "altitude_deg", "confidence"});
  if (const json* p = c.member(*obj, ptr, "frame"))
    if (auto i = c.integer(*p, ptr + "/frame", 0,
                           frames ? *frames - 1 : std::numeric_limits<std::int64_t>::max(),
                           frames_text(frames)))
      out.frame = *i;
  if (const json* p = c.member(*obj, ptr, "azimuth_deg"))
    if (auto d = c.number(*p, ptr + "/azimuth_deg", {-180.0, 180.0, true, false}))
      out.direction.azimuth_deg = *d;
  if (const json* p = c.member(*obj, ptr, "altitude_deg"))
    if (auto d = c.number(*p, ptr + "/altitude_deg", {-90.0, 90.0, false, false}))
      out.direction.altitude_deg = *d;
  if (const json* p = c.member(*obj, ptr, "confidence"))
    if (auto d = c.number(*p, ptr + "/confidence", {0.0, 1.0, false, false})) out.confidence = *d;
}

void read_track(Checker& c, const json& v, const std::string& ptr,
                std::optional<std::int64_t> frames, std::set<std::string>& names,
                effects::SubjectTrack& out) {
  const json* obj = c.object(v, ptr);
  if (!obj) return;
  c.only_keys(*obj, ptr, {"name", "points"});
  if (const json* p = c.member(*obj, ptr, "name"))
    if (auto s = c.string(*p, ptr + "/name")) {
      if (!effects::valid_track_name(*s))
        c.error(ptr + "/name",
                "track name \"" + excerpt(*s) + "\" is not 1 to 64 of A-Z, a-z, 0-9, '_' and '-'");
      else if (!names.insert(*s).second)
        c.error(ptr + "/name", "a second track named \"" + *s + "\" (names are unique)");
      out.name = *s;
    }
  const json* p = c.member(*obj, ptr, "points");
  if (!p) return;
  const std::string pp = ptr + "/points";
  if (!p->is_array() || p->empty()) {
    c.error(pp, std::string("expected a non-empty array of points, found ") +
                    (p->is_array() ? "an empty one" : type_name(*p)));
    return;
  }
  out.points.resize(p->size());
  ArrayProblems problems(c, pp);
  for (std::size_t i = 0; i < p->size(); ++i) {
    const std::size_t before = c.problems();
    const std::string ip = pp + "/" + std::to_string(i);
    read_point(c, (*p)[i], ip, frames, out.points[i]);
    if (c.problems() == before && i > 0 && out.points[i].frame != out.points[i - 1].frame + 1)
      c.error(ip + "/frame", "frame " + std::to_string(out.points[i].frame) + " after frame " +
                                 std::to_string(out.points[i - 1].frame) +
                                 ": a track has one point per frame over a contiguous span");
    if (c.problems() != before) {
      problems.item_had_problem();
      if (!problems.reporting()) break;
    }
  }
  problems.finish();
}

}  // namespace

void read_anchor(Checker& c, const json& entry, const std::string& ptr, effects::Anchor& out) {
  const json* p = c.member(entry, ptr, "anchor", /*required=*/false);
  if (!p) return;
  const auto s = c.string(*p, ptr + "/anchor");
  if (!s) return;
  if (const auto a = effects::parse_anchor(*s))
    out = *a;
  else
    c.error(ptr + "/anchor", "unknown anchor \"" + excerpt(*s) +
                                 "\" (expected video, world or track:NAME, NAME 1 to 64 of "
                                 "A-Z, a-z, 0-9, '_' and '-')");
}

void write_anchor(nlohmann::ordered_json& entry, const effects::Anchor& anchor) {
  if (!anchor.is_video()) entry["anchor"] = effects::anchor_name(anchor);
}

void read_camera(Checker& c, const json& v, std::optional<std::int64_t> frames,
                 std::optional<effects::CameraMotion>& out) {
  const std::string ptr = "/camera";
  const json* obj = c.object(v, ptr);
  if (!obj) return;
  c.only_keys(*obj, ptr, {"source", "orientation"});
  effects::CameraMotion camera;
  if (const json* p = c.member(*obj, ptr, "source"))
    if (auto s = c.string(*p, ptr + "/source")) {
      if (const auto source = effects::parse_camera_source(*s))
        camera.source = *source;
      else
        c.error(ptr + "/source",
                "unknown source \"" + excerpt(*s) + "\" (expected estimated, camm or given)");
    }
  const json* p = c.member(*obj, ptr, "orientation");
  if (!p) return;
  const std::string op = ptr + "/orientation";
  if (!p->is_array()) {
    c.error(op, std::string("expected an array of quaternions, found ") + type_name(*p));
    return;
  }
  if (frames && p->size() != static_cast<std::size_t>(*frames)) {
    c.error(op, std::to_string(p->size()) + " orientations for a video of " +
                    std::to_string(*frames) + " frames (video.frames): one per frame");
    return;
  }
  camera.orientation.resize(p->size());
  ArrayProblems problems(c, op);
  for (std::size_t i = 0; i < p->size(); ++i)
    if (!read_quat(c, (*p)[i], op + "/" + std::to_string(i), problems.reporting(),
                   camera.orientation[i]))
      problems.item_had_problem();
  problems.finish();
  out = std::move(camera);
}

void read_tracks(Checker& c, const json& v, std::optional<std::int64_t> frames,
                 std::vector<effects::SubjectTrack>& out) {
  if (!v.is_array()) {
    c.error("/tracks", std::string("expected an array, found ") + type_name(v));
    return;
  }
  std::set<std::string> names;
  out.resize(v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    read_track(c, v[i], "/tracks/" + std::to_string(i), frames, names, out[i]);
}

void check_anchors(Checker& c, const Sidecar& s, const std::vector<AnchorAt>& anchors) {
  for (const AnchorAt& at : anchors) {
    const std::string& ptr = at.first;
    const effects::Anchor& a = at.second;
    if (a.kind == effects::Anchor::Kind::World && !s.camera)
      c.error(ptr,
              "anchor \"world\" needs the camera's orientation at every frame, and the "
              "sidecar has no camera section (vdfx track camera records it)");
    if (a.kind == effects::Anchor::Kind::Track &&
        std::none_of(s.tracks.begin(), s.tracks.end(),
                     [&](const effects::SubjectTrack& t) { return t.name == a.track; }))
      c.error(ptr, "anchor \"" + effects::anchor_name(a) + "\" names no track in /tracks (vdfx " +
                       "track subject --name " + a.track + " records one)");
  }
}

nlohmann::ordered_json camera_to_json(const effects::CameraMotion& camera) {
  nlohmann::ordered_json j;
  j["source"] = effects::camera_source_name(camera.source);
  nlohmann::ordered_json q = nlohmann::ordered_json::array();
  for (const effects::Quat& o : camera.orientation) q.push_back({o[0], o[1], o[2], o[3]});
  j["orientation"] = std::move(q);
  return j;
}

nlohmann::ordered_json tracks_to_json(const std::vector<effects::SubjectTrack>& tracks) {
  nlohmann::ordered_json all = nlohmann::ordered_json::array();
  for (const effects::SubjectTrack& t : tracks) {
    nlohmann::ordered_json j;
    j["name"] = t.name;
    nlohmann::ordered_json points = nlohmann::ordered_json::array();
    for (const effects::TrackPoint& p : t.points) {
      nlohmann::ordered_json pj;
      pj["frame"] = p.frame;
      pj["azimuth_deg"] = p.direction.azimuth_deg;
      pj["altitude_deg"] = p.direction.altitude_deg;
      pj["confidence"] = p.confidence;
      points.push_back(std::move(pj));
    }
    j["points"] = std::move(points);
    all.push_back(std::move(j));
  }
  return all;
}

}  // namespace vdfx::io::detail
