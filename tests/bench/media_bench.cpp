/// @file
/// @brief Video decoding and export speed against their floors, measured in the same run:
/// - decode: frames/s of vdfx's decode path (io::VideoSource, frames ready for upload: Y'CbCr
///   pictures on the worker's queue) against FFmpeg's plain decode loop of the same 4K H.264 file
///   (av_read_frame / avcodec_send_packet / avcodec_receive_frame, same threading; both open
///   the file once and decode it whole from frame 0 in every iteration);
///   counter "x_plain" = vdfx frames/s / plain frames/s (target >= 0.9);
/// - export: frames/s of the baked export pipeline (decode, per-pixel render, encode) against the
///   same pipeline with no effects (decode, encode) and the same encoder settings; counter
///   "x_encode" (target >= 0.7);
/// - one baked 4K frame with the parameters on the automatic grid and exactly per pixel, and the
///   difference between the two;
/// - the stages of one baked 1920 x 960 frame (the `vdfx bench` export clip's size), single
///   threaded as each render thread runs them: Y'CbCr -> RGB, the render with the colour effects,
///   with colour and blur, RGB -> Y'CbCr.
/// The clips, the plain loop and the sidecar are app/bench/media.h's, which `vdfx bench` measures
/// too; the clips are made once and kept in the system's temporary folder.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <opencv2/core/utility.hpp>
#include <string>

#include "app/bench/media.h"
#include "app/export/baked_export.h"
#include "app/export/pipeline.h"
#include "effects/keyframe.h"
#include "effects/stack_interpolator.h"
#include "io/frame_decoder.h"
#include "io/libav_util.h"
#include "io/sidecar.h"
#include "io/video_encoder.h"
#include "io/video_source.h"
#include "io/ycbcr.h"

namespace {

using namespace vdfx;
namespace fs = std::filesystem;

using app::bench::media_clip;
using app::bench::media_frame;
using app::bench::media_sidecar;

constexpr int k4kFrames = 24;
const fs::path& clip_4k() {
  static const fs::path p = media_clip("vdfx_bench_4k_h264.mp4", 3840, 1920, k4kFrames);
  return p;
}

/// Frames per second of the floors measured earlier in this run (the peers run first; with
/// repetitions, their best run: the ratios are conservative).
std::map<std::string, double>& floors() {
  static std::map<std::string, double> f;
  return f;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// FFmpeg's own loop: every frame of the file decoded, nothing else.
void BM_DecodePlainLoop4k(benchmark::State& state) {
  app::bench::PlainDecodeLoop plain(clip_4k());
  std::int64_t total = 0;
  double wall = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const int got = plain.run();
    total += got;
    wall += seconds_since(t0);
    benchmark::DoNotOptimize(got);
  }
  state.SetItemsProcessed(total);
  floors()["decode"] = std::max(floors()["decode"], static_cast<double>(total) / wall);
  state.counters["frames"] = static_cast<double>(total) / static_cast<double>(state.iterations());
}

/// vdfx: VideoSource's worker decoding into its queue; the consumer takes every frame as the
/// frame loop would (Y'CbCr pictures, ready for VideoLayerGl::set_frame).
void BM_DecodeVideoSource4k(benchmark::State& state) {
  io::VideoSourceOptions o;
  o.on_warning = [](const std::string&) {};
  auto src = io::VideoSource::open(clip_4k(), o);
  const std::int64_t n = src->properties().frames;
  std::int64_t total = 0;
  double wall = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    src->seek(0);
    for (std::int64_t k = 0; k < n; ++k) {
      const auto f = src->frame_at(k, std::chrono::seconds(30));
      if (!f || f->index != k) state.SkipWithError("frame missing");
      benchmark::DoNotOptimize(f->picture.planes[0].data);
    }
    total += n;
    wall += seconds_since(t0);
  }
  state.SetItemsProcessed(total);
  state.counters["frames"] = static_cast<double>(n);
  if (floors().count("decode"))
    state.counters["x_plain"] = static_cast<double>(total) / wall / floors()["decode"];
}

constexpr int kExportW = 1920, kExportH = 960, kExportFrames = 8;

