/// @file
/// @brief Document: the sidecar's camera and subject tracks (what anchors turn by) as undo steps,
/// and each effect's anchor.
#include <algorithm>
#include <utility>

#include "app/editor/document.h"
#include "io/input_error.h"

namespace vdfx::app {

namespace {
/// Throws io::InputError for a name a track may not have.
void check_track_name(const std::string& name) {
  if (!effects::valid_track_name(name))
    throw io::InputError("tracks: '" + name + "' is not a track name ([A-Za-z0-9_-]{1,64})");
}
}  // namespace

const effects::SubjectTrack* Document::track(std::string_view name) const {
  for (const effects::SubjectTrack& t : tracks_)
    if (t.name == name) return &t;
  return nullptr;
}

void Document::set_camera(effects::CameraMotion camera) {
  if (static_cast<std::int64_t>(camera.orientation.size()) != video_.frames)
    throw io::InputError("camera: " + std::to_string(camera.orientation.size()) +
                         " orientations for a video of " + std::to_string(video_.frames) +
                         " frames");
  if (camera_ == camera) return;
  SourcesSnapshot before = sources();
  camera_ = std::move(camera);
  resolve_anchors();
  record("track camera", std::move(before));
}

void Document::put_track(effects::SubjectTrack track) {
  check_track_name(track.name);
  if (track.points.empty()) throw io::InputError("tracks/" + track.name + ": no points");
  for (const effects::TrackPoint& p : track.points)
    if (p.frame < 0 || p.frame >= video_.frames)
      throw io::InputError("tracks/" + track.name + ": frame " + std::to_string(p.frame) +
                           " is outside the video's " + std::to_string(video_.frames) + " frames");
  SourcesSnapshot before = sources();
  const auto same = [&](const effects::SubjectTrack& t) { return t.name == track.name; };
  const auto it = std::find_if(tracks_.begin(), tracks_.end(), same);
  const std::string label = (it == tracks_.end() ? "track " : "re-track ") + track.name;
  if (it == tracks_.end())
    tracks_.push_back(std::move(track));
  else if (*it == track)
    return;
  else
    *it = std::move(track);
  resolve_anchors();
  record(label, std::move(before));
}

int Document::remove_track(const std::string& name) {
  const auto named = [&](const effects::SubjectTrack& t) { return t.name == name; };
  if (std::none_of(tracks_.begin(), tracks_.end(), named))
    throw io::InputError("tracks: there is no track named " + name);
  const std::string label = "delete track " + name;
  return one_step(label, [&] {
    const std::vector<EditTarget> anchored = anchored_to(name);
    for (const EditTarget t : anchored) set_anchor(t, effects::Anchor{});
    SourcesSnapshot before = sources();
    tracks_.erase(std::find_if(tracks_.begin(), tracks_.end(), named));
    resolve_anchors();
    record(label, std::move(before));
    return static_cast<int>(anchored.size());
  });
}

int Document::rename_track(const std::string& from, const std::string& to) {
  if (!track(from)) throw io::InputError("tracks: there is no track named " + from);
  check_track_name(to);
  if (track(to)) throw io::InputError("tracks: a track named " + to + " is already there");
  const std::string label = "rename track " + from + " to " + to;
  return one_step(label, [&] {
    // The new name beside the old for a moment, so that every anchor resolves at every step.
    SourcesSnapshot before = sources();
    effects::SubjectTrack renamed = *track(from);
    renamed.name = to;
    tracks_.push_back(std::move(renamed));
    record(label, std::move(before));
    const std::vector<EditTarget> anchored = anchored_to(from);
    for (const EditTarget t : anchored) {
      EffectSnapshot was = snapshot(t);
      anchors_[idx(t)].track = to;  // the same rotations: no keyframe moves
      resolve_anchors();
      record(std::string(t.name()) + " anchor", t, std::move(was));
    }
    before = sources();
    const auto old = std::find_if(tracks_.begin(), tracks_.end(),
                                  [&](const effects::SubjectTrack& s) { return s.name == from; });
    *old = std::move(tracks_.back());  // in the old one's place
    tracks_.pop_back();
    resolve_anchors();
    record(label, std::move(before));
    return static_cast<int>(anchored.size());
  });
}

std::vector<EditTarget> Document::anchored_to(const std::string& track_name) const {
  std::vector<EditTarget> out;
  for (const EditTarget t : all_edit_targets()) {
    const effects::Anchor& a = anchors_[idx(t)];
    if (a.kind == effects::Anchor::Kind::Track && a.track == track_name) out.push_back(t);
  }
  return out;
}

int Document::one_step(const std::string& label, const std::function<int()>& body) {
  begin_group(label);
  int result = 0;
  try {
    result = body();
  } catch (...) {
    end_group();
    throw;
  }
  end_group();
  undo_.rename_last(label);
  return result;
}

void Document::restore(const SourcesSnapshot& s) {
  camera_ = s.camera;
  tracks_ = s.tracks;
  if (!restoring_step_) resolve_anchors();
}

void Document::record(const std::string& label, SourcesSnapshot before) {
  undo_.push(label, SourcesChange{std::move(before), sources()});
  changed();
}

effects::AnchorSources Document::anchor_sources() const {
  return {camera_ ? &*camera_ : nullptr, tracks_};
}

void Document::resolve_anchors() {
  effects::AnchorResolver resolve(anchor_sources());
  for (const EditTarget t : all_edit_targets()) {
    try {
      frames_[idx(t)] = resolve.resolve(anchors_[idx(t)]).frames;
    } catch (const std::invalid_argument& e) {
      throw io::InputError(std::string(t.name()) + ": " + e.what());
    }
  }
}

void Document::set_anchor(EditTarget t, const effects::Anchor& anchor) {
  if (anchor == anchors_[idx(t)]) return;
  effects::AnchorFrames to;
  try {
    to = effects::anchor_frames(anchor, camera_ ? &*camera_ : nullptr, tracks_);
  } catch (const std::invalid_argument& e) {
    throw io::InputError(std::string(t.name()) + ": " + e.what());
  }
  auto before = snapshot(t);
  const effects::AnchorFrames from = frames_[idx(t)];
  std::vector<effects::Keyframe> keyframes = sets_[idx(t)]->keyframes();
  for (effects::Keyframe& k : keyframes)
    k.direction = to.apply(from.unapply(k.direction, k.frame), k.frame);
  if (t.is_flare() && flare_)
    if (auto* light = std::get_if<effects::Direction>(&flare_->light))
      *light = to.apply(from.unapply(*light, 0), 0);
  anchors_[idx(t)] = anchor;
  resolve_anchors();
  rebuild(t, std::move(keyframes));
  record(std::string(t.name()) + " anchor", t, std::move(before));
}

}  // namespace vdfx::app
