/// @file
/// @brief `vdfx track`'s knobs of `vdfx bench` (docs/anchors.md, "Measured"), on clips with a known
/// truth (track_clips.h): the camera tracker's analysis width, corners per key frame and key-frame
/// spacing against its error from the true path (and its drift over a slow 1000-frame pan), and
/// the subject tracker's template size against its error from the patch's true centre. Camera
/// times are the analysis alone (reducing each decoded picture and tracking, per frame), beside
/// the decoding of the same frames in the same runs; subject times are whole frames (decoding,
/// the view renders, the matching) beside FFmpeg's plain decode loop over the same clip.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "app/bench/media.h"
#include "app/bench/registry.h"
#include "app/bench/track_clips.h"
#include "app/track/camera_estimate.h"
#include "app/track/subject_estimate.h"
#include "io/frame_decoder.h"

namespace vdfx::app::bench {
namespace {

namespace fs = std::filesystem;

struct CameraClipSpec {
  CameraPath path;
  const char* name;
  int width, frames;
};

/// The clip of `spec` (made once, kept in the temporary folder) and its true path.
fs::path camera_clip(const CameraClipSpec& spec, std::vector<Eigen::Quaterniond>& truth) {
  truth = camera_path(spec.path, spec.frames, 30.0);
  const int w = spec.width, h = spec.width / 2;
  const fs::path p = fs::temp_directory_path() /
                     ("vdfx_bench_track_" + std::string(spec.name) + "_" + std::to_string(w) + "x" +
                      std::to_string(h) + "_" + std::to_string(spec.frames) + ".mp4");
  if (fs::exists(p)) return p;
  const cv::Mat world = world_panorama("forest", std::min(2 * w, 1024));
  return encode_clip(p, w, h, spec.frames, 30, [&](int i) {
    return camera_view(world, truth[static_cast<std::size_t>(i)], w, h);
  });
}

TimeStats stats_of(std::vector<double> v) {
  return {median_of(v), p90_of(v), static_cast<int>(v.size())};
}

/// Runs the tracker over the clip `samples` times: the analysis and the decoding per frame
/// (medians of the runs), the errors of the last run.
void camera_row(Row& row, const CameraClipSpec& spec, const track::CameraTrackOptions& options,
                int samples) {
  std::vector<Eigen::Quaterniond> truth;
  const fs::path clip = camera_clip(spec, truth);
  std::vector<double> analysis, decode, cpu;
  track::CameraEstimate e;
  for (int s = 0; s < samples; ++s) {
    const auto decoder = io::open_frame_decoder(clip);
    e = track::estimate_camera(*decoder, {}, options);
    analysis.push_back(e.analysis_seconds / spec.frames);
    decode.push_back(e.decode_seconds / spec.frames);
    cpu.push_back(e.analysis_cpu_seconds / spec.frames);
  }
  row.time = stats_of(analysis);
  row.peer_time = stats_of(decode);
  const OrientationErrors err = orientation_errors(e.track.orientation, truth);
  row.error.rms = err.rms;
  row.error.max = err.max;
  // The analysis's own CPU time: on a shared machine the wall time also counts the waits.
  row.add("analysis_cpu_ms", 1e3 * median_of(cpu));
  row.add("last_frame_deg", err.last);
  row.add("keyframes", e.track.keyframes);
  row.add("links", e.track.links);
  row.add("held", static_cast<double>(e.track.held.size()));
  row.note = std::string(spec.name) + ": " + std::to_string(spec.width) + "x" +
             std::to_string(spec.width / 2) + " H.264, " + std::to_string(spec.frames) +
             " frames; analysis " + std::to_string(e.width) + " pixels a turn, " +
             std::to_string(options.points) + " corners, a key frame every " +
             std::to_string(options.keyframe_spacing) + " frames, " +
             std::to_string(options.far_links) + " far links";
}

Knob camera_knob(const char* id, const char* varied) {
  return {id,
          std::string("camera orientation against ") + varied +
              ": a panorama turned along a known path, x264",
          "frame",
          "deg",
          "the true path the clip was rendered along",
          "decoding the same frames (the tracker's decoder, same runs)",
          PlotError::Rms,
          false,
          true};
}

}  // namespace

namespace {

struct SubjectClipSpec {
  SubjectMotion motion;
  const char* name;
  int width, frames;
  double start;  //!< where the track starts, as a fraction of the clip
};

fs::path subject_clip(const SubjectClipSpec& spec, std::vector<SubjectPose>& truth) {
  truth = subject_path(spec.motion, spec.frames);
  const int w = spec.width, h = spec.width / 2;
  const fs::path p = fs::temp_directory_path() /
                     ("vdfx_bench_subject_" + std::string(spec.name) + "_" + std::to_string(w) +
                      "x" + std::to_string(h) + "_" + std::to_string(spec.frames) + ".mp4");
  if (fs::exists(p)) return p;
  const cv::Mat world = world_panorama("courtyard", w), texture = subject_texture();
  return encode_clip(p, w, h, spec.frames, 30, [&](int i) {
    return draw_subject(world, truth[static_cast<std::size_t>(i)], texture);
  });
}

void subject_row(Row& row, const SubjectClipSpec& spec, int template_px, const Context& ctx) {
  std::vector<SubjectPose> truth;
  const fs::path clip = subject_clip(spec, truth);
  const auto start = static_cast<std::int64_t>(spec.start * (spec.frames - 1));
  track::SubjectOptions o;
  o.template_px = template_px;
  o.size_deg = truth[static_cast<std::size_t>(start)].size_deg;
  track::SubjectEstimate last;
  PlainDecodeLoop plain(clip);
  Budget budget = ctx.budget;
  budget.min_samples = ctx.quick ? 1 : 2;
  budget.min_time_s = 0.0;
  const auto times = measure_pair(Timed(
                                      [&] {
                                        const auto decoder = io::open_frame_decoder(clip);
                                        last = track::estimate_subject(
                                            *decoder, {}, start,
                                            truth[static_cast<std::size_t>(start)].centre(), o);
                                      },
                                      spec.frames),
                                  Timed([&] { plain.run(); }, spec.frames), budget);
  row.time = times.subject;
  row.peer_time = times.peer;
  std::vector<Eigen::Vector3d> directions;
  std::vector<bool> seen;
  for (const track::SubjectSample& s : last.samples) {
    directions.push_back(s.direction);
    seen.push_back(s.seen);
  }
  const SubjectErrors err = subject_errors(directions, seen, truth);
  row.error.rms = err.rms;
  row.error.max = err.max;
  row.add("hidden_frames_not_reported", static_cast<double>(err.hidden_seen.size()));
  row.add("visible_frames_lost", static_cast<double>(err.visible_lost.size()));
  row.series = spec.name;
  row.note = std::string(spec.name) + ": " + std::to_string(spec.width) + "x" +
             std::to_string(spec.width / 2) + " H.264, " + std::to_string(spec.frames) +
             " frames, the track started at frame " + std::to_string(start) + "; equirect " +
             std::to_string(last.width) + " pixels a turn";
}

struct CameraSetting {
  std::string name;
  track::CameraTrackOptions options;
};

void add_camera_knob(Registry& r, const char* id, const char* varied, const CameraClipSpec& clip,
                     int runs, const std::vector<CameraSetting>& settings) {
  r.knob(camera_knob(id, varied));
  for (const CameraSetting& s : settings)
    r.add(id, s.name, [=](Row& row, const Context&) { camera_row(row, clip, s.options, runs); });
}

/// The default options but for one change.
template <class Change>
CameraSetting setting(std::string name, Change change) {
  CameraSetting s{std::move(name), {}};
  change(s.options);
  return s;
}

}  // namespace

void add_track_knobs(Registry& r, bool quick) {
  // The width knob carries the time goal (3 runs); the others 2 (the 1000-frame pan is long).
  const int runs = quick ? 1 : 3, other_runs = quick ? 1 : 2;
  std::vector<CameraSetting> widths, points, spacings;
  for (const int w :
       quick ? std::vector<int>{256, 512} : std::vector<int>{256, 384, 512, 768, 1024})
    widths.push_back(setting("W=" + std::to_string(w), [w](auto& o) { o.width = w; }));
  for (const int p : quick ? std::vector<int>{100, 400} : std::vector<int>{100, 200, 400, 800})
    points.push_back(setting("P=" + std::to_string(p), [p](auto& o) { o.points = p; }));
  std::vector<std::pair<int, int>> k_far = {{10, 8}, {10, 0}};
  if (!quick) k_far = {{5, 8}, {10, 8}, {20, 8}, {10, 0}, {1, 0}};
  for (const auto& [k, far] : k_far)
    spacings.push_back(
        setting("K=" + std::to_string(k) + (far ? "" : " chained"), [k = k, far = far](auto& o) {
          o.keyframe_spacing = k;
          o.far_links = far;
        }));
  add_camera_knob(r, "track.camera_width", "the analysis width W (pixels a turn)",
                  quick ? CameraClipSpec{CameraPath::Turn, "turn", 512, 90}
                        : CameraClipSpec{CameraPath::Turn, "turn", 1920, 300},
                  runs, widths);
  add_camera_knob(r, "track.camera_points", "the corners followed per key frame P",
                  quick ? CameraClipSpec{CameraPath::Shake, "shake", 512, 60}
                        : CameraClipSpec{CameraPath::Shake, "shake", 1024, 300},
                  other_runs, points);
  add_camera_knob(r, "track.camera_keyframes",
                  "the key-frame spacing K (chained: no links past the previous key frame)",
                  quick ? CameraClipSpec{CameraPath::Pan, "pan", 512, 200}
                        : CameraClipSpec{CameraPath::Pan, "pan", 1024, 1000},
                  other_runs, spacings);
  r.knob({"track.subject_template",
          "subject direction against the template's side T (pixels): a textured patch moved over a "
          "panorama, x264",
          "frame", "deg", "the patch's true centre, over the frames where it is drawn",
          "FFmpeg's plain decode loop over the same clip", PlotError::Rms, false, true});
  const int sw = quick ? 512 : 1024, sf = quick ? 40 : 90;
  const SubjectClipSpec clips[] = {{SubjectMotion::Seam, "seam", sw, sf, 0.5},
                                   {SubjectMotion::Pole, "pole", sw, sf, 0.5},
                                   {SubjectMotion::Approach, "approach", sw, sf, 0.7},
                                   {SubjectMotion::Turn, "turn", sw, sf, 0.5}};
  for (const SubjectClipSpec& c : clips)
    for (const int t : quick ? std::vector<int>{32} : std::vector<int>{16, 24, 32, 48})
      r.add("track.subject_template", std::string(c.name) + " T=" + std::to_string(t),
            [=](Row& row, const Context& ctx) { subject_row(row, c, t, ctx); });
}

}  // namespace vdfx::app::bench
