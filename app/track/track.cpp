/// @file
/// @brief run_track_camera, run_track_subject and their *_into forms (track.h): open the video,
/// check the request against it, run the estimator, put the result into the sidecar.
#include "app/track/track.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>

#include "app/cli/command_registry.h"
#include "app/cli/layout_options.h"
#include "app/cli/progress.h"
#include "app/cli/stop_signals.h"
#include "app/track/camera_estimate.h"
#include "app/track/camm_motion.h"
#include "app/track/subject_estimate.h"
#include "effects/stereo_layout.h"
#include "io/camm_track.h"
#include "io/frame_decoder.h"
#include "io/input_error.h"

namespace vdfx::app::track {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;
using Tick = std::function<void(double)>;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// A video opened for tracking.
struct Clip {
  std::unique_ptr<io::FrameDecoder> decoder;
  effects::StereoLayout layout;
  std::string name;  //!< the video's file name, for messages
};

std::unique_ptr<io::FrameDecoder> open_video(const fs::path& video) {
  auto decoder = io::open_frame_decoder(video);
  if (decoder->properties().is_still)
    throw io::InputError(video.string() +
                         ": is a still image: a camera or subject track needs a video");
  return decoder;
}

/// A sidecar for the video, as a command starts one when it has none.
io::Sidecar fresh_sidecar(const fs::path& video, const io::VideoProperties& p) {
  return io::new_sidecar({video.string(), p.fps.value(), p.frames, p.width, p.height});
}

/// The layout the tracker sees (recorded in the sidecar), and the frame count checked against the
/// sidecar's: every camera orientation and track point belongs to one of its frames.
Clip prepare_clip(std::unique_ptr<io::FrameDecoder> decoder, const fs::path& video,
                  const io::LayoutOverride& cli, io::Sidecar& sidecar,
                  const fs::path& sidecar_path) {
  Clip clip{std::move(decoder), {}, video.string()};
  const io::VideoProperties& p = clip.decoder->properties();
  clip.layout = shown_layout(p, cli, &sidecar.video, sidecar_path);
  if (sidecar.video.frames != p.frames)
    throw io::InputError(sidecar_path.string() +
                         ": /video/frames: " + std::to_string(sidecar.video.frames) +
                         " frames, but " + clip.name + " has " + std::to_string(p.frames));
  io::record_layout(sidecar.video, clip.layout);
  return clip;
}

/// Reports progress and stops when asked (Cancelled).
Tick progress_tick(Progress* progress) {
  return [progress](double fraction) {
    if (!progress) return;
    if (progress->cancel.load()) throw Cancelled();
    progress->fraction.store(std::clamp(fraction, 0.0, 1.0));
  };
}

/// A progress bar on stderr over `frames` frames.
Tick bar_tick(std::int64_t frames) {
  auto bar = std::make_shared<ProgressReporter>(std::cerr, ::isatty(2) != 0, frames, 5.0, "track");
  const auto start = Clock::now();
  return [bar, start, frames](double fraction) {
    const auto done = static_cast<std::int64_t>(std::llround(fraction * frames));
    if (done >= frames)
      bar->finish(done, seconds_since(start));
    else
      bar->update(done, seconds_since(start));
  };
}

/// The bar, with a stop signal (app/cli/stop_signals.h, through `progress`'s cancel flag) ending
/// the job at its next frame, as the editor's Cancel does (Cancelled).
Tick stoppable_bar_tick(Progress& progress, std::int64_t frames) {
  return [check = progress_tick(&progress), bar = bar_tick(frames)](double fraction) {
    check(fraction);
    bar(fraction);
  };
}

/// Runs `job(clip, sidecar, sidecar_path, tick)` on a copy of `sidecar` that replaces it only
/// once the job is done (a *_into call: the editor's sidecar, a Progress).
template <class Report, class Job>
Report run_into(const fs::path& video, const io::LayoutOverride& layout,
                const io::SidecarOptions& options, io::Sidecar& sidecar, Progress* progress,
                const Job& job) {
  const auto start = Clock::now();
  io::Sidecar work = sidecar;
  const fs::path sidecar_path = options.in.value_or(fs::path("sidecar"));
  Clip clip = prepare_clip(open_video(video), video, layout, work, sidecar_path);
  Report report = job(clip, work, sidecar_path, progress_tick(progress));
  sidecar = std::move(work);
  report.seconds = seconds_since(start);
  return report;
}

/// Runs `job` on the sidecar the command starts from (io/sidecar_target.h) and writes it, with a
/// progress bar. A stop signal stops it with nothing written (app::Stopped).
template <class Report, class Job>
Report run_writing(const fs::path& video, const io::LayoutOverride& layout,
                   const io::SidecarOptions& options, const Job& job) {
  const auto start = Clock::now();
  Progress progress;
  const CancelOnStop cancel_on_stop(progress.cancel);
  const io::SidecarTarget target =
      io::resolve_sidecar_target(options, {{"VIDEO", video}}, "vdfx track");
  auto decoder = open_video(video);
  io::Sidecar sidecar = io::read_sidecar_base(target, fresh_sidecar(video, decoder->properties()));
  const io::Sidecar before = sidecar;
  const fs::path sidecar_path = target.base.value_or(options.out);
  Clip clip = prepare_clip(std::move(decoder), video, layout, sidecar, sidecar_path);
  Report report;
  try {
    report = job(clip, sidecar, sidecar_path,
                 stoppable_bar_tick(progress, clip.decoder->properties().frames));
  } catch (const Cancelled&) {
    throw Stopped("nothing written; " + options.out.string() + " left as it was");
  }
  io::write_sidecar(options.out, sidecar);
  report.sidecar_note = io::sidecar_target_note(target, options.out, before);
  report.seconds = seconds_since(start);
  return report;
}

}  // namespace

