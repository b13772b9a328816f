/// @file
/// @brief `vdfx export`: the baked per-pixel 360 video (--baked OUT) or the flat video along a
/// viewer's recorded head path (--path REC --out OUT); docs/export.md.
#include <unistd.h>

#include <charconv>
#include <chrono>
#include <iostream>
#include <optional>
#include <string>

#include "app/cli/cli_util.h"
#include "app/cli/command_functions.h"
#include "app/export/baked_export.h"
#include "app/export/layers.h"
#include "app/export/output_file.h"
#include "app/export/path_export.h"
#include "app/export/pipeline.h"
#include "app/export/progress.h"
#include "effects/stack_interpolator.h"
#include "io/frame_decoder.h"
#include "io/input_error.h"
#include "io/output_path.h"
#include "io/recording.h"
#include "io/sidecar.h"
#include "io/video_encoder.h"
#include "io/ycbcr.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;

struct FrameRange {
  std::int64_t first = 0, last = -1;  //!< inclusive; last < 0: not given
};

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

bool is_output_name(const fs::path& p) {
  const std::string e = p.extension().string();
  return e == ".mp4" || e == ".mov" || e == ".mkv";
}

}  // namespace

int cmd_export(const Args& args) {
  CLI::App cli{
      "Exports VIDEO with the sidecar's effects, as a baked 360 video (every equirect\n"
      "pixel with its own parameters, Spherical Video V2 metadata) for players without\n"
      "sidecar support, or as the flat video a viewer saw along a recorded head path.",
      "vdfx export"};
  std::string video, sidecar_path, baked_out, path_rec, path_out, codec = "h264", preset = "medium";
  std::string frames_text, size_text = "1280x720", chroma = "420";
  int crf = -1, threads = 0, param_step = 0;
  double fov = 90.0;
  cli.add_option("VIDEO", video, "the equirect video (or a panorama image: a one-frame video)")
      ->required();
  cli.add_option("--sidecar", sidecar_path, "the effects (.vdfx.json)")->required();
  cli.add_option("--baked", baked_out, "write the baked 360 video here (.mp4, .mov or .mkv)");
  cli.add_option("--path", path_rec, "a recorded session (.vdrec.jsonl): export the viewer's view");
  cli.add_option("--out", path_out, "with --path: the flat video to write (.mp4, .mov or .mkv)");
  cli.add_option("--codec", codec, "h264 (libx264) or h265 (libx265)")
      ->check(CLI::IsMember({"h264", "h265"}))
      ->capture_default_str();
  cli.add_option("--crf", crf,
                 "constant rate factor (0 = lossless with h264; default 18 / 20 for h265)")
      ->check(CLI::Range(0, 51));
  cli.add_option("--preset", preset, "encoder speed preset (ultrafast ... veryslow)")
      ->capture_default_str();
  cli.add_option("--chroma", chroma, "chroma subsampling: 420 (players' default) or 444")
      ->check(CLI::IsMember({"420", "444"}))
      ->capture_default_str();
  cli.add_option("--frames", frames_text, "only frames A-B (inclusive; a quick check)");
  cli.add_option("--threads", threads, "render threads (default: one per core)")
      ->check(CLI::Range(1, 256));
  cli.add_option("--param-step", param_step,
                 "--baked: evaluate the effects exactly every N pixels, bilinear between (1: every "
                 "pixel; default: a grid at most 512 columns wide)")
      ->check(CLI::Range(1, 64));
  cli.add_option("--fov", fov, "--path: horizontal field of view in degrees")
      ->check(finite_range(1.0, 179.0))
      ->capture_default_str();
  cli.add_option("--size", size_text, "--path: output size WxH")->capture_default_str();
  if (auto code = parse_cli(cli, args)) return *code;

  const bool baked = !baked_out.empty();
  ImageSize view_size;
  FrameRange range;
  try {
    if (baked == !path_rec.empty())
      throw CLI::ValidationError("export", "give either --baked OUT or --path REC --out OUT");
    if (!baked && path_out.empty()) throw CLI::ValidationError("--out", "required with --path");
    if (baked && !path_out.empty())
      throw CLI::ValidationError("--out", "goes with --path; --baked names its own output");
    const fs::path out = baked ? baked_out : path_out;
    if (!is_output_name(out))
      throw CLI::ValidationError("export",
                                 "'" + out.string() + "': the output must end .mp4, .mov or .mkv");
    if (!frames_text.empty()) range = parse_frames(frames_text);
    view_size = parse_size(size_text, "--size");
    if (baked && (cli.count("--fov") || cli.count("--size")))
      throw CLI::ValidationError(
          "export", "--fov and --size go with --path (a baked video keeps the video's size)");
    if (!baked && cli.count("--param-step"))
      throw CLI::ValidationError("--param-step", "goes with --baked");
  } catch (const CLI::ValidationError& e) {
    std::cerr << "vdfx export: " << e.what() << "\n";
    return kExitUsage;
  }
  // An output that is one of the inputs (whatever its name: links count) is refused before any
  // work, and a link the user named is written through: the file it names is replaced, the link
  // kept (docs/reliability.md, "Outputs").
  std::vector<io::NamedInput> inputs = {{"VIDEO", video}, {"--sidecar", sidecar_path}};
  if (!baked) inputs.push_back({"--path", path_rec});
  io::check_output_is_not_input(baked ? "--baked" : "--out", baked ? baked_out : path_out, inputs);
  const fs::path target = baked ? baked_out : path_out;  // as named, for messages and the format
  const fs::path target_file = io::resolve_output_path(target);

  // Inputs: every problem is the user's (exit 1), found before anything is written.
  const io::Sidecar sidecar = io::read_sidecar(sidecar_path);
  std::vector<HeadSample> head;
  if (!baked) head = head_path(io::read_recording(path_rec));
  io::DecoderOptions dopts;
  dopts.format = io::PixelFormat::RgbF32;
  auto decoder = io::open_frame_decoder(video, dopts);
  const io::VideoProperties props = decoder->properties();
  const std::int64_t last_available = props.frames - 1;
  if (range.last < 0) {
    range.first = 0;
    range.last =
        baked ? last_available : std::min(last_available, path_last_frame(head, props.fps));
  }
  if (range.last > last_available)
    throw io::InputError(video + ": --frames " + frames_text +
                         " goes past the video's last frame (" + std::to_string(last_available) +
                         ")");
  const effects::StackInterpolator stack(sidecar.effects, sidecar.interpolation, sidecar.video.fps);

  io::EncoderSettings es;
  es.codec = codec == "h265" ? "libx265" : "libx264";
  es.crf = crf >= 0 ? crf : (codec == "h265" ? 20 : 18);
  es.preset = preset;
  if (codec == "h265") es.codec_options["x265-params"] = "log-level=error";
  es.width = baked ? props.width : view_size.width;
  es.height = baked ? props.height : view_size.height;
  if (chroma == "444") {
    es.ycbcr.log2_chroma_w = es.ycbcr.log2_chroma_h = 0;
    es.ycbcr.chroma_x = es.ycbcr.chroma_y = 0.0;
  } else if (es.width % 2 || es.height % 2) {
    throw io::InputError((baked ? video : std::string("--size ") + size_text) + ": " +
                         std::to_string(es.width) + "x" + std::to_string(es.height) +
                         " is odd; 4:2:0 needs even sizes (use --chroma 444)");
  }
  es.frame_rate = props.fps;
  // The source's timestamps are kept (shifted to start at 0 for a partial range); without any
  // (stills, raw streams) frames are 1 / fps apart.
  const bool timed = decoder->timestamp(range.first).has_value() && props.time_base.num > 0;
  es.time_base = timed ? props.time_base : io::Rational{props.fps.den, props.fps.num};
  const std::int64_t shift = timed && (range.first > 0 || range.last < last_available)
                                 ? *decoder->timestamp(range.first)
                                 : 0;
  auto pts_of = [&](std::int64_t k) {
    return timed ? *decoder->timestamp(k) - shift : k - range.first;
  };
  es.spherical_equirect = baked;
  if (!props.is_still) {
    es.copy_audio_from = video;
    if (shift != 0 || range.last < last_available) {
      io::AudioWindow w;
      w.time_base = es.time_base;
      w.start = timed ? shift : range.first;
      w.end = range.last < last_available
                  ? (timed ? *decoder->timestamp(range.last + 1) : range.last + 1)
                  : INT64_MAX;
      es.audio_window = w;
    }
  }
  es.format_from = target;

  const std::int64_t total = range.last - range.first + 1;
  std::cerr << "vdfx export: " << (baked ? "baked per-pixel 360 video" : "viewer's path") << ", "
            << es.width << "x" << es.height << ", frames " << range.first << "-" << range.last
            << " (" << total << ") at " << props.fps.num << "/" << props.fps.den << " fps, "
            << es.codec << " crf " << es.crf << " " << chroma
            << (baked ? ", Spherical Video V2 equirectangular" : "") << "\n";
  std::optional<PathLayers> layers;
  if (!baked && (!sidecar.flares.empty() || !sidecar.grains.empty())) {
    layers.emplace(sidecar);
    for (const std::string& what : layers->left_out())
      std::cerr << "vdfx export: left out: " << what << "\n";
    if (layers->needs_frame_order()) {
      std::cerr << "vdfx export: an auto flare light follows the video frame by frame: one render "
                   "thread\n";
      threads = 1;
    }
  }
  if (baked) {
    std::cerr << "vdfx export: flare and grain are view-dependent and never part of a baked video";
    if (baked_drops_effects(stack))
      std::cerr << "; the vignette (measured from the eye's centre) is left out too";
    std::cerr << "\n";
  }

  BakedOptions bo;
  bo.param_step = param_step;
  PathRenderSettings ps;
  ps.hfov_deg = fov;
  ps.width = view_size.width;
  ps.height = view_size.height;
  if (layers)
    ps.view_layers = [&](cv::Mat& rgb, const cv::Mat& equirect, const xr::RenderView& view,
                         std::int64_t k) { layers->draw(rgb, equirect, view, k); };
  const FrameRenderer render =
      baked ? baked_frame_renderer(stack, bo, es.ycbcr)
            : [&](const io::Picture& src, std::int64_t k) {
                const cv::Mat rgb = io::to_rgb(src, io::PixelFormat::RgbF32);
                return io::rgb_to_ycbcr(
                    render_path_frame(rgb, stack, path_view(head, k, props.fps), k, ps), es.ycbcr);
              };

  // Signals only set a flag from here on; the guard outlives the temporary file, so the file is
  // gone before the signal is raised again.
  InterruptGuard guard;
  PendingOutput out(target_file);
  auto encoder = io::VideoEncoder::create(out.temp(), es);
  const auto start = std::chrono::steady_clock::now();
  auto seconds = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  ProgressReporter progress(std::cerr, ::isatty(2) != 0, total);
  PipelineSettings pset;
  pset.first = range.first;
  pset.last = range.last;
  pset.workers = threads;
  pset.cancel = &guard.interrupted();
  pset.on_progress = [&](std::int64_t done) { progress.update(done, seconds()); };
  const PipelineResult r = run_export_pipeline(
      *decoder, render, [&](const io::Picture& p, std::int64_t k) { encoder->write(p, pts_of(k)); },
      pset);
  if (r.cancelled) {
    std::cerr << "\nvdfx export: interrupted; " << target.string() << " left as it was\n";
    return kExitBadInput;  // not reached when a signal stopped it: the guard re-raises it
  }
  encoder->finish();
  out.commit();
  progress.finish(r.encoded, seconds());
  if (r.ended_early)
    std::cerr << "vdfx export: warning: " << video << " ends at frame " << r.end
              << " (cut short?); exported " << r.encoded << " frames\n";
  std::cout << target.string() << ": " << r.encoded << " frames, " << es.width << "x" << es.height
            << "\n";
  return kExitOk;
}

}  // namespace vdfx::app
