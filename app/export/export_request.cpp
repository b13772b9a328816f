/// @file
/// @brief run_export: inputs read and checked, the encoder's settings, the plan announced, the
/// frame renderer chosen (baked or viewer's path), then the pipeline into a pending output.
#include "app/export/export_request.h"

#include <unistd.h>

#include <chrono>
#include <functional>
#include <iostream>
#include <memory>
#include <vector>

#include "app/cli/command_registry.h"
#include "app/cli/layout_options.h"
#include "app/cli/progress.h"
#include "app/export/baked_export.h"
#include "app/export/layers.h"
#include "app/export/output_file.h"
#include "app/export/path_export.h"
#include "app/export/pipeline.h"
#include "effects/stack_interpolator.h"
#include "io/eye_picture.h"
#include "io/frame_decoder.h"
#include "io/input_error.h"
#include "io/output_path.h"
#include "io/recording.h"
#include "io/sidecar.h"
#include "io/sidecar_sets.h"
#include "io/video_encoder.h"
#include "io/ycbcr.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;

bool is_output_name(const fs::path& p) {
  const std::string e = p.extension().string();
  return e == ".mp4" || e == ".mov" || e == ".mkv";
}

/// Everything an export reads, checked before anything is written (every problem: exit 1).
struct Inputs {
  io::Sidecar sidecar;
  std::vector<HeadSample> head;  //!< path exports only
  std::unique_ptr<io::FrameDecoder> decoder;
  io::VideoProperties props;
  effects::StereoLayout layout;  //!< the source's (docs/stereo.md)
  FrameRange range;
  std::int64_t last_available = 0;
};

Inputs read_inputs(const ExportRequest& req) {
  Inputs in;
  in.sidecar = io::read_sidecar(req.sidecar);
  if (!req.baked()) in.head = head_path(io::read_recording(req.path_recording));
  io::DecoderOptions dopts;
  dopts.format = io::PixelFormat::RgbF32;
  in.decoder = io::open_frame_decoder(req.video, dopts);
  in.props = in.decoder->properties();
  in.layout = shown_layout(in.props, req.layout, &in.sidecar.video, req.sidecar);
  in.last_available = in.props.frames - 1;
  if (req.frames) {
    in.range = *req.frames;
  } else {
    in.range.last = req.baked()
                        ? in.last_available
                        : std::min(in.last_available, path_last_frame(in.head, in.props.fps));
  }
  if (in.range.last > in.last_available)
    throw io::InputError(req.video.string() + ": --frames " + std::to_string(in.range.first) + "-" +
                         std::to_string(in.range.last) + " goes past the video's last frame (" +
                         std::to_string(in.last_available) + ")");
  return in;
}

/// The encoder's settings and each frame's timestamp: the source's (shifted to start at 0 for a
/// partial range), or 1 / fps apart without any (stills, raw streams); the audio cut to match.
struct Encoding {
  io::EncoderSettings settings;
  std::function<std::int64_t(std::int64_t frame)> pts_of;
};

/// --depth, or by default the source's: 10 for a source deeper than 8 bits where the codec can
/// write 10 (h265 or prores), ProRes always 10, else 8.
int export_depth(const ExportRequest& req, const io::VideoProperties& source) {
  if (req.depth != 0) return req.depth;
  if (req.prores) return 10;
  return source.bit_depth > 8 && req.h265 ? 10 : 8;
}

