/// @file
/// @brief Test clips made inside the tests with FFmpeg's libraries (io::VideoEncoder for video, a
/// few libavcodec calls for an AAC tone), frames that carry their own index, and the `ffmpeg`
/// command line as the outside reference for decoded pixels.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "io/libav_util.h"
#include "io/video_encoder.h"
#include "io/ycbcr.h"

namespace vdfx::test_media {

namespace fs = std::filesystem;

/// Frame i's index as 8 black/white stripes (RGB 8-bit): robust to any lossy codec.
inline cv::Mat coded_frame(int index, int width = 128, int height = 64) {
  cv::Mat m(height, width, CV_8UC3, cv::Scalar(0, 0, 0));
  const int stripe = width / 8;
  for (int b = 0; b < 8; ++b)
    if (index & (1 << b))
      m(cv::Rect(b * stripe, 0, stripe, height)).setTo(cv::Scalar(255, 255, 255));
  return m;
}

/// Reads the stripes back (RGB 8-bit or float; the middle row).
inline int frame_code(const cv::Mat& rgb) {
  cv::Mat m8;
  if (rgb.depth() == CV_32F)
    rgb.convertTo(m8, CV_8UC3, 255.0);
  else
    m8 = rgb;
  const int stripe = m8.cols / 8;
  int code = 0;
  for (int b = 0; b < 8; ++b)
    if (m8.at<cv::Vec3b>(m8.rows / 2, b * stripe + stripe / 2)[1] > 127) code |= 1 << b;
  return code;
}

/// A smooth colourful frame (RGB 8-bit) that moves with i: chroma varies slowly, so chroma
/// resampling differences between decoders stay small and the comparison tests the matrix.
inline cv::Mat smooth_frame(int i, int width, int height) {
  cv::Mat m(height, width, CV_8UC3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double u = (x + 3.0 * i) / width, v = static_cast<double>(y) / height;
      m.at<cv::Vec3b>(y, x) =
          cv::Vec3b(cv::saturate_cast<uchar>(30 + 200 * u), cv::saturate_cast<uchar>(40 + 180 * v),
                    cv::saturate_cast<uchar>(128 + 90 * std::sin(6.0 * u + 3.0 * v)));
    }
  return m;
}

/// Flat 32 x 32 colour patches (RGB 8-bit), saturated and pale, dark and bright, changing with
/// i. Inside a patch chroma is constant, so any two decoders agree there whatever chroma
/// upsampling they use: what remains is the matrix, the range and their arithmetic.
inline cv::Mat patch_frame(int i, int width, int height) {
  static const std::uint8_t kColours[][3] = {
      {230, 30, 40},  {30, 200, 60},  {40, 60, 220},   {240, 230, 50},
      {20, 220, 230}, {220, 40, 210}, {128, 128, 128}, {250, 250, 250},
      {8, 8, 8},      {180, 120, 90}, {90, 140, 200},  {60, 90, 40},
      {255, 0, 0},    {0, 255, 0},    {0, 0, 255},     {200, 170, 160}};
  cv::Mat m(height, width, CV_8UC3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const auto* c = kColours[(x / 32 + 3 * (y / 32) + i) % 16];
      m.at<cv::Vec3b>(y, x) = cv::Vec3b(c[0], c[1], c[2]);
    }
  return m;
}

/// Largest per-channel difference inside the patches of patch_frame, in 1/255 steps. `margin`
/// pixels from every patch edge are left out: wide enough for a bicubic chroma upsampler (what
/// swscale uses for odd widths) and for chroma siting.
inline int max_patch_interior_diff(const cv::Mat& a, const cv::Mat& b, int margin = 8) {
  int worst = 0;
  for (int y = 0; y < a.rows; ++y)
    for (int x = 0; x < a.cols; ++x) {
      const int px = x % 32, py = y % 32;
      if (px < margin || px >= 32 - margin || py < margin || py >= 32 - margin) continue;
      if (x / 32 * 32 + 32 > a.cols || y / 32 * 32 + 32 > a.rows) continue;  // cut patches
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(a.at<cv::Vec3b>(y, x)[c] - b.at<cv::Vec3b>(y, x)[c]));
    }
  return worst;
}

struct ClipSpec {
  int width = 128, height = 64, frames = 48;
  io::Rational fps{24, 1};
  io::Rational time_base{0, 1};   //!< 0: 1 / fps
  std::vector<std::int64_t> pts;  //!< empty: 0, 1, 2, ... in 1 / fps
  std::string codec = "libx264";
  io::YcbcrInfo ycbcr;  //!< BT.709 limited 4:2:0 by default
  std::map<std::string, std::string> options{{"qp", "12"}};
  std::string preset = "superfast";  //!< x264: keeps B-frames (ultrafast has none)
  int gop = 0, max_b_frames = 3;
  int rotation_deg = 0;
  bool spherical = false;
  effects::StereoLayout stereo;  //!< with spherical: the st3d mode and equi bounds written
  fs::path audio_from;
  std::function<cv::Mat(int)> frame;  //!< RGB 8-bit frame i; default coded_frame
};

