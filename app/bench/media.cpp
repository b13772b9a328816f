/// @file
/// @brief The benchmarks' video clip, plain decode loop and export sidecar.
#include "app/bench/media.h"

#include <cmath>
#include <stdexcept>

#include "app/export/baked_export.h"
#include "effects/keyframe.h"
#include "io/frame_decoder.h"
#include "io/libav_util.h"
#include "io/video_encoder.h"
#include "io/ycbcr.h"

namespace vdfx::app::bench {

namespace fs = std::filesystem;

cv::Mat media_frame(int i, int w, int h) {
  cv::Mat m(h, w, CV_8UC3);
  m.forEach<cv::Vec3b>([&](cv::Vec3b& p, const int* pos) {
    const double u = (pos[1] + 7.0 * i) / w, v = static_cast<double>(pos[0]) / h;
    p = cv::Vec3b(cv::saturate_cast<uchar>(40 + 170 * u), cv::saturate_cast<uchar>(60 + 150 * v),
                  cv::saturate_cast<uchar>(128 + 100 * std::sin(40.0 * u + 25.0 * v)));
  });
  cv::RNG rng(static_cast<std::uint64_t>(i) + 7);
  cv::Mat noise(h, w, CV_8UC3);
  rng.fill(noise, cv::RNG::NORMAL, 0, 6);
  m += noise;
  return m;
}

fs::path encode_clip(const fs::path& path, int w, int h, int frames, int fps,
                     const std::function<cv::Mat(int)>& frame, const ClipFormat& format) {
  if (fs::exists(path)) return path;
  io::EncoderSettings s;
  s.codec = format.codec;
  if (format.codec == "libx265") s.codec_options["x265-params"] = "log-level=error";
  s.spherical_equirect = format.stereo.stereo();
  s.stereo = format.stereo;
  s.width = w;
  s.height = h;
  s.frame_rate = {fps, 1};
  s.crf = 20;
  s.preset = "veryfast";
  // Written aside and renamed, so an interrupted run leaves no half clip under the final name.
  const fs::path tmp = path.string() + ".part.mp4";
  auto enc = io::VideoEncoder::create(tmp, s);
  for (int i = 0; i < frames; ++i) enc->write(io::rgb_to_ycbcr(frame(i), s.ycbcr), i);
  enc->finish();
  fs::rename(tmp, path);
  return path;
}

fs::path media_clip(const std::string& name, int w, int h, int frames, int fps,
                    const ClipFormat& format) {
  return encode_clip(
      fs::temp_directory_path() / name, w, h, frames, fps,
      [w, h](int i) { return media_frame(i, w, h); }, format);
}

namespace {

/// The frame's planes as cv::Mat headers over its buffers.
std::array<cv::Mat, 3> planes_of(const AVFrame& f) {
  const AVPixFmtDescriptor* d = av_pix_fmt_desc_get(static_cast<AVPixelFormat>(f.format));
  if (!d || d->nb_components < 3 || (d->flags & AV_PIX_FMT_FLAG_RGB) ||
      !(d->flags & AV_PIX_FMT_FLAG_PLANAR))
    throw std::runtime_error("the plain decode loop compares planar Y'CbCr frames only");
  const int type = d->comp[0].depth > 8 ? CV_16UC1 : CV_8UC1;
  const int cw = AV_CEIL_RSHIFT(f.width, d->log2_chroma_w);
  const int ch = AV_CEIL_RSHIFT(f.height, d->log2_chroma_h);
  std::array<cv::Mat, 3> p;
  p[0] = cv::Mat(f.height, f.width, type, f.data[0], static_cast<std::size_t>(f.linesize[0]));
  for (int i = 1; i < 3; ++i)
    p[i] = cv::Mat(ch, cw, type, f.data[i], static_cast<std::size_t>(f.linesize[i]));
  return p;
}

}  // namespace

struct PlainDecodeLoop::Impl {
  io::av::InputPtr in;
  io::av::CodecPtr codec;
  int stream = -1;
  io::av::PacketPtr pkt = io::av::make_packet();
  io::av::FramePtr frame = io::av::make_frame();
};

PlainDecodeLoop::PlainDecodeLoop(const fs::path& clip) : impl_(std::make_unique<Impl>()) {
  std::string error;
  impl_->in = io::av::open_input(clip.string(), error);
  if (!impl_->in) throw std::runtime_error("cannot open " + clip.string() + ": " + error);
  const AVCodec* dec = nullptr;
  impl_->stream = av_find_best_stream(impl_->in.get(), AVMEDIA_TYPE_VIDEO, -1, -1, &dec, 0);
  if (impl_->stream < 0) throw std::runtime_error(clip.string() + " has no video stream");
  impl_->codec.reset(avcodec_alloc_context3(dec));
  AVCodecContext* c = impl_->codec.get();
  avcodec_parameters_to_context(c, impl_->in->streams[impl_->stream]->codecpar);
  c->thread_count = 0;
  c->thread_type = FF_THREAD_FRAME | FF_THREAD_SLICE;
  if (avcodec_open2(c, dec, nullptr) < 0)
    throw std::runtime_error("cannot open the decoder of " + clip.string());
}

PlainDecodeLoop::~PlainDecodeLoop() = default;

int PlainDecodeLoop::run(const PlanesFn& each) {
  Impl& m = *impl_;
  av_seek_frame(m.in.get(), m.stream, 0, AVSEEK_FLAG_BACKWARD);
  avcodec_flush_buffers(m.codec.get());  // also ends the previous run's draining state
  int got = 0;
  bool eof = false;
  for (;;) {
    const int r = avcodec_receive_frame(m.codec.get(), m.frame.get());
    if (r == 0) {
      ++got;
      if (each) each(planes_of(*m.frame));
      av_frame_unref(m.frame.get());
      continue;
    }
    if (r == AVERROR_EOF || eof) break;
    if (av_read_frame(m.in.get(), m.pkt.get()) < 0) {
      avcodec_send_packet(m.codec.get(), nullptr);  // drain the frames still in the decoder
      eof = true;
      continue;
    }
    if (m.pkt->stream_index == m.stream) avcodec_send_packet(m.codec.get(), m.pkt.get());
    av_packet_unref(m.pkt.get());
  }
  return got;
}

io::Sidecar media_sidecar(bool blur) {
  const auto kf = [](double az, double alt, std::vector<double> v) {
    effects::Keyframe k;
    k.direction = {az, alt};
    k.frame = 0;
    k.params = std::move(v);
    return k;
  };
  const auto track = [](effects::EffectType t, std::vector<effects::Keyframe> k) {
    effects::EffectTrack tr;
    tr.type = t;
    tr.keyframes = std::move(k);
    return tr;
  };
  using effects::EffectType;
  io::Sidecar s;
  s.video.fps = 30.0;
  s.effects.push_back(
      track(EffectType::Tint, {kf(75, -15, {1.25, 1.0, 0.7}), kf(-75, -10, {1, 1, 1})}));
  s.effects.push_back(
      track(EffectType::Exposure, {kf(31, 5, {-1.2}), kf(-75, -10, {0.6}), kf(75, -15, {0.3})}));
  s.effects.push_back(track(EffectType::Saturation, {kf(31, 5, {1.2}), kf(-150, 0, {0.15})}));
  if (blur) s.effects.push_back(track(EffectType::Blur, {kf(90, 0, {3.0}), kf(-90, 0, {0.0})}));
  return s;
}

std::int64_t export_clip(const fs::path& clip, const FrameRenderer& render, const fs::path& out,
                         const ExportFormat& format) {
  auto decoder = io::open_frame_decoder(clip, {});
  const io::VideoProperties& props = decoder->properties();
  io::EncoderSettings es;
  es.width = props.width;
  es.height = props.height;
  es.codec = format.h265 ? "libx265" : "libx264";
  if (format.h265) es.codec_options["x265-params"] = "log-level=error";
  es.ycbcr.bit_depth = format.bit_depth;
  es.crf = format.h265 ? 20 : 18;
  es.preset = "medium";  // vdfx export's defaults
  es.spherical_equirect = true;
  auto enc = io::VideoEncoder::create(out, es);
  PipelineSettings ps;
  ps.first = 0;
  ps.last = props.frames - 1;
  const auto r = run_export_pipeline(
      *decoder, render, [&](const io::Picture& p, std::int64_t k) { enc->write(p, k); }, ps);
  enc->finish();
  return r.encoded;
}

FrameRenderer baked_renderer(const effects::StackInterpolator& stack,
                             const effects::StereoLayout& layout, int bit_depth) {
  io::YcbcrInfo out;
  out.bit_depth = bit_depth;
  return baked_frame_renderer(stack, {}, out, layout);
}

FrameRenderer unchanged_renderer() {
  return [](const io::Picture& p, std::int64_t) { return p; };
}

}  // namespace vdfx::app::bench