namespace {

void check_camera_request(const CameraRequest& r) {
  const CameraTrackOptions& o = r.options;
  if (o.width < 64 || o.width > 4096) throw UsageError("--width must be within [64, 4096]");
  if (o.points < 32 || o.points > 5000) throw UsageError("--points must be within [32, 5000]");
  if (o.keyframe_spacing < 1 || o.keyframe_spacing > 1000)
    throw UsageError("--keyframe-spacing must be within [1, 1000]");
}

/// Frame i's presentation time in seconds (its timestamp; else i / fps).
std::vector<double> frame_times(const io::FrameDecoder& decoder) {
  const io::VideoProperties& p = decoder.properties();
  std::vector<double> t;
  for (std::int64_t i = 0; i < p.frames; ++i) {
    const auto ts = decoder.timestamp(i);
    t.push_back(ts && p.time_base.num > 0 ? static_cast<double>(*ts) * p.time_base.value()
                                          : static_cast<double>(i) / p.fps.value());
  }
  return t;
}

std::string camm_text(const io::CammTrack& t) {
  return std::to_string(t.angle_axis.size()) + " angle-axis orientations, " +
         std::to_string(t.gyro.size()) + " gyroscope samples";
}

CameraReport camera_job(const CameraRequest& r, Clip& clip, io::Sidecar& sidecar,
                        const Tick& tick) {
  CameraReport report;
  report.frames = clip.decoder->properties().frames;
  const std::optional<io::CammTrack> camm = io::read_camm_track(r.video);
  if (camm) report.camm = camm_text(*camm);
  effects::CameraMotion motion;
  std::vector<Eigen::Quaterniond> q;
  if (r.source == CameraSource::Camm) {
    if (!camm) throw io::InputError(clip.name + ": --source camm: the video has no CAMM track");
    const CammMotion m = camm_motion(*camm, frame_times(*clip.decoder), clip.name);
    q = m.orientation;
    motion.source = effects::CameraMotion::Source::Camm;
    report.source_text = std::string("the video's CAMM track: ") + camm_kind_text(m.kind) + " (" +
                         std::to_string(m.records) + " records)";
    if (tick) tick(1.0);
  } else {
    const CameraEstimate e = estimate_camera(*clip.decoder, clip.layout, r.options, tick);
    q = e.track.orientation;
    report.held = e.track.held;
    report.analysis_ms_per_frame = 1e3 * e.analysis_seconds / std::max<double>(1, q.size());
    report.source_text = "estimated from the pictures (" + std::to_string(e.width) +
                         " pixels a turn, " + std::to_string(e.track.keyframes) + " key frames, " +
                         std::to_string(e.track.links) + " links)";
  }
  report.source = motion.source;
  for (const Eigen::Quaterniond& o : q) {
    motion.orientation.push_back(effects::from_eigen(o));
    report.largest_turn_deg =
        std::max(report.largest_turn_deg,
                 o.angularDistance(Eigen::Quaterniond::Identity()) * effects::kRadToDeg);
  }
  if (sidecar.camera) report.replaced = effects::camera_source_name(sidecar.camera->source);
  sidecar.camera = std::move(motion);
  return report;
}

}  // namespace

CameraReport track_camera_into(const CameraRequest& request, io::Sidecar& sidecar,
                               Progress* progress) {
  check_camera_request(request);
  return run_into<CameraReport>(request.video, request.layout, request.sidecar, sidecar, progress,
                                [&](Clip& clip, io::Sidecar& s, const fs::path&, const Tick& tick) {
                                  return camera_job(request, clip, s, tick);
                                });
}

CameraReport run_track_camera(const CameraRequest& request) {
  check_camera_request(request);
  return run_writing<CameraReport>(
      request.video, request.layout, request.sidecar,
      [&](Clip& clip, io::Sidecar& s, const fs::path&, const Tick& tick) {
        return camera_job(request, clip, s, tick);
      });
}