io::EncoderSettings codec_settings(const ExportRequest& req, const Inputs& in) {
  io::EncoderSettings es;
  es.codec = req.prores ? "prores_ks" : req.h265 ? "libx265" : "libx264";
  es.crf = req.prores ? -1 : req.crf >= 0 ? req.crf : (req.h265 ? 20 : 18);
  es.ycbcr.bit_depth = export_depth(req, in.props);
  es.preset = req.preset;
  if (req.h265) es.codec_options["x265-params"] = "log-level=error";
  if (!req.encoder.empty()) {
    es.codec = req.encoder;
    es.codec_options = req.encoder_options;
  }
  es.width = req.baked() ? in.props.width : req.width * (req.stereo_side_by_side ? 2 : 1);
  es.height = req.baked() ? in.props.height : req.height;
  if (req.prores) {  // ProRes 422 HQ: 4:2:2, its own rate control (no crf, no preset)
    es.codec_options["profile"] = "3";
    es.preset.clear();
    es.ycbcr.log2_chroma_w = 1;
    es.ycbcr.log2_chroma_h = 0;
    es.ycbcr.chroma_y = 0.0;
  }
  if (req.chroma_444) {
    es.ycbcr.log2_chroma_w = es.ycbcr.log2_chroma_h = 0;
    es.ycbcr.chroma_x = es.ycbcr.chroma_y = 0.0;
  } else if (es.width % 2 || es.height % 2) {
    const std::string size = std::to_string(es.width) + "x" + std::to_string(es.height);
    throw io::InputError((req.baked() ? req.video.string() : "--size " + size) + ": " + size +
                         " is odd; 4:2:0 needs even sizes (use --chroma 444)");
  }
  es.frame_rate = in.props.fps;
  es.spherical_equirect = req.baked();
  if (req.baked()) es.stereo = in.layout;  // a stereo source stays stereo, tagged so
  if (req.stereo_side_by_side) es.stereo = {effects::StereoMode::LeftRight, 360};
  es.format_from = req.output();
  return es;
}

Encoding encoding(const ExportRequest& req, const Inputs& in) {
  Encoding e{codec_settings(req, in), {}};
  io::EncoderSettings& es = e.settings;
  io::FrameDecoder& decoder = *in.decoder;
  const FrameRange range = in.range;
  const bool timed = decoder.timestamp(range.first).has_value() && in.props.time_base.num > 0;
  es.time_base = timed ? in.props.time_base : io::Rational{in.props.fps.den, in.props.fps.num};
  const bool partial = range.first > 0 || range.last < in.last_available;
  const std::int64_t shift = timed && partial ? *decoder.timestamp(range.first) : 0;
  e.pts_of = [&decoder, timed, shift, range](std::int64_t k) {
    return timed ? *decoder.timestamp(k) - shift : k - range.first;
  };
  if (!in.props.is_still) {
    es.copy_audio_from = req.video;
    if (shift != 0 || range.last < in.last_available) {
      io::AudioWindow w;
      w.time_base = es.time_base;
      w.start = timed ? shift : range.first;
      w.end = range.last < in.last_available
                  ? (timed ? *decoder.timestamp(range.last + 1) : range.last + 1)
                  : INT64_MAX;
      es.audio_window = w;
    }
  }
  return e;
}

/// ", top-bottom stereo, VR180" and the like for the announcement; "" for mono 360.
std::string stereo_note(const ExportRequest& req, const Inputs& in) {
  std::string s;
  if (in.layout.stereo())
    s += ", " + std::string(effects::stereo_mode_name(in.layout.mode)) +
         (req.baked() ? " stereo" : " stereo source");
  if (in.layout.coverage_deg != 360) s += ", VR180";
  return s;
}

/// "libx264 crf 18 420", "prores_ks 422 10-bit": the encoder, its rate (when it has a crf), the
/// chroma subsampling and a depth above 8 bits.
std::string codec_note(const io::EncoderSettings& es) {
  const io::YcbcrInfo& y = es.ycbcr;
  const char* chroma = y.log2_chroma_w == 0 ? "444" : y.log2_chroma_h == 0 ? "422" : "420";
  return es.codec + (es.crf >= 0 ? " crf " + std::to_string(es.crf) : std::string()) + " " +
         chroma + (y.bit_depth > 8 ? " " + std::to_string(y.bit_depth) + "-bit" : std::string());
}

