/// @file
/// @brief Video decode knob of `vdfx bench`: vdfx's decode path (io::VideoSource: the worker
/// decoding into its queue, every frame taken in order as the frame loop takes it, Y'CbCr
/// pictures ready for upload) against FFmpeg's plain decode loop (app/bench/media.h) of the same
/// generated H.264 clip, both opening the file in every sample. The error is the largest
/// difference between the code values the two deliver, over every sample of every frame: 0 when
/// vdfx hands on the decoder's own pictures, in order.
///
/// Stereo (docs/stereo.md): a generated top-bottom HEVC clip (tagged, 4096 x 4096 in a full run)
/// against the plain loop of that file, and against vdfx's decode of the same pictures untagged
/// (mono) timed beside it (`vs_mono`: the stereo clip's frames per second over the mono one's;
/// the goal is at least 0.9), with the mono clip's own row against the plain loop.
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "app/bench/media.h"
#include "app/bench/registry.h"
#include "io/video_source.h"

namespace vdfx::app::bench {
namespace {

constexpr const char* kKnob = "video.decode";

std::unique_ptr<io::VideoSource> open_source(const std::filesystem::path& clip) {
  io::VideoSourceOptions o;
  o.on_warning = [](const std::string&) {};  // a missing frame fails the row (frame_of)
  return io::VideoSource::open(clip, o);
}

io::VideoFrame frame_of(io::VideoSource& src, std::int64_t k) {
  const auto f = src.frame_at(k, std::chrono::seconds(30));
  if (!f || f->index != k)
    throw std::runtime_error("frame " + std::to_string(k) + " of the bench clip did not arrive");
  return *f;
}

/// Every frame through io::VideoSource beside the plain loop's: max and RMS difference of the
/// code values (all three planes).
ErrorStats decode_error(const std::filesystem::path& clip, std::int64_t frames) {
  auto src = open_source(clip);
  PlainDecodeLoop plain_loop(clip);
  std::int64_t k = 0;
  double max = 0.0, sum2 = 0.0, count = 0.0;
  const int got = plain_loop.run([&](const std::array<cv::Mat, 3>& plain) {
    const io::VideoFrame f = frame_of(*src, k++);
    for (int i = 0; i < 3; ++i) {
      const cv::Mat& mine = f.picture.planes[static_cast<std::size_t>(i)];
      if (mine.size() != plain[i].size() || mine.type() != plain[i].type())
        throw std::runtime_error("plane " + std::to_string(i) + " differs in size or depth");
      cv::Mat d;
      cv::absdiff(mine, plain[i], d);
      double m = 0.0;
      cv::minMaxLoc(d, nullptr, &m);
      max = std::max(max, m);
      sum2 += cv::norm(d, cv::NORM_L2SQR);
      count += static_cast<double>(d.total());
    }
  });
  if (got != frames)
    throw std::runtime_error("the plain loop decoded " + std::to_string(got) +
                             " frames, VideoSource has " + std::to_string(frames));
  return {max, std::sqrt(sum2 / count)};
}

/// vdfx's decode of every frame of an opened source (the timed work of a row).
void decode_all(io::VideoSource& src, std::int64_t frames) {
  src.seek(0);
  for (std::int64_t k = 0; k < frames; ++k) frame_of(src, k);
}

/// vdfx's decode of `clip` against the plain loop of it: time, peer time, error, frame rates.
void decode_row(Row& row, const Context& ctx, const std::filesystem::path& clip, int frames) {
  auto src = open_source(clip);
  PlainDecodeLoop plain(clip);
  const double n = frames;
  const auto t = measure_pair(Timed([&] { decode_all(*src, frames); }, n),
                              Timed([&] { plain.run(); }, n), ctx.budget);
  row.time = t.subject;
  row.peer_time = t.peer;
  row.error = decode_error(clip, frames);
  row.add("frames_per_s", 1.0 / t.subject.median_s);
  row.add("peer_frames_per_s", 1.0 / t.peer.median_s);
}

/// The stereo decode clips: the same media frames as HEVC, tagged top-bottom or not at all.
std::filesystem::path hevc_clip(int size, int frames, bool top_bottom) {
  ClipFormat f;
  f.codec = "libx265";
  if (top_bottom) f.stereo = {effects::StereoMode::TopBottom, 360};
  return media_clip("vdfx_bench_" + std::to_string(size) + "x" + std::to_string(size) + "_" +
                        std::to_string(frames) + (top_bottom ? "_tb" : "_mono") + "_hevc.mp4",
                    size, size, frames, 30, f);
}

/// The HEVC rows: the top-bottom clip (and its ratio to the mono one, timed beside it), then the
/// mono clip alone.
void add_stereo_decode(Registry& r, bool quick) {
  const int size = quick ? 1024 : 4096, frames = 12;
  const std::string dims = std::to_string(size) + "x" + std::to_string(size);
  const std::string note = std::to_string(frames) +
                           " frames, libx265 veryfast crf 20, 4:2:0 8-bit; the decoder's own "
                           "threads";
  r.add(kKnob, dims + " HEVC, top-bottom stereo", [=](Row& row, const Context& ctx) {
    const auto tb = hevc_clip(size, frames, true), mono = hevc_clip(size, frames, false);
    decode_row(row, ctx, tb, frames);
    auto stereo_src = open_source(tb), mono_src = open_source(mono);
    const auto vs = measure_pair(Timed([&] { decode_all(*stereo_src, frames); }, frames),
                                 Timed([&] { decode_all(*mono_src, frames); }, frames), ctx.budget);
    row.add("mono_frames_per_s", 1.0 / vs.peer.median_s);
    row.add("vs_mono", vs.peer.median_s / vs.subject.median_s);
    row.note = note +
               "; tagged top-bottom (st3d); vs_mono: against the same pictures untagged, "
               "timed beside it";
  });
  r.add(kKnob, dims + " HEVC, mono", [=](Row& row, const Context& ctx) {
    decode_row(row, ctx, hevc_clip(size, frames, false), frames);
    row.note = note + "; the pictures of the top-bottom row, untagged";
  });
}

}  // namespace

void add_decode_knobs(Registry& r, bool quick) {
  r.knob({kKnob,
          "video decode: vdfx's path (io::VideoSource, frames ready for upload) on a generated "
          "H.264 clip, and a top-bottom stereo HEVC one",
          "frame", "code values",
          "FFmpeg's plain decode of the same file (every Y'CbCr sample of every frame)",
          "FFmpeg's plain decode loop of the same file (av_read_frame, send/receive)",
          PlotError::Max, false, false});
  struct Clip {
    int w, h, frames;
  };
  const std::vector<Clip> clips = quick ? std::vector<Clip>{{1920, 960, 12}}
                                        : std::vector<Clip>{{1920, 960, 12}, {3840, 1920, 24}};
  for (const Clip& c : clips) {
    r.add(kKnob, std::to_string(c.w) + "x" + std::to_string(c.h) + " H.264",
          [c](Row& row, const Context& ctx) {
            const auto clip =
                media_clip("vdfx_bench_" + std::to_string(c.w) + "x" + std::to_string(c.h) + "_" +
                               std::to_string(c.frames) + "_h264.mp4",
                           c.w, c.h, c.frames);
            decode_row(row, ctx, clip, c.frames);
            row.note = std::to_string(c.frames) +
                       " frames, libx264 veryfast crf 20, 4:2:0 8-bit; the decoder's own threads";
          });
  }
  add_stereo_decode(r, quick);
}

}  // namespace vdfx::app::bench
