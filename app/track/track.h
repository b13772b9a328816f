/// @file
/// @brief `vdfx track`'s library entry points (docs/anchors.md): the camera's orientation at every
/// frame into the sidecar's `camera`, a subject's direction at every frame into its `tracks`. The
/// commands parse their options into a request and call run_track_camera / run_track_subject; the
/// editor calls the *_into forms on its own sidecar, on a worker, with a Progress.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/suggest/suggest.h"
#include "app/track/camera_tracker.h"
#include "app/track/subject_tracker.h"
#include "effects/anchor.h"
#include "effects/coords.h"
#include "io/sidecar.h"
#include "io/sidecar_target.h"
#include "io/video_layout.h"

namespace vdfx::app::track {

/// How far a tracking job on another thread is, and the request to stop: the same as a
/// suggestion's, so one editor worker runs both.
using Progress = suggest::Progress;

/// Thrown by the *_into functions when Progress::cancel was set: nothing was changed.
struct Cancelled : std::runtime_error {
  Cancelled() : std::runtime_error("the tracking was cancelled") {}
};

enum class CameraSource { Estimated, Camm };

struct CameraRequest {
  std::filesystem::path video;
  io::SidecarOptions sidecar;  //!< --sidecar-in, --sidecar-out, --force
  CameraSource source = CameraSource::Estimated;
  CameraTrackOptions options;  //!< --width, --points, --keyframe-spacing
  io::LayoutOverride layout;   //!< --layout, --coverage
};

struct CameraReport {
  effects::CameraMotion::Source source = effects::CameraMotion::Source::Estimated;
  std::string source_text;  //!< what the orientations came from, for the user
  std::string camm;         //!< the video's CAMM track ("" when it has none): what it holds
  std::string replaced;     //!< the source of the camera the sidecar had ("" when none)
  std::int64_t frames = 0;
  std::vector<std::int64_t> held;      //!< frames whose orientation is held (no estimate there)
  double largest_turn_deg = 0.0;       //!< the farthest the camera turned from frame 0
  double analysis_ms_per_frame = 0.0;  //!< estimated: reducing and tracking, decoding aside
  double seconds = 0.0;
  std::string sidecar_note;  //!< io::sidecar_target_note
};

/// Tracks the camera and sets `sidecar.camera` (replacing one it had). `sidecar.video` must
/// describe the video (its frame count is the orientations'). Throws io::InputError (a still
/// image, a frame count that differs, --source camm without a CAMM track), UsageError (options
/// out of range) or Cancelled; on any exception `sidecar` is left as it was.
CameraReport track_camera_into(const CameraRequest& request, io::Sidecar& sidecar,
                               Progress* progress = nullptr);

/// Tracks the camera and writes --sidecar-out (io/sidecar_target.h's rule), with a progress bar
/// on stderr. A stop signal (app/cli/stop_signals.h) stops it at its next frame: app::Stopped,
/// nothing written.
CameraReport run_track_camera(const CameraRequest& request);

struct SubjectRequest {
  std::filesystem::path video;
  io::SidecarOptions sidecar;
  std::string name;        //!< --name: [A-Za-z0-9_-]{1,64}
  effects::Direction at;   //!< --at AZ,ALT,FRAME: where the subject is ...
  std::int64_t frame = 0;  //!< ... at this frame
  SubjectOptions options;  //!< --size (size_deg)
  bool replace = false;    //!< --replace: a track of that name is replaced
  io::LayoutOverride layout;
};

struct SubjectReport {
  std::int64_t frames = 0;
  std::vector<std::int64_t> held;  //!< frames where the subject was not seen (direction held)
  double mean_confidence = 0.0;    //!< over the frames where it was seen
  int width = 0;                   //!< analysis equirect width
  double seconds = 0.0;
  std::string sidecar_note;
};

/// Follows the subject forwards and backwards from request.frame and adds its track to
/// `sidecar.tracks` (or replaces the one of that name with request.replace). Throws
/// io::InputError (a still image, --at outside the video's frames or a VR180 image, the name
/// taken), UsageError or Cancelled; on any exception `sidecar` is left as it was.
SubjectReport track_subject_into(const SubjectRequest& request, io::Sidecar& sidecar,
                                 Progress* progress = nullptr);

/// Follows the subject and writes --sidecar-out (stopped as run_track_camera is).
SubjectReport run_track_subject(const SubjectRequest& request);

/// `vdfx track rename FROM TO`: no video, only the sidecar.
struct RenameRequest {
  io::SidecarOptions sidecar;
  std::string from, to;
};

struct RenameReport {
  int anchors = 0;  //!< anchors that named the track (now track:TO)
};

/// Renames the track `from` of the sidecar the command starts from (io/sidecar_target.h) to `to`,
/// with every anchor naming it, and writes --sidecar-out. Throws UsageError (`to` not a valid
/// name) and io::InputError (no sidecar to start from, no track `from`, `to` taken, an editor
/// holding the sidecar's lock), naming the file and the JSON pointer.
RenameReport run_track_rename(const RenameRequest& request);

}  // namespace vdfx::app::track