inline fs::path write_clip(const fs::path& path, const ClipSpec& c) {
  io::EncoderSettings s;
  s.codec = c.codec;
  s.width = c.width;
  s.height = c.height;
  s.frame_rate = c.fps;
  s.time_base = c.time_base;
  s.ycbcr = c.ycbcr;
  s.codec_options = c.options;
  s.preset = c.codec.starts_with("libx26") ? c.preset : "";
  s.gop = c.gop;
  s.max_b_frames = c.codec.starts_with("libx26") || c.codec == "mpeg4" ? c.max_b_frames : -1;
  s.display_rotation_deg = c.rotation_deg;
  s.spherical_equirect = c.spherical;
  s.stereo = c.stereo;
  s.copy_audio_from = c.audio_from;
  if (c.codec == "libx265") s.codec_options.emplace("x265-params", "log-level=error");
  auto enc = io::VideoEncoder::create(path, s);
  for (int i = 0; i < c.frames; ++i) {
    const cv::Mat rgb = c.frame ? c.frame(i) : coded_frame(i, c.width, c.height);
    enc->write(io::rgb_to_ycbcr(rgb, c.ycbcr),
               c.pts.empty() ? i : c.pts[static_cast<std::size_t>(i)]);
  }
  enc->finish();
  return path;
}

/// An audio-only file (.m4a): `seconds` of a 440 Hz AAC tone at 48 kHz, mono.
inline fs::path write_tone(const fs::path& path, double seconds) {
  using namespace io::av;
  AVFormatContext* raw = nullptr;
  EXPECT_GE(avformat_alloc_output_context2(&raw, nullptr, "ipod", path.string().c_str()), 0);
  const AVCodec* codec = avcodec_find_encoder(AV_CODEC_ID_AAC);
  CodecPtr c(avcodec_alloc_context3(codec));
  c->sample_rate = 48000;
  c->sample_fmt = AV_SAMPLE_FMT_FLTP;
  av_channel_layout_default(&c->ch_layout, 1);
  c->bit_rate = 64000;
  c->time_base = {1, 48000};
  if (raw->oformat->flags & AVFMT_GLOBALHEADER) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  EXPECT_GE(avcodec_open2(c.get(), codec, nullptr), 0);
  AVStream* st = avformat_new_stream(raw, nullptr);
  st->time_base = c->time_base;
  avcodec_parameters_from_context(st->codecpar, c.get());
  EXPECT_GE(avio_open(&raw->pb, path.string().c_str(), AVIO_FLAG_WRITE), 0);
  EXPECT_GE(avformat_write_header(raw, nullptr), 0);
  FramePtr f = make_frame();
  PacketPtr pkt = make_packet();
  auto drain = [&] {
    while (avcodec_receive_packet(c.get(), pkt.get()) == 0) {
      av_packet_rescale_ts(pkt.get(), c->time_base, st->time_base);
      pkt->stream_index = st->index;
      av_interleaved_write_frame(raw, pkt.get());
    }
  };
  const std::int64_t total = static_cast<std::int64_t>(seconds * 48000);
  for (std::int64_t t = 0; t < total; t += c->frame_size) {
    f->nb_samples = c->frame_size;
    f->format = c->sample_fmt;
    av_channel_layout_copy(&f->ch_layout, &c->ch_layout);
    av_frame_get_buffer(f.get(), 0);
    auto* s = reinterpret_cast<float*>(f->data[0]);
    for (int k = 0; k < c->frame_size; ++k)
      s[k] = 0.3f * static_cast<float>(std::sin(2 * M_PI * 440.0 * (t + k) / 48000.0));
    f->pts = t;
    avcodec_send_frame(c.get(), f.get());
    av_frame_unref(f.get());
    drain();
  }
  avcodec_send_frame(c.get(), nullptr);
  drain();
  av_write_trailer(raw);
  avio_closep(&raw->pb);
  avformat_free_context(raw);
  return path;
}

/// `ffmpeg -i CLIP -vf select=eq(n\,FRAME) -frames:v 1 -pix_fmt rgb24` as an RGB CV_8UC3 mat of
/// `width` x `height` (the displayed size); fails the test (never skips) when ffmpeg is missing.
inline cv::Mat ffmpeg_rgb24(const fs::path& clip, int frame, int width, int height) {
  const std::string cmd = "ffmpeg -v error -nostdin -i '" + clip.string() +
                          "' -vf 'select=eq(n\\," + std::to_string(frame) +
                          ")' -frames:v 1 -pix_fmt rgb24 -f rawvideo -";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) {
    ADD_FAILURE() << "cannot run: " << cmd;
    return {};
  }
  cv::Mat m(height, width, CV_8UC3);
  const std::size_t want = static_cast<std::size_t>(width) * height * 3;
  const std::size_t got = std::fread(m.data, 1, want, p);
  const int rc = pclose(p);
  if (rc != 0 || got != want) {
    ADD_FAILURE() << "ffmpeg (Debian package ffmpeg, .ci/deps.sh) failed or gave " << got << " of "
                  << want << " bytes: " << cmd;
    return {};
  }
  return m;
}

/// Largest per-channel difference of two RGB CV_8UC3 images, in 1/255 steps.
inline int max_abs_diff(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size() || a.type() != b.type()) return 1000;
  cv::Mat d;
  cv::absdiff(a, b, d);
  double mx = 0;
  cv::minMaxLoc(d.reshape(1), nullptr, &mx);
  return static_cast<int>(mx);
}

}  // namespace vdfx::test_media