/// The first line on stderr: what is exported, how.
void announce(const ExportRequest& req, const Inputs& in, const io::EncoderSettings& es) {
  const FrameRange r = in.range;
  std::cerr << "vdfx export: " << (req.baked() ? "baked per-pixel 360 video" : "viewer's path")
            << ", " << es.width << "x" << es.height << ", frames " << r.first << "-" << r.last
            << " (" << r.last - r.first + 1 << ") at " << in.props.fps.num << "/"
            << in.props.fps.den << " fps, " << codec_note(es)
            << (req.baked() ? ", Spherical Video V2 equirectangular" : "") << stereo_note(req, in)
            << "\n";
  if (!es.copy_audio_from.empty())
    for (const std::string& note : io::audio_copy_notes(es.copy_audio_from))
      std::cerr << "vdfx export: note: " << note << "\n";
  if (req.baked() && in.layout.mode == effects::StereoMode::RightLeft &&
      req.output().extension() != ".mkv")
    std::cerr << "vdfx export: note: MP4/MOV's st3d box has no right-left mode; the stereo tag is "
                 "left out (write .mkv to keep it)\n";
}

/// Flare and grain of a path export (none when the sidecar has neither), with the notes on what
/// is left out; an auto light needs frames in order, so `threads` becomes 1.
std::unique_ptr<PathLayers> path_layers(const io::Sidecar& sidecar, int& threads) {
  if (sidecar.flares.empty() && sidecar.grains.empty()) return nullptr;
  auto layers = std::make_unique<PathLayers>(sidecar);
  for (const std::string& what : layers->left_out())
    std::cerr << "vdfx export: left out: " << what << "\n";
  if (layers->needs_frame_order()) {
    std::cerr << "vdfx export: an auto flare light follows the video frame by frame: one render "
                 "thread\n";
    threads = 1;
  }
  return layers;
}

void note_baked_leaves_out(const effects::StackInterpolator& stack) {
  std::cerr << "vdfx export: flare and grain are view-dependent and never part of a baked video";
  if (baked_drops_effects(stack))
    std::cerr << "; the vignette (measured from the eye's centre) is left out too";
  std::cerr << "\n";
}

/// Source frame -> the picture to encode: the baked equirect, or the view along the head path.
FrameRenderer frame_renderer(const ExportRequest& req, const Inputs& in,
                             const effects::StackInterpolator& stack, PathLayers* layers,
                             const io::YcbcrInfo& out) {
  if (req.baked()) {
    BakedOptions bo;
    bo.param_step = req.param_step;
    return baked_frame_renderer(stack, bo, out, in.layout);
  }
  PathRenderSettings ps;
  ps.hfov_deg = req.hfov_deg;
  ps.width = req.width;
  ps.height = req.height;
  ps.layout = in.layout;
  ps.eye = req.eye;
  if (layers)
    ps.view_layers = [layers](cv::Mat& rgb, const cv::Mat& equirect, const xr::RenderView& view,
                              std::int64_t k) { layers->draw(rgb, equirect, view, k); };
  const std::vector<HeadSample>& head = in.head;
  const io::Rational fps = in.props.fps;
  const bool both = req.stereo_side_by_side;
  return [&stack, &head, fps, ps, out, both](const io::Picture& src, std::int64_t k) {
    const cv::Mat rgb = io::to_rgb_by_eye(src, ps.layout, io::PixelFormat::RgbF32);
    const PathView view = path_view(head, k, fps);
    if (!both) return io::rgb_to_ycbcr(render_path_frame(rgb, stack, view, k, ps), out);
    PathRenderSettings right = ps;
    right.eye = effects::EyeIndex::Right;
    cv::Mat pair;
    cv::hconcat(render_path_frame(rgb, stack, view, k, ps),
                render_path_frame(rgb, stack, view, k, right), pair);
    // Each eye's view encoded on its own (a flat side-by-side pair).
    return io::rgb_to_ycbcr_by_eye(pair, out, {effects::StereoMode::LeftRight, 360});
  };
}

