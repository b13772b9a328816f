/// @file
/// @brief Video frame thumbnails for the timeline strip (the paper's Fig. 6b), decoded on a worker
/// at a low resolution and kept: the frame thread never decodes them.
///
/// `count` frames evenly spread over the clip (the centre frame of each of `count` equal
/// spans), each scaled down to `size` (BGR, the strip's format). A separate decoder on its own
/// thread, so the playing video's decoder is not disturbed; it seeks to each frame (exact seek,
/// io::FrameDecoder) or reads on when the next one is near. A video that cannot be read leaves the
/// strip without thumbnails (the message says why) rather than failing the editor.
#pragma once
#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "effects/stereo_layout.h"

namespace vdfx::app {

class ThumbnailWorker {
 public:
  /// `layout`: stereo video's thumbnails show its left eye (docs/stereo.md).
  ThumbnailWorker(std::filesystem::path video, int count, cv::Size size,
                  effects::StereoLayout layout = {});
  /// Stops between frames and joins.
  ~ThumbnailWorker();
  ThumbnailWorker(const ThumbnailWorker&) = delete;
  ThumbnailWorker& operator=(const ThumbnailWorker&) = delete;

  /// Every thumbnail, once all are decoded (then once only); nullopt before and after.
  std::optional<std::vector<cv::Mat>> take();
  /// Blocks until the worker has finished (tests); false on timeout.
  bool wait(std::chrono::milliseconds timeout);
  /// Why there are no thumbnails ("" while working or when they are done).
  std::string problem() const;
  /// The frame each thumbnail shows, in order.
  static std::vector<std::int64_t> frames_for(std::int64_t frame_count, int count);

 private:
  void run(std::filesystem::path video, int count, cv::Size size, effects::StereoLayout layout);

  mutable std::mutex mutex_;
  std::optional<std::vector<cv::Mat>> done_;
  std::string problem_;
  bool finished_ = false;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace vdfx::app
