/// @file
/// @brief A video (or a still as a one-frame video) decoded on a worker thread into a small
/// bounded queue of pictures in the decoder's own layout (Y'CbCr planes, not converted). The
/// consumer asks for frame N and gets the newest decoded frame <= N, waiting at most a timeout for
/// N itself: decoding never blocks the render loop.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "io/frame_decoder.h"
#include "io/frame_queue.h"

namespace vdfx::io {

struct VideoSourceOptions {
  DecoderOptions decoder;
  std::size_t queue_capacity = 4;
  /// Frame N is waited for when the decoder is at most this many frames before it; farther
  /// (or behind) is a seek.
  std::int64_t max_wait_ahead = 8;
  /// This many failed frames in a row end the stream there (a truncated file).
  int max_consecutive_errors = 8;
  bool loop = false;
  /// Warnings (skipped frames, early end), each naming the file. Called on the decode thread,
  /// without the source's lock held. Default: a line on std::cerr.
  std::function<void(const std::string&)> on_warning;
};

struct VideoStats {
  std::int64_t decoded = 0;        //!< frames decoded (all runs)
  std::int64_t decode_errors = 0;  //!< frames skipped because they failed to decode
  std::int64_t seeks = 0;          //!< seeks done by the decoder (loop wraps not counted)
  bool ended_early = false;        //!< the stream ended before the declared frame count
  std::int64_t end = 0;            //!< frames playable: declared count, or where it ended early
};

class VideoSource {
 public:
  /// Opens a video or still (io/frame_decoder.h); throws io::InputError naming the file.
  static std::unique_ptr<VideoSource> open(const std::filesystem::path& path,
                                           VideoSourceOptions options = {});
  /// Runs any decoder (tests inject failing or slow ones).
  VideoSource(std::unique_ptr<FrameDecoder> decoder, VideoSourceOptions options);
  ~VideoSource();
  VideoSource(const VideoSource&) = delete;
  VideoSource& operator=(const VideoSource&) = delete;

  const VideoProperties& properties() const { return props_; }

  /// The newest decoded frame with index <= `index`. When frame `index` itself is not decoded
  /// yet but coming (or reachable by one seek, which this issues), waits for it at most
  /// `timeout`, then returns the newest <= index it has, or nothing. Never waits forever.
  std::optional<VideoFrame> frame_at(std::int64_t index, std::chrono::nanoseconds timeout);

  /// Moves decoding to `index` (clamped to the video) and drops queued frames.
  void seek(std::int64_t index);
  void set_loop(bool loop);
  bool loop() const;
  /// Paused: decodes only up to the last frame asked for, not ahead.
  void set_paused(bool paused);
  bool paused() const;
  VideoStats stats() const;

 private:
  void run();  //!< the worker: seeks and decodes until stopped
  // The worker's steps, called with the lock held (released while the decoder works).
  void seek_decoder(std::unique_lock<std::mutex>& lock);  //!< a requested seek or a loop's wrap
  void decode_next(std::unique_lock<std::mutex>& lock);   //!< frame next_ into the queue
  void decode_failed(std::int64_t index);  //!< counts it; too many in a row end the video
  void end_early(std::int64_t end);        //!< the video holds only frames before `end`
  bool wants_decode() const;
  void request_seek(std::int64_t index);
  void warn(const std::string& message);  //!< queued; the worker reports it unlocked
  void flush_warnings(std::unique_lock<std::mutex>& lock);

  std::unique_ptr<FrameDecoder> decoder_;
  VideoSourceOptions options_;
  VideoProperties props_;

  mutable std::mutex mutex_;
  std::condition_variable changed_;
  FrameQueue queue_;
  std::optional<VideoFrame> current_;  //!< the frame last handed out
  std::int64_t next_ = 0;              //!< index the decoder produces next (after pending seek)
  std::int64_t target_ = 0;            //!< last frame asked for (paused decoding stops there)
  std::int64_t limit_ = 0;             //!< frames playable
  std::uint64_t epoch_ = 0;            //!< bumped by each seek: older decodes are dropped
  bool seek_pending_ = false;
  bool at_end_ = false;
  bool loop_ = false;
  bool paused_ = false;
  bool stop_ = false;
  int consecutive_errors_ = 0;
  VideoStats stats_;
  std::vector<std::string> pending_warnings_;
  std::thread worker_;
};

}  // namespace vdfx::io
