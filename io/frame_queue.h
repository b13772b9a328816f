/// @file
/// @brief The bounded queue between the decode thread and the consumer, and the rule for which
/// frames a consumer at frame N has passed. Not thread-safe: VideoSource guards it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>

#include "io/picture.h"

namespace vdfx::io {

struct VideoFrame {
  std::int64_t index = -1;
  /// As the decoder made it: Y'CbCr planes for videos (the GPU converts them), RGB for stills.
  /// io::to_rgb converts on the CPU.
  Picture picture;
};

class FrameQueue {
 public:
  explicit FrameQueue(std::size_t capacity) : capacity_(capacity == 0 ? 1 : capacity) {}
  std::size_t capacity() const { return capacity_; }
  std::size_t size() const { return frames_.size(); }
  bool empty() const { return frames_.empty(); }
  bool full() const { return frames_.size() >= capacity_; }
  std::optional<std::int64_t> front_index() const {
    return frames_.empty() ? std::nullopt : std::optional(frames_.front().index);
  }
  void push(VideoFrame f) { frames_.push_back(std::move(f)); }
  void clear() { frames_.clear(); }

  /// Pops the frames a consumer now at `target` has passed and returns the newest of them.
  /// Frames are in decode order; a loop starts a new increasing run (..., 58, 59, 0, 1). Popped
  /// are front frames with index <= target that keep increasing from `after` (the consumer's
  /// current frame, when it is below target), so a consumer at 59 does not take the 0 that
  /// follows, while one asking for 0 does. A consumer that went back (after > target: a loop
  /// or a jump back) first drops the rest of the run it left: those frames are behind it now.
  std::optional<VideoFrame> take_upto(std::int64_t target, std::optional<std::int64_t> after) {
    if (after && *after > target) {
      std::int64_t prev = -1;
      while (!frames_.empty() && frames_.front().index > target && frames_.front().index > prev) {
        prev = frames_.front().index;
        frames_.pop_front();
      }
    }
    std::int64_t ref = after && *after < target ? *after : -1;
    std::optional<VideoFrame> last;
    while (!frames_.empty() && frames_.front().index <= target && frames_.front().index > ref) {
      ref = frames_.front().index;
      last = std::move(frames_.front());
      frames_.pop_front();
    }
    return last;
  }

 private:
  std::size_t capacity_;
  std::deque<VideoFrame> frames_;
};

}  // namespace vdfx::io
