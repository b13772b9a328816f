/// @file
/// @brief `vdfx export`: the baked per-pixel 360 video (--baked OUT) or the flat video along a
/// viewer's recorded head path (--path REC --out OUT); docs/export.md.
/// The command parses; app/export/export_request.h does the work.
#include <charconv>
#include <iostream>
#include <string>

#include "app/cli/cli_util.h"
#include "app/cli/command_functions.h"
#include "app/cli/layout_options.h"
#include "app/cli/stop_signals.h"
#include "app/export/export_request.h"

namespace vdfx::app {
namespace {

/// "A-B" (inclusive, A <= B); throws CLI::ValidationError for anything else.
FrameRange parse_frames(const std::string& text) {
  const auto dash = text.find('-');
  FrameRange r;
  auto number = [&](std::string_view s, std::int64_t& out) {
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return !s.empty() && ec == std::errc() && p == s.data() + s.size() && out >= 0;
  };
  if (dash == std::string::npos || !number(std::string_view(text).substr(0, dash), r.first) ||
      !number(std::string_view(text).substr(dash + 1), r.last) || r.first > r.last)
    throw CLI::ValidationError("--frames",
                               "'" + text + "': expected A-B, whole frame numbers with A <= B");
  return r;
}

/// The option texts that need parsing after CLI11.
struct ExportTexts {
  std::string video, sidecar, baked_out, path_rec, path_out, codec = "h264", chroma = "420";
  std::string frames, size = "1280x720", eye = "left", stereo;
};

void add_export_options(CLI::App& cli, ExportRequest& r, ExportTexts& t) {
  cli.add_option("VIDEO", t.video, "the equirect video (or a panorama image: a one-frame video)")
      ->required();
  cli.add_option("--sidecar", t.sidecar, "the effects (.vdfx.json)")->required();
  cli.add_option("--baked", t.baked_out, "write the baked 360 video here (.mp4, .mov or .mkv)");
  cli.add_option("--path", t.path_rec,
                 "a recorded session (.vdrec.jsonl): export the viewer's view");
  cli.add_option("--out", t.path_out, "with --path: the flat video to write (.mp4, .mov or .mkv)");
  cli.add_option("--codec", t.codec,
                 "h264 (libx264), h265 (libx265) or prores (ProRes 422 HQ, 10-bit, .mov)")
      ->check(CLI::IsMember({"h264", "h265", "prores"}))
      ->capture_default_str();
  cli.add_option("--depth", r.depth,
                 "bits per sample: 8, or 10 (with --codec h265: Main10; prores is 10-bit). "
                 "Default: the source's where the codec can carry it, else 8")
      ->check(CLI::IsMember({8, 10}));
  cli.add_option("--crf", r.crf,
                 "constant rate factor (0 = lossless with h264; default 18 / 20 for h265)")
      ->check(CLI::Range(0, 51));
  cli.add_option("--preset", r.preset, "encoder speed preset (ultrafast ... veryslow)")
      ->capture_default_str();
  cli.add_option("--chroma", t.chroma, "chroma subsampling: 420 (players' default) or 444")
      ->check(CLI::IsMember({"420", "444"}))
      ->capture_default_str();
  cli.add_option("--frames", t.frames, "only frames A-B (inclusive; a quick check)");
  cli.add_option("--threads", r.threads, "render threads (default: one per core)")
      ->check(CLI::Range(1, 256));
  cli.add_option("--param-step", r.param_step,
                 "--baked: evaluate the effects exactly every N pixels, bilinear between (1: every "
                 "pixel; default: a grid at most 512 columns wide)")
      ->check(CLI::Range(1, 64));
  cli.add_flag("--stabilize", r.stabilize,
               "--baked: turn the video back into the world frame with the sidecar's camera "
               "motion (the horizon holds still; vdfx track camera records it)");
  cli.add_option("--fov", r.hfov_deg, "--path: horizontal field of view in degrees")
      ->check(finite_range(1.0, 179.0))
      ->capture_default_str();
  cli.add_option("--size", t.size, "--path: output size WxH")->capture_default_str();
  cli.add_option("--eye", t.eye, "--path on stereo video: the eye whose half is shown")
      ->check(CLI::IsMember({"left", "right"}))
      ->capture_default_str();
  cli.add_option("--stereo", t.stereo,
                 "--path on stereo video: left-right writes both eyes side by side, tagged as a "
                 "3D video")
      ->check(CLI::IsMember({"left-right"}));
  add_layout_options(cli, r.layout);
}

/// The parsed options as a request; a usage error throws (CLI::ValidationError, UsageError).
ExportRequest export_request(const CLI::App& cli, ExportRequest r, const ExportTexts& t) {
  r.video = t.video;
  r.sidecar = t.sidecar;
  r.baked_out = t.baked_out;
  r.path_recording = t.path_rec;
  r.path_out = t.path_out;
  r.h265 = t.codec == "h265";
  r.prores = t.codec == "prores";

  r.chroma_444 = t.chroma == "444";
  check_export_request(r);
  if (!t.frames.empty()) r.frames = parse_frames(t.frames);
  const ImageSize size = parse_size(t.size, "--size");
  r.width = size.width;
  r.height = size.height;
  if (r.baked() && (cli.count("--fov") || cli.count("--size")))
    throw CLI::ValidationError(
        "export", "--fov and --size go with --path (a baked video keeps the video's size)");
  if (r.baked() && cli.count("--eye"))
    throw CLI::ValidationError("--eye", "goes with --path (a baked video keeps both eyes)");
  r.eye = t.eye == "right" ? effects::EyeIndex::Right : effects::EyeIndex::Left;
  r.stereo_side_by_side = !t.stereo.empty();
  if (r.stereo_side_by_side && r.baked())
    throw CLI::ValidationError("--stereo", "goes with --path (a baked video keeps its layout)");
  if (r.stereo_side_by_side && cli.count("--eye"))
    throw CLI::ValidationError("--stereo", "shows both eyes; drop --eye");
  return r;
}

}  // namespace

int cmd_export(const Args& args) {
  CLI::App cli{
      "Exports VIDEO with the sidecar's effects, as a baked 360 video (every equirect\n"
      "pixel with its own parameters, Spherical Video V2 metadata) for players without\n"
      "sidecar support, or as the flat video a viewer saw along a recorded head path.",
      "vdfx export"};
  ExportRequest options;
  ExportTexts texts;
  add_export_options(cli, options, texts);
  if (auto code = parse_cli(cli, args)) return *code;
  const ExportRequest request = parse_request([&] { return export_request(cli, options, texts); });
  const StopSignals stop;
  const ExportResult r = run_export(request);
  if (r.cancelled)
    throw Stopped("the temporary file removed; " + request.output().string() + " left as it was");
  if (r.ended_early)
    std::cerr << "vdfx export: warning: " << request.video.string() << " ends at frame " << r.end
              << " (cut short?); exported " << r.frames << " frames\n";
  std::cout << r.output.string() << ": " << r.frames << " frames, " << r.width << "x" << r.height
            << "\n";
  return kExitOk;
}

}  // namespace vdfx::app
