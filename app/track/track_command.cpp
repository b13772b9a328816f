/// @file
/// @brief `vdfx track camera|subject VIDEO ...` and `vdfx track rename FROM TO` (docs/anchors.md):
/// options into a track::CameraRequest, SubjectRequest or RenameRequest, then run_track_camera /
/// run_track_subject / run_track_rename and their report.
#include <cstdio>
#include <string>
#include <vector>

#include "app/cli/cli_util.h"
#include "app/cli/command_functions.h"
#include "app/cli/layout_options.h"
#include "app/cli/stop_signals.h"
#include "app/track/track.h"

namespace vdfx::app {

namespace {

struct SidecarArgs {
  std::string video, in, out;
};

void add_common(CLI::App& sub, SidecarArgs& c, io::SidecarOptions& s, io::LayoutOverride& layout) {
  sub.add_option("video", c.video, "the video")->required();
  sub.add_option("--sidecar-in", c.in,
                 "add to this sidecar (default: --sidecar-out when it exists, else a new one)");
  sub.add_option("--sidecar-out", c.out, "write the sidecar here")->required();
  sub.add_flag("--force", s.force,
               "replace an existing --sidecar-out (without it, an existing --sidecar-out is "
               "added to)");
  add_layout_options(sub, layout);
}

void fill_sidecar(const SidecarArgs& c, io::SidecarOptions& s) {
  if (!c.in.empty()) s.in = c.in;
  s.out = c.out;
}

/// "3, 7-12, 40" (at most `limit` ranges, then "...").
std::string frame_ranges(const std::vector<std::int64_t>& frames, std::size_t limit = 12) {
  std::string out;
  std::size_t ranges = 0;
  for (std::size_t i = 0; i < frames.size();) {
    std::size_t j = i;
    while (j + 1 < frames.size() && frames[j + 1] == frames[j] + 1) ++j;
    if (ranges++ == limit) return out + ", ...";
    out += (out.empty() ? "" : ", ") + std::to_string(frames[i]) +
           (j > i ? "-" + std::to_string(frames[j]) : "");
    i = j + 1;
  }
  return out;
}

void print_camera(const track::CameraRequest& r, const track::CameraReport& report) {
  std::printf("camera: %s; %lld frames, turned up to %.1f deg from frame 0\n",
              report.source_text.c_str(), static_cast<long long>(report.frames),
              report.largest_turn_deg);
  if (r.source == track::CameraSource::Estimated) {
    std::printf("analysis %.1f ms a frame (decoding aside)\n", report.analysis_ms_per_frame);
    if (!report.camm.empty())
      std::printf("the video carries a CAMM track (%s): --source camm uses it\n",
                  report.camm.c_str());
  }
  if (!report.held.empty())
    std::printf("no estimate (orientation held) at %zu frames: %s\n", report.held.size(),
                frame_ranges(report.held).c_str());
  if (!report.replaced.empty())
    std::printf("the sidecar's camera (source: %s) is replaced\n", report.replaced.c_str());
  std::printf("%.2f s -> %s%s%s\n", report.seconds, r.sidecar.out.string().c_str(),
              report.sidecar_note.empty() ? "" : " ", report.sidecar_note.c_str());
}

void print_subject(const track::SubjectRequest& r, const track::SubjectReport& report) {
  std::printf("track '%s': %lld frames, seen in %lld (mean confidence %.2f)\n", r.name.c_str(),
              static_cast<long long>(report.frames),
              static_cast<long long>(report.frames - static_cast<std::int64_t>(report.held.size())),
              report.mean_confidence);
  if (!report.held.empty())
    std::printf("not seen (last confident direction held, confidence 0) at %zu frames: %s\n",
                report.held.size(), frame_ranges(report.held).c_str());
  std::printf("%.2f s -> %s%s%s\n", report.seconds, r.sidecar.out.string().c_str(),
              report.sidecar_note.empty() ? "" : " ", report.sidecar_note.c_str());
}

}  // namespace

int cmd_track(const Args& args) {
  CLI::App cli{
      "the camera's orientation, or a subject's direction, at every frame; or a track renamed "
      "(docs/anchors.md)",
      "vdfx track"};
  cli.require_subcommand(1);
  SidecarArgs c;
  track::CameraRequest cam;
  track::SubjectRequest sub;

  CLI::App* camera = cli.add_subcommand(
      "camera", "the camera's orientation at every frame, into the sidecar's camera");
  add_common(*camera, c, cam.sidecar, cam.layout);
  std::string source = "estimated";
  camera
      ->add_option("--source", source,
                   "estimated (from the pictures) or camm (the video's CAMM track)")
      ->check(CLI::IsMember({"estimated", "camm"}));
  camera->add_option("--width", cam.options.width, "analysis pixels a turn (512)")
      ->check(whole_range(64, 4096));
  camera->add_option("--points", cam.options.points, "corners followed per key frame (400)")
      ->check(whole_range(32, 5000));
  camera
      ->add_option("--keyframe-spacing", cam.options.keyframe_spacing,
                   "frames between key frames (10)")
      ->check(whole_range(1, 1000));

  CLI::App* subject = cli.add_subcommand(
      "subject", "a subject's direction at every frame, into the sidecar's tracks");
  add_common(*subject, c, sub.sidecar, sub.layout);
  std::string at;
  subject->add_option("--name", sub.name, "the track's name ([A-Za-z0-9_-], up to 64)")->required();
  subject->add_option("--at", at, "AZ,ALT,FRAME: where the subject is at one frame")->required();
  subject->add_option("--size", sub.options.size_deg, "the subject's width, degrees (10)")
      ->check(finite_range(1.0, 90.0));
  subject->add_flag("--replace", sub.replace, "replace a track of the same name");

  track::RenameRequest ren;
  CLI::App* rename = cli.add_subcommand(
      "rename", "renames a track, and every anchor naming it, in the sidecar (no video needed)");
  rename->add_option("from", ren.from, "the track's name now")->required();
  rename->add_option("to", ren.to, "its new name ([A-Za-z0-9_-], up to 64)")->required();
  rename->add_option("--sidecar-in", c.in,
                     "rename in this sidecar (default: --sidecar-out, renamed in place)");
  rename->add_option("--sidecar-out", c.out, "write the sidecar here")->required();
  rename->add_flag("--force", ren.sidecar.force,
                   "replace an existing --sidecar-out other than --sidecar-in");

  if (const auto code = parse_cli(cli, args)) return *code;
  if (rename->parsed()) {
    fill_sidecar(c, ren.sidecar);
    const track::RenameReport report = track::run_track_rename(ren);
    std::printf("track '%s' renamed '%s' (%d %s) -> %s\n", ren.from.c_str(), ren.to.c_str(),
                report.anchors, report.anchors == 1 ? "anchor" : "anchors",
                ren.sidecar.out.string().c_str());
    return kExitOk;
  }
  const StopSignals stop;  // the tracking stops at its next frame, nothing written
  if (camera->parsed()) {
    fill_sidecar(c, cam.sidecar);
    cam.video = c.video;
    cam.source = source == "camm" ? track::CameraSource::Camm : track::CameraSource::Estimated;
    print_camera(cam, track::run_track_camera(cam));
    return kExitOk;
  }
  fill_sidecar(c, sub.sidecar);
  sub.video = c.video;
  const EvalPoint p = parse_request([&] { return parse_eval_point(at); });
  sub.at = p.direction;
  sub.frame = p.frame;
  print_subject(sub, track::run_track_subject(sub));
  return kExitOk;
}

}  // namespace vdfx::app