/// One export run over the whole bench clip (app/bench/media.h's export_clip).
void run_export(benchmark::State& state, const app::FrameRenderer& render, const std::string& key) {
  const fs::path clip = media_clip("vdfx_bench_2k_h264.mp4", kExportW, kExportH, kExportFrames);
  const fs::path out = fs::temp_directory_path() / ("vdfx_bench_export_" + key + ".mp4");
  std::int64_t total = 0;
  double wall = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    total += app::bench::export_clip(clip, render, out);
    wall += seconds_since(t0);
  }
  state.SetItemsProcessed(total);
  const double fps = static_cast<double>(total) / wall;
  if (key == "floor")
    floors()["export"] = std::max(floors()["export"], fps);
  else if (floors().count("export"))
    state.counters["x_encode"] = fps / floors()["export"];
}

void BM_ExportEncodeOnly(benchmark::State& state) {
  run_export(state, app::bench::unchanged_renderer(), "floor");
}

void BM_ExportBaked(benchmark::State& state) {
  const bool blur = state.range(0) != 0;
  const io::Sidecar sc = media_sidecar(blur);
  const effects::StackInterpolator stack(sc.effects, sc.interpolation, sc.video.fps);
  run_export(state, app::bench::baked_renderer(stack), blur ? "blur" : "colour");
}

/// One 3840 x 1920 baked frame (the bench sidecar with blur), parameters on the automatic grid
/// (arg 0) or exactly at every pixel (arg 1); counters: the difference between the two renders
/// (8-bit output, 0..255 steps), measured once.
void BM_BakedFrame4k(benchmark::State& state) {
  const io::Sidecar sc = media_sidecar(true);
  const effects::StackInterpolator stack(sc.effects, sc.interpolation, sc.video.fps);
  cv::Mat rgb;
  media_frame(0, 3840, 1920).convertTo(rgb, CV_32FC3, 1.0 / 255.0);
  app::BakedOptions o;
  o.param_step = state.range(0) == 0 ? 0 : 1;
  static cv::Mat reference[2];
  for (auto _ : state) {
    cv::Mat out = app::render_baked(rgb, stack, 0, o);
    benchmark::DoNotOptimize(out.data);
    reference[state.range(0)] = out;
  }
  if (!reference[0].empty() && !reference[1].empty()) {
    cv::Mat a, b, d;
    cv::min(cv::max(reference[0], 0.0), 1.0, a);
    cv::min(cv::max(reference[1], 0.0), 1.0, b);
    cv::absdiff(a, b, d);
    double mx = 0;
    cv::minMaxLoc(d.reshape(1), nullptr, &mx);
    state.counters["max_diff_255"] = mx * 255.0;
    const cv::Scalar m = cv::mean(d);
    state.counters["mean_diff_255"] = (m[0] + m[1] + m[2]) / 3.0 * 255.0;
  }
}

/// One stage of the baked export's frame at 1920 x 960 on one thread (OpenCV's pool off, as in
/// a render worker whose parallel_for_ runs serially): 0 Y'CbCr -> RGB float, 1 the render with
/// the colour effects, 2 with colour and the 0..3 degree blur, 3 RGB -> Y'CbCr 4:2:0.
void BM_BakedStagesHd(benchmark::State& state) {
  const int stage = static_cast<int>(state.range(0));
  const io::Sidecar sc = media_sidecar(stage == 2);
  const effects::StackInterpolator stack(sc.effects, sc.interpolation, sc.video.fps);
  cv::Mat rgb, out, scratch;  // reused as the export's render threads reuse theirs
  media_frame(0, 1920, 960).convertTo(rgb, CV_32FC3, 1.0 / 255.0);
  const io::YcbcrInfo info;
  const io::Picture pic = io::rgb_to_ycbcr(rgb, info);
  app::BakedGridCache cache;
  app::BakedOptions o;
  o.cache = &cache;
  const int threads = cv::getNumThreads();
  cv::setNumThreads(1);
  for (auto _ : state) {
    if (stage == 0) io::to_rgb(pic, io::PixelFormat::RgbF32, out);
    if (stage == 1 || stage == 2) {
      rgb.copyTo(out);
      app::render_baked_into(out, stack, 0, o, &scratch);
    }
    if (stage == 3) benchmark::DoNotOptimize(io::rgb_to_ycbcr(rgb, info).planes[0].data);
    benchmark::DoNotOptimize(out.data);
  }
  cv::setNumThreads(threads);
}

}  // namespace

// Real time: the work runs on decoder, worker and encoder threads.
BENCHMARK(BM_DecodePlainLoop4k)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);
BENCHMARK(BM_DecodeVideoSource4k)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);
BENCHMARK(BM_ExportEncodeOnly)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);
BENCHMARK(BM_ExportBaked)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
BENCHMARK(BM_BakedStagesHd)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(BM_BakedFrame4k)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
