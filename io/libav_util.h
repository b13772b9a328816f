/// @file
/// @brief Small owning wrappers and error text for FFmpeg's C libraries (libavformat,
/// libavcodec, libavutil), shared by the decoder, the encoder and their tests. Only io/ sources,
/// tests and `vdfx bench`'s plain decode loop (app/bench/media.cpp, the decoder's peer) include
/// this: nothing else sees the libav headers.
#pragma once

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/avutil.h>
#include <libavutil/pixdesc.h>
}

#include <malloc.h>

#include <memory>
#include <string>

#include "io/library_logs.h"

namespace vdfx::io::av {

struct InputCloser {
  void operator()(AVFormatContext* c) const { avformat_close_input(&c); }
};
struct CodecCloser {
  void operator()(AVCodecContext* c) const { avcodec_free_context(&c); }
};
struct FrameFree {
  void operator()(AVFrame* f) const { av_frame_free(&f); }
};
struct PacketFree {
  void operator()(AVPacket* p) const { av_packet_free(&p); }
};

using InputPtr = std::unique_ptr<AVFormatContext, InputCloser>;
using CodecPtr = std::unique_ptr<AVCodecContext, CodecCloser>;
using FramePtr = std::unique_ptr<AVFrame, FrameFree>;
using PacketPtr = std::unique_ptr<AVPacket, PacketFree>;

inline FramePtr make_frame() {
  return FramePtr(av_frame_alloc());
}
inline PacketPtr make_packet() {
  return PacketPtr(av_packet_alloc());
}

/// libav's message for an error code ("Invalid data found when processing input").
inline std::string error_text(int code) {
  char buf[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, buf, sizeof buf);
  return buf;
}

/// libav prints encoder statistics and stream notes at "info" level on stderr; vdfx reports what
/// matters itself, so only libav's errors pass (set once per process, before the first use), and
/// none once the command line asked for quiet libraries (io/library_logs.h: vdfx's own message
/// about a damaged file is then the one line the user sees; `--verbose` keeps libav's errors).
inline void limit_logs() {
  static const bool done = [] {
    av_log_set_level(library_logs_quiet() ? AV_LOG_QUIET : AV_LOG_ERROR);
    return true;
  }();
  (void)done;
}

/// Decoded pictures are large (12 MB for a 4K 4:2:0 frame) and libavcodec's frame pools allocate
/// them zeroed (av_buffer_allocz). glibc hands such blocks back to the kernel when they are freed
/// (above its mmap threshold, or trimmed from the top of a thread's arena), so a video held in a
/// queue and sought now and then page-faulted fresh memory in and zeroed it for about 4 frames in
/// 10: 15 % of the decode time of a 4K H.264 clip (docs/inputs.md). Set once per process before
/// the first video opens: blocks up to glibc's largest mmap threshold (32 MiB: an 8K plane) come
/// from the arenas and up to 256 MiB of freed memory stays mapped for the next frames.
inline void keep_frame_memory() {
  static const bool done = [] {
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
    return true;
  }();
  (void)done;
}

/// Opens `path` for reading and reads its stream information; null with `error` set otherwise.
inline InputPtr open_input(const std::string& path, std::string& error) {
  limit_logs();
  keep_frame_memory();
  AVFormatContext* raw = nullptr;
  int r = avformat_open_input(&raw, path.c_str(), nullptr, nullptr);
  if (r < 0) {
    error = error_text(r);
    return nullptr;
  }
  InputPtr in(raw);
  r = avformat_find_stream_info(in.get(), nullptr);
  if (r < 0) {
    error = error_text(r);
    return nullptr;
  }
  return in;
}

}  // namespace vdfx::io::av