/// Decodes, renders and encodes the range into `out`'s temporary file, with progress on stderr;
/// complete, the file replaces the output.
PipelineResult encode_frames(Inputs& in, const FrameRenderer& render, const Encoding& enc,
                             int threads, const std::atomic<bool>& cancel, PendingOutput& out) {
  auto encoder = io::VideoEncoder::create(out.temp(), enc.settings);
  const auto start = std::chrono::steady_clock::now();
  auto seconds = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  ProgressReporter progress(std::cerr, ::isatty(2) != 0, in.range.last - in.range.first + 1);
  PipelineSettings pset;
  pset.first = in.range.first;
  pset.last = in.range.last;
  pset.workers = threads;
  pset.cancel = &cancel;
  pset.on_progress = [&](std::int64_t done) { progress.update(done, seconds()); };
  const PipelineResult r = run_export_pipeline(
      *in.decoder, render,
      [&](const io::Picture& p, std::int64_t k) { encoder->write(p, enc.pts_of(k)); }, pset);
  if (r.cancelled) return r;
  encoder->finish();
  out.commit();
  progress.finish(r.encoded, seconds());
  return r;
}

/// --depth and --codec together (docs/export.md, "10 bits").
void check_depth(const ExportRequest& req) {
  if (req.depth != 0 && req.depth != 8 && req.depth != 10) throw UsageError("--depth: 8 or 10");
  if (req.prores && req.depth == 8)
    throw UsageError("--codec prores: ProRes 422 HQ is 10-bit (drop --depth 8)");
  if (req.prores && req.output().extension() != ".mov")
    throw UsageError("--codec prores: write a .mov ('" + req.output().string() + "')");
  if (req.depth == 10 && !req.h265 && !req.prores)
    throw UsageError("--depth 10: needs --codec h265 (Main10) or --codec prores");
}

}  // namespace

void check_export_request(const ExportRequest& req) {
  if (req.baked() == !req.path_recording.empty())
    throw UsageError("export: give either --baked OUT or --path REC --out OUT");
  if (!req.baked() && req.path_out.empty()) throw UsageError("--out: required with --path");
  if (req.baked() && !req.path_out.empty())
    throw UsageError("--out: goes with --path; --baked names its own output");
  if (!is_output_name(req.output()))
    throw UsageError("export: '" + req.output().string() +
                     "': the output must end .mp4, .mov or .mkv");
  if (!req.baked() && req.param_step > 0) throw UsageError("--param-step: goes with --baked");
  check_depth(req);
}

ExportResult run_export(const ExportRequest& req) {
  check_export_request(req);
  // An output that is one of the inputs (whatever its name: links count) is refused before any
  // work, and a link the user named is written through: the file it names is replaced, the link
  // kept (docs/reliability.md, "Outputs").
  std::vector<io::NamedInput> named = {{"VIDEO", req.video}, {"--sidecar", req.sidecar}};
  if (!req.baked()) named.push_back({"--path", req.path_recording});
  io::check_output_is_not_input(req.baked() ? "--baked" : "--out", req.output(), named);
  const fs::path target_file = io::resolve_output_path(req.output());

  Inputs in = read_inputs(req);
  if (req.stereo_side_by_side && !in.layout.stereo())
    throw io::InputError(req.video.string() +
                         ": --stereo left-right needs a stereo video (this one is mono; --layout "
                         "says otherwise)");
  const io::Sidecar& sidecar = in.sidecar;
  const effects::StackInterpolator stack = io::stack_of(sidecar);
  const Encoding enc = encoding(req, in);
  announce(req, in, enc.settings);
  int threads = req.threads;
  const std::unique_ptr<PathLayers> layers = req.baked() ? nullptr : path_layers(sidecar, threads);
  if (req.baked()) note_baked_leaves_out(stack);
  const FrameRenderer render = frame_renderer(req, in, stack, layers.get(), enc.settings.ycbcr);

  // Signals only set a flag from here on; the guard outlives the temporary file, so the file is
  // gone before the signal is raised again.
  InterruptGuard guard;
  PendingOutput out(target_file);
  const PipelineResult r = encode_frames(in, render, enc, threads, guard.interrupted(), out);
  ExportResult result{req.output(), r.encoded, enc.settings.width, enc.settings.height};
  result.cancelled = r.cancelled;
  result.ended_early = r.ended_early;
  result.end = r.end;
  // Said before the guard re-raises the signal (which ends the process once `out` is gone).
  if (r.cancelled)
    std::cerr << "\nvdfx export: interrupted; " << req.output().string() << " left as it was\n";
  return result;
}

}  // namespace vdfx::app
