/// @file
/// @brief Video decoding and export speed against their floors, measured in the same run:
/// - decode: frames/s of vdfx's decode path (io::VideoSource, frames ready for upload: Y'CbCr
///   pictures on the worker's queue) against FFmpeg's plain decode loop of the same 4K H.264 file
///   (avformat_read_frame / avcodec_send_packet / avcodec_receive_frame, same threading);
///   counter "x_plain" = vdfx frames/s / plain frames/s (target >= 0.9);
/// - export: frames/s of the baked export pipeline (decode, per-pixel render, encode) against the
///   same pipeline with no effects (decode, encode) and the same encoder settings; counter
///   "x_encode" (target >= 0.7);
/// - one baked 4K frame with the parameters on the automatic grid and exactly per pixel, and the
///   difference between the two.
/// The clips are made once with FFmpeg's libraries and kept in the system's temporary folder.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "app/export_baked.h"
#include "app/export_pipeline.h"
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

/// A moving, textured equirect frame (RGB 8-bit): gradients, a sine pattern and fine noise, so
/// the encoder spends bits as on camera footage.
cv::Mat bench_frame(int i, int w, int h) {
  cv::Mat m(h, w, CV_8UC3);
  cv::RNG rng(static_cast<std::uint64_t>(i) + 7);
  m.forEach<cv::Vec3b>([&](cv::Vec3b& p, const int* pos) {
    const double u = (pos[1] + 7.0 * i) / w, v = static_cast<double>(pos[0]) / h;
    p = cv::Vec3b(cv::saturate_cast<uchar>(40 + 170 * u), cv::saturate_cast<uchar>(60 + 150 * v),
                  cv::saturate_cast<uchar>(128 + 100 * std::sin(40.0 * u + 25.0 * v)));
  });
  cv::Mat noise(h, w, CV_8UC3);
  rng.fill(noise, cv::RNG::NORMAL, 0, 6);
  m += noise;
  return m;
}

fs::path bench_clip(const std::string& name, int w, int h, int frames) {
  const fs::path p = fs::temp_directory_path() / name;
  if (fs::exists(p)) return p;
  io::EncoderSettings s;
  s.width = w;
  s.height = h;
  s.crf = 20;
  s.preset = "veryfast";  // B-frames and CABAC, as delivered files have
  const fs::path tmp = p.string() + ".part.mp4";
  auto enc = io::VideoEncoder::create(tmp, s);
  for (int i = 0; i < frames; ++i) enc->write(io::rgb_to_ycbcr(bench_frame(i, w, h), s.ycbcr), i);
  enc->finish();
  fs::rename(tmp, p);
  return p;
}

constexpr int k4kFrames = 24;
const fs::path& clip_4k() {
  static const fs::path p = bench_clip("vdfx_bench_4k_h264.mp4", 3840, 1920, k4kFrames);
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
  std::string error;
  io::av::InputPtr in = io::av::open_input(clip_4k().string(), error);
  const AVCodec* dec = nullptr;
  const int stream = av_find_best_stream(in.get(), AVMEDIA_TYPE_VIDEO, -1, -1, &dec, 0);
  io::av::CodecPtr c(avcodec_alloc_context3(dec));
  avcodec_parameters_to_context(c.get(), in->streams[stream]->codecpar);
  c->thread_count = 0;
  c->thread_type = FF_THREAD_FRAME | FF_THREAD_SLICE;
  avcodec_open2(c.get(), dec, nullptr);
  io::av::PacketPtr pkt = io::av::make_packet();
  io::av::FramePtr frame = io::av::make_frame();
  std::int64_t total = 0;
  double wall = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    av_seek_frame(in.get(), stream, 0, AVSEEK_FLAG_BACKWARD);
    avcodec_flush_buffers(c.get());
    int got = 0;
    bool eof = false;
    while (true) {
      const int r = avcodec_receive_frame(c.get(), frame.get());
      if (r == 0) {
        ++got;
        av_frame_unref(frame.get());
        continue;
      }
      if (r == AVERROR_EOF || eof) break;
      if (av_read_frame(in.get(), pkt.get()) < 0) {
        avcodec_send_packet(c.get(), nullptr);
        eof = true;
        continue;
      }
      if (pkt->stream_index == stream) avcodec_send_packet(c.get(), pkt.get());
      av_packet_unref(pkt.get());
    }
    // The flush at EOF ends the decoder's stream: reopen the codec for the next round.
    avcodec_flush_buffers(c.get());
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
  if (floors().count("decode")) state.counters["x_plain"] = static_cast<double>(total) / wall / floors()["decode"];
}

