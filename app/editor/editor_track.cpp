/// @file
/// @brief The editor's tracking (docs/editor.md, "Tracking"): a subject or the camera tracked on
/// a worker with progress and cancel, its result one undo step; a track corrected from a point
/// dropped at the current frame; the current effect's anchor chosen; a track renamed.
#include <cctype>

#include "app/editor/editor.h"
#include "app/editor/text_format.h"
#include "io/input_error.h"

namespace vdfx::app {

namespace {

const char* job_name(TrackJob::Kind kind) {
  switch (kind) {
    case TrackJob::Kind::Camera: return "camera";
    case TrackJob::Kind::Subject: return "subject";
    case TrackJob::Kind::Correction: return "correct";
  }
  return "";
}

}  // namespace

void Editor::start_tracking(TrackJob job) {
  if (tracking_) {  // pressed again: cancel
    tracking_->cancel();
    return say("cancelling the tracking\u2026");
  }
  if (!options_.video) return say("no video to track");
  job.camera.video = job.subject.video = *options_.video;
  tracking_ =
      std::make_unique<TrackWorker>(std::move(job), doc_.sidecar(), options_.async_suggestions);
  poll_tracking();  // a synchronous one is done already
}

void Editor::track_subject() {
  TrackJob job;
  job.kind = TrackJob::Kind::Subject;
  for (int i = 1; job.subject.name.empty() || doc_.track(job.subject.name); ++i)
    job.subject.name = "subject" + std::to_string(i);
  job.subject.at = view_;
  job.subject.frame = play_.frame;
  start_tracking(std::move(job));
}

void Editor::track_camera() {
  TrackJob job;
  job.kind = TrackJob::Kind::Camera;
  start_tracking(std::move(job));
}

void Editor::correct_track() {
  if (tracking_) return start_tracking({});  // cancels
  const effects::SubjectTrack* shown = shown_track();
  if (!shown) return say("no track to correct: press Track subject first");
  TrackJob job;
  job.kind = TrackJob::Kind::Correction;
  job.subject.name = shown->name;
  job.subject.at = view_;
  job.subject.frame = play_.frame;
  job.subject.replace = true;
  start_tracking(std::move(job));
}

std::optional<double> Editor::tracking_progress() const {
  if (!tracking_) return std::nullopt;
  return tracking_->fraction();
}

bool Editor::wait_for_tracking(std::chrono::milliseconds timeout) {
  if (!tracking_) return true;
  const bool done = tracking_->wait(timeout);
  poll_tracking();
  show();
  return done;
}

void Editor::poll_tracking() {
  if (!tracking_) return;
  std::optional<TrackOutcome> out = tracking_->take();
  if (!out) return;
  tracking_.reset();
  if (out->cancelled) return say("tracking cancelled, nothing changed");
  if (!out->problem.empty()) return say("tracking failed: " + out->problem);
  try {
    if (out->camera) doc_.set_camera(std::move(*out->camera));
    if (out->track) {
      track_name_ = out->track->name;
      doc_.put_track(std::move(*out->track));
    }
  } catch (const io::InputError& e) {
    return say(std::string("tracking failed: ") + e.what());
  }
  say(out->summary + ": undo removes it");
}

void Editor::delete_track() {
  if (tracking_) return say("tracking runs: cancel it before deleting a track");
  if (doc_.pending()) return say("let go of the keyframe before deleting a track");
  const effects::SubjectTrack* shown = shown_track();
  if (!shown) return say("no track to delete");
  const std::string name = shown->name;
  const int anchored = doc_.remove_track(name);
  if (track_name_ == name) track_name_.clear();
  selected_.reset();
  say("deleted track " + name +
      (anchored ? ": " + std::to_string(anchored) + (anchored == 1 ? " effect" : " effects") +
                      " back on the video"
                : std::string()) +
      "; undo brings it back");
}

void Editor::begin_rename() {
  if (tracking_) return say("tracking runs: cancel it before renaming a track");
  const effects::SubjectTrack* shown = shown_track();
  if (!shown) return say("no track to rename");
  rename_ = RenameView{true, shown->name, shown->name, false, false};
  say("type the new name of " + shown->name + " on the keys, then Rename");
}

void Editor::rename_key(const std::string& key) {
  if (!rename_.open) return;
  if (key == "Shift") {
    rename_.upper = !rename_.upper;
  } else if (key == "Back") {
    if (!rename_.text.empty()) rename_.text.pop_back();
  } else if (key.size() == 1 && rename_.text.size() < effects::kMaxTrackNameLength) {
    const auto c = static_cast<unsigned char>(key[0]);
    rename_.text += static_cast<char>(rename_.upper ? std::toupper(c) : c);
  }
}

void Editor::commit_rename() {
  if (!rename_.open) return;
  if (doc_.pending()) return say("let go of the keyframe before renaming a track");
  const std::string from = rename_.from, to = rename_.text;
  try {
    const int anchored = doc_.rename_track(from, to);
    if (track_name_ == from) track_name_ = to;
    rename_ = {};
    say("renamed track " + from + " to " + to +
        (anchored ? ": " + std::to_string(anchored) + (anchored == 1 ? " effect" : " effects") +
                        " anchored to it"
                  : std::string()) +
        "; undo takes the old name back");
  } catch (const io::InputError& e) {
    say(e.what());
  }
}

void Editor::cancel_rename() {
  rename_ = {};
}

const effects::SubjectTrack* Editor::shown_track() const {
  const effects::Anchor& a = doc_.anchor(effect_);
  if (a.kind == effects::Anchor::Kind::Track)
    if (const effects::SubjectTrack* t = doc_.track(a.track)) return t;
  if (const effects::SubjectTrack* t = doc_.track(track_name_)) return t;
  return doc_.tracks().empty() ? nullptr : &doc_.tracks().front();
}

bool Editor::set_anchor(const effects::Anchor& anchor) {
  if (doc_.pending()) return say("let go of the keyframe before changing the anchor"), false;
  if (anchor.kind == effects::Anchor::Kind::World && !doc_.camera())
    return say("a world anchor needs the camera's motion: press Track camera first"), false;
  if (anchor.kind == effects::Anchor::Kind::Track && !doc_.track(anchor.track))
    return say("there is no track named " + anchor.track), false;
  try {
    doc_.set_anchor(effect_, anchor);
  } catch (const io::InputError& e) {
    return say(e.what()), false;
  }
  selected_.reset();
  if (anchor.kind == effects::Anchor::Kind::Track) track_name_ = anchor.track;
  say(effect_.title() + " anchored to " + effects::anchor_name(anchor));
  return true;
}

void Editor::next_anchor() {
  std::vector<effects::Anchor> options{{}};
  if (doc_.camera()) options.push_back({effects::Anchor::Kind::World, ""});
  for (const effects::SubjectTrack& t : doc_.tracks())
    options.push_back({effects::Anchor::Kind::Track, t.name});
  std::size_t i = 0;
  while (i < options.size() && !(options[i] == doc_.anchor(effect_))) ++i;
  set_anchor(options[(i + 1) % options.size()]);
}

TrackView Editor::track_view() const {
  TrackView v;
  v.available = options_.video.has_value();
  v.anchor = effects::anchor_name(doc_.anchor(effect_));
  v.has_camera = doc_.camera().has_value();
  if (tracking_) {
    v.running = job_name(tracking_->job().kind);
    v.progress = tracking_->fraction();
  }
  const effects::SubjectTrack* t = shown_track();
  if (t) {
    v.track = t->name;
    v.first = static_cast<int>(t->points.front().frame);
    v.last = static_cast<int>(t->points.back().frame);
    for (const effects::TrackPoint& p : t->points) {
      if (p.confidence <= 0.0) v.held.push_back(static_cast<int>(p.frame));
      if (p.frame != play_.frame) continue;
      v.marker = p.direction;
      v.marker_held = p.confidence <= 0.0;
    }
  }
  v.rename = rename_;
  v.rename.can_commit =
      rename_.open && effects::valid_track_name(rename_.text) && !doc_.track(rename_.text);
  if (tracking_)
    v.line = "tracking " + v.running + fmt(" %.0f %%", 100.0 * v.progress) + ": press to cancel";
  else if (t)
    v.line = v.track + ": " + std::to_string(v.held.size()) + " frames held" +
             (v.has_camera ? ", camera tracked" : "");
  else
    v.line = v.has_camera ? "camera tracked; no subject yet" : "nothing tracked yet";
  return v;
}

}  // namespace vdfx::app
