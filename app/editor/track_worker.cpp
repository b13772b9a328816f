/// @file
/// @brief TrackWorker: the camera or a subject tracked on a thread, with progress and cancel.
#include "app/editor/track_worker.h"

#include <cstdio>
#include <map>
#include <utility>

namespace vdfx::app {

namespace {

std::string held_text(const std::vector<std::int64_t>& held) {
  if (held.empty()) return "";
  return ", held on " + std::to_string(held.size()) + " frames";
}

}  // namespace

effects::SubjectTrack merge_correction(const effects::SubjectTrack& old_track,
                                       effects::SubjectTrack fresh, std::int64_t frame) {
  std::map<std::int64_t, const effects::TrackPoint*> old_at;
  for (const effects::TrackPoint& p : old_track.points) old_at[p.frame] = &p;
  for (effects::TrackPoint& p : fresh.points) {
    if (p.frame >= frame) continue;
    const auto it = old_at.find(p.frame);
    if (it != old_at.end() && it->second->confidence > 0.0) p = *it->second;
  }
  return fresh;
}

TrackWorker::TrackWorker(TrackJob job, io::Sidecar sidecar, bool async) : job_(std::move(job)) {
  if (async)
    thread_ = std::thread([this, s = std::move(sidecar)]() mutable { run(std::move(s)); });
  else
    run(std::move(sidecar));
}

TrackWorker::~TrackWorker() {
  cancel();
  if (thread_.joinable()) thread_.join();
}

TrackOutcome TrackWorker::track_camera(io::Sidecar& sidecar) {
  const track::CameraReport r = track::track_camera_into(job_.camera, sidecar, &progress_);
  TrackOutcome out;
  out.camera = sidecar.camera;
  char buf[160];
  std::snprintf(buf, sizeof buf, "camera tracked (%s): turns up to %.1f\u00b0",
                r.source_text.c_str(), r.largest_turn_deg);
  out.summary = buf + held_text(r.held);
  return out;
}

TrackOutcome TrackWorker::track_subject(io::Sidecar& sidecar) {
  const std::string& name = job_.subject.name;
  std::optional<effects::SubjectTrack> old_track;
  for (const effects::SubjectTrack& t : sidecar.tracks)
    if (t.name == name) old_track = t;
  const track::SubjectReport r = track::track_subject_into(job_.subject, sidecar, &progress_);
  TrackOutcome out;
  for (effects::SubjectTrack& t : sidecar.tracks)
    if (t.name == name) out.track = std::move(t);
  if (!out.track) throw std::logic_error("the tracker left no track named " + name);
  if (job_.kind == TrackJob::Kind::Correction && old_track)
    out.track = merge_correction(*old_track, std::move(*out.track), job_.subject.frame);
  char buf[160];
  std::snprintf(buf, sizeof buf, "%s %s: %lld frames, confidence %.2f",
                job_.kind == TrackJob::Kind::Correction ? "re-tracked" : "tracked", name.c_str(),
                static_cast<long long>(r.frames), r.mean_confidence);
  out.summary = buf + held_text(r.held);
  return out;
}

void TrackWorker::run(io::Sidecar sidecar) {
  TrackOutcome out;
  try {
    out = job_.kind == TrackJob::Kind::Camera ? track_camera(sidecar) : track_subject(sidecar);
  } catch (const track::Cancelled&) {
    out = {};
    out.cancelled = true;
    out.problem = "cancelled";
  } catch (const std::exception& e) {  // an unreadable video, a still image, ...
    out = {};
    out.problem = e.what();
  }
  result_.put(std::move(out));
}

std::optional<TrackOutcome> TrackWorker::take() {
  return result_.take();
}

bool TrackWorker::wait(std::chrono::milliseconds timeout) {
  return result_.wait(timeout);
}

}  // namespace vdfx::app