/// A typical sidecar: tint, exposure, saturation (and, with `blur`, a blur towards one side).
io::Sidecar bench_sidecar(bool blur) {
  auto kf = [](double az, double alt, std::vector<double> v) {
    effects::Keyframe k;
    k.direction = {az, alt};
    k.frame = 0;
    k.params = std::move(v);
    return k;
  };
  auto track = [](effects::EffectType t, std::vector<effects::Keyframe> k) {
    effects::EffectTrack tr;
    tr.type = t;
    tr.keyframes = std::move(k);
    return tr;
  };
  io::Sidecar s;
  s.video.fps = 30.0;
  s.effects.push_back(track(effects::EffectType::Tint, {kf(75, -15, {1.25, 1.0, 0.7}), kf(-75, -10, {1, 1, 1})}));
  s.effects.push_back(track(effects::EffectType::Exposure, {kf(31, 5, {-1.2}), kf(-75, -10, {0.6}), kf(75, -15, {0.3})}));
  s.effects.push_back(track(effects::EffectType::Saturation, {kf(31, 5, {1.2}), kf(-150, 0, {0.15})}));
  if (blur) s.effects.push_back(track(effects::EffectType::Blur, {kf(90, 0, {3.0}), kf(-90, 0, {0.0})}));
  return s;
}

constexpr int kExportW = 1920, kExportH = 960, kExportFrames = 8;

/// One export run over the whole bench clip; `render` null: no effects (the encoder's floor).
void run_export(benchmark::State& state, const app::FrameRenderer& render, const std::string& key) {
  const fs::path clip = bench_clip("vdfx_bench_2k_h264.mp4", kExportW, kExportH, kExportFrames);
  const fs::path out = fs::temp_directory_path() / ("vdfx_bench_export_" + key + ".mp4");
  io::DecoderOptions dopts;
  std::int64_t total = 0;
  double wall = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    auto decoder = io::open_frame_decoder(clip, dopts);
    io::EncoderSettings es;
    es.width = kExportW;
    es.height = kExportH;
    es.crf = 18;
    es.preset = "medium";  // vdfx export's defaults
    es.spherical_equirect = true;
    auto enc = io::VideoEncoder::create(out, es);
    app::PipelineSettings ps;
    ps.first = 0;
    ps.last = kExportFrames - 1;
    const auto r = app::run_export_pipeline(*decoder, render,
                                            [&](const io::Picture& p, std::int64_t k) { enc->write(p, k); }, ps);
    enc->finish();
    total += r.encoded;
    wall += seconds_since(t0);
  }
  state.SetItemsProcessed(total);
  const double fps = static_cast<double>(total) / wall;
  if (key == "floor") floors()["export"] = std::max(floors()["export"], fps);
  else if (floors().count("export")) state.counters["x_encode"] = fps / floors()["export"];
}

void BM_ExportEncodeOnly(benchmark::State& state) {
  run_export(state, [](const io::Picture& p, std::int64_t) { return p; }, "floor");
}

void BM_ExportBaked(benchmark::State& state) {
  const bool blur = state.range(0) != 0;
  const io::Sidecar sc = bench_sidecar(blur);
  const effects::StackInterpolator stack(sc.effects, sc.interpolation, sc.video.fps);
  io::YcbcrInfo ycbcr;
  run_export(state,
             [&](const io::Picture& p, std::int64_t k) {
               return io::rgb_to_ycbcr(app::render_baked(io::to_rgb(p, io::PixelFormat::RgbF32), stack, k), ycbcr);
             },
             blur ? "blur" : "colour");
}

/// One 3840 x 1920 baked frame (the bench sidecar with blur), parameters on the automatic grid
/// (arg 0) or exactly at every pixel (arg 1); counters: the difference between the two renders
/// (8-bit output, 0..255 steps), measured once.
void BM_BakedFrame4k(benchmark::State& state) {
  const io::Sidecar sc = bench_sidecar(true);
  const effects::StackInterpolator stack(sc.effects, sc.interpolation, sc.video.fps);
  cv::Mat rgb;
  bench_frame(0, 3840, 1920).convertTo(rgb, CV_32FC3, 1.0 / 255.0);
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

}  // namespace

// Real time: the work runs on decoder, worker and encoder threads.
BENCHMARK(BM_DecodePlainLoop4k)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);
BENCHMARK(BM_DecodeVideoSource4k)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);
BENCHMARK(BM_ExportEncodeOnly)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);
BENCHMARK(BM_ExportBaked)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);
BENCHMARK(BM_BakedFrame4k)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