namespace {

/// A usage error where `name` (given as `what`) cannot name a track.
void check_track_name(const std::string& what, const std::string& name) {
  if (!effects::valid_track_name(name))
    throw UsageError(what + " must be 1 to 64 of A-Z, a-z, 0-9, '_' and '-', got '" + name + "'");
}

void check_subject_request(const SubjectRequest& r) {
  check_track_name("--name", r.name);
  if (!(r.options.size_deg >= 1.0 && r.options.size_deg <= 90.0))
    throw UsageError("--size must be within [1, 90] degrees");
}

std::string at_text(const SubjectRequest& r) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "--at %g,%g,%lld", r.at.azimuth_deg, r.at.altitude_deg,
                static_cast<long long>(r.frame));
  return buf;
}

/// Where the track goes: the index of the track of that name (replaced), or tracks.size().
std::size_t track_slot(const SubjectRequest& r, const io::Sidecar& sidecar,
                       const fs::path& sidecar_path) {
  for (std::size_t i = 0; i < sidecar.tracks.size(); ++i)
    if (sidecar.tracks[i].name == r.name) {
      if (!r.replace)
        throw io::InputError(sidecar_path.string() + ": /tracks/" + std::to_string(i) +
                             "/name: a track named '" + r.name +
                             "' is already there; --replace replaces it");
      return i;
    }
  return sidecar.tracks.size();
}

SubjectReport subject_job(const SubjectRequest& r, Clip& clip, io::Sidecar& sidecar,
                          const fs::path& sidecar_path, const Tick& tick) {
  const std::int64_t frames = clip.decoder->properties().frames;
  if (r.frame < 0 || r.frame >= frames)
    throw io::InputError(clip.name + ": " + at_text(r) + ": frame " + std::to_string(r.frame) +
                         " is not in the video (frames 0 to " + std::to_string(frames - 1) + ")");
  if (effects::coverage_weight(clip.layout, r.at.azimuth_deg) <= 0.0)
    throw io::InputError(clip.name + ": " + at_text(r) +
                         ": outside the video's image (VR180: azimuth -90 to 90)");
  const std::size_t slot = track_slot(r, sidecar, sidecar_path);
  const SubjectEstimate e = estimate_subject(*clip.decoder, clip.layout, r.frame,
                                             effects::to_unit(r.at), r.options, tick);
  SubjectReport report;
  report.frames = frames;
  report.width = e.width;
  effects::SubjectTrack track{r.name, {}};
  double confidence = 0.0;
  for (std::size_t f = 0; f < e.samples.size(); ++f) {
    const SubjectSample& s = e.samples[f];
    track.points.push_back({static_cast<std::int64_t>(f), effects::from_unit(s.direction),
                            s.seen ? std::clamp(s.confidence, 0.0, 1.0) : 0.0});
    if (!s.seen) report.held.push_back(static_cast<std::int64_t>(f));
    if (s.seen) confidence += s.confidence;
  }
  const auto seen = static_cast<double>(e.samples.size() - report.held.size());
  report.mean_confidence = seen > 0 ? confidence / seen : 0.0;
  if (slot == sidecar.tracks.size())
    sidecar.tracks.push_back(std::move(track));
  else
    sidecar.tracks[slot] = std::move(track);
  return report;
}

}  // namespace

SubjectReport track_subject_into(const SubjectRequest& request, io::Sidecar& sidecar,
                                 Progress* progress) {
  check_subject_request(request);
  return run_into<SubjectReport>(
      request.video, request.layout, request.sidecar, sidecar, progress,
      [&](Clip& clip, io::Sidecar& s, const fs::path& path, const Tick& tick) {
        return subject_job(request, clip, s, path, tick);
      });
}

SubjectReport run_track_subject(const SubjectRequest& request) {
  check_subject_request(request);
  return run_writing<SubjectReport>(
      request.video, request.layout, request.sidecar,
      [&](Clip& clip, io::Sidecar& s, const fs::path& path, const Tick& tick) {
        return subject_job(request, clip, s, path, tick);
      });
}

RenameReport run_track_rename(const RenameRequest& r) {
  check_track_name("the new name", r.to);
  // Without --sidecar-in the rename is in place: --force has nothing to replace.
  io::SidecarOptions options = r.sidecar;
  if (!options.in) options.force = false;
  const io::SidecarTarget target = io::resolve_sidecar_target(options, {}, "vdfx track");
  if (!target.base)
    throw io::InputError(r.sidecar.out.string() +
                         ": no such sidecar (and no --sidecar-in): there is no track to rename");
  io::Sidecar sidecar = io::read_sidecar_base(target, {});
  RenameReport report;
  report.anchors = io::rename_track(sidecar, r.from, r.to, target.base->string());
  io::write_sidecar(r.sidecar.out, sidecar);
  return report;
}

}  // namespace vdfx::app::track
