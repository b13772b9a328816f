/// @file
/// @brief The editor's tracking (docs/editor.md, "Tracking"): the camera's motion or a subject's
/// track (app/track/track.h) computed off the frame thread on a copy of the document's sidecar,
/// with its progress and a cancel. The editor takes the result when it is done and puts it into
/// the document as one undo step; a cancelled or failed run leaves the document untouched.
#pragma once

#include <chrono>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "app/editor/worker_result.h"
#include "app/track/track.h"
#include "io/sidecar.h"

namespace vdfx::app {

/// What to track: the camera, a new subject, or a correction of a subject's track (a point
/// dropped at a frame: it is tracked again from there).
struct TrackJob {
  enum class Kind { Camera, Subject, Correction };
  Kind kind = Kind::Subject;
  track::CameraRequest camera;    //!< Kind::Camera
  track::SubjectRequest subject;  //!< Subject, Correction (name, at, frame)
};

/// What a finished run left: the camera or the track to put into the document, or why none.
struct TrackOutcome {
  std::optional<effects::CameraMotion> camera;
  std::optional<effects::SubjectTrack> track;
  std::string summary;     //!< what was found, for the status line
  std::string problem;     //!< why there is nothing ("" when there is)
  bool cancelled = false;  //!< stopped by cancel()
};

/// A correction: the new run's points from `frame` on; before it, the old track's points where
/// it saw the subject and the new run's where it was holding (or had none).
effects::SubjectTrack merge_correction(const effects::SubjectTrack& old_track,
                                       effects::SubjectTrack fresh, std::int64_t frame);

class TrackWorker {
 public:
  /// Starts the job on `sidecar` (a copy) on a thread of its own; `async` false runs it here,
  /// before the constructor returns (replays are exact). A correction needs the old track in
  /// `sidecar`.
  TrackWorker(TrackJob job, io::Sidecar sidecar, bool async = true);
  /// Cancels and joins.
  ~TrackWorker();
  TrackWorker(const TrackWorker&) = delete;
  TrackWorker& operator=(const TrackWorker&) = delete;

  const TrackJob& job() const { return job_; }
  /// 0..1, as the tracker reports it.
  double fraction() const { return progress_.fraction.load(); }
  /// Asks the tracker to stop; it then ends cancelled (unless it had already finished).
  void cancel() { progress_.cancel.store(true); }
  /// The outcome once the job has ended (then once only); nullopt before and after.
  std::optional<TrackOutcome> take();
  /// Blocks until the job has ended (tests); false on timeout.
  bool wait(std::chrono::milliseconds timeout);

 private:
  void run(io::Sidecar sidecar);
  TrackOutcome track_camera(io::Sidecar& sidecar);
  TrackOutcome track_subject(io::Sidecar& sidecar);

  TrackJob job_;
  track::Progress progress_;
  WorkerResult<TrackOutcome> result_;
  std::thread thread_;
};

}  // namespace vdfx::app
