/// @file
/// @brief VideoSource: the decode worker and the consumer's frame selection.
#include "io/video_source.h"

#include <algorithm>
#include <iostream>

namespace vdfx::io {

std::unique_ptr<VideoSource> VideoSource::open(const std::filesystem::path& path,
                                               VideoSourceOptions options) {
  auto decoder = open_frame_decoder(path, options.decoder);
  return std::make_unique<VideoSource>(std::move(decoder), std::move(options));
}

VideoSource::VideoSource(std::unique_ptr<FrameDecoder> decoder, VideoSourceOptions options)
    : decoder_(std::move(decoder)),
      options_(std::move(options)),
      props_(decoder_->properties()),
      queue_(options_.queue_capacity) {
  limit_ = props_.frames;
  stats_.end = limit_;
  loop_ = options_.loop;
  next_ = decoder_->next_index();
  if (next_ != 0) {  // decoders may have read ahead to check the file
    next_ = 0;
    seek_pending_ = true;
  }
  if (props_.declared_frames > props_.frames)
    warn("the file declares " + std::to_string(props_.declared_frames) + " frames but holds " +
         std::to_string(props_.frames) + " (cut short?); playing those");
  worker_ = std::thread([this] { run(); });
}

VideoSource::~VideoSource() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  worker_.join();
}

void VideoSource::warn(const std::string& message) {
  pending_warnings_.push_back(props_.path.string() + ": " + message);
}

void VideoSource::flush_warnings(std::unique_lock<std::mutex>& lock) {
  if (pending_warnings_.empty()) return;
  std::vector<std::string> lines;
  lines.swap(pending_warnings_);
  // Outside the lock: the callback may take its own locks or ask the source for stats.
  lock.unlock();
  for (const std::string& line : lines) {
    if (options_.on_warning)
      options_.on_warning(line);
    else
      std::cerr << "vdfx: warning: " << line << "\n";
  }
  lock.lock();
}

bool VideoSource::wants_decode() const {
  if (queue_.full()) return false;
  if (at_end_) return loop_ && limit_ > 1;  // wrap to frame 0
  return !paused_ || next_ <= target_;
}

void VideoSource::run() {
  std::unique_lock lock(mutex_);
  while (true) {
    flush_warnings(lock);
    changed_.wait(lock, [&] { return stop_ || seek_pending_ || wants_decode(); });
    if (stop_) return;
    if (seek_pending_ || at_end_)
      seek_decoder(lock);
    else
      decode_next(lock);
  }
}

void VideoSource::seek_decoder(std::unique_lock<std::mutex>& lock) {
  // A requested seek, or the wrap of a loop (which keeps the queued frames).
  const bool wrap = !seek_pending_;
  const std::int64_t to = wrap ? 0 : next_;
  const std::uint64_t epoch = epoch_;
  seek_pending_ = false;
  lock.unlock();
  std::string error;
  try {
    decoder_->seek(to);
  } catch (const std::exception& e) {
    error = e.what();
  }
  lock.lock();
  if (epoch != epoch_) return;  // superseded by a newer seek
  if (!wrap) ++stats_.seeks;
  if (wrap) {
    next_ = 0;
    at_end_ = false;
  }
  if (!error.empty()) {
    // The read that follows counts the failure and skips on.
    warn("seek to frame " + std::to_string(to) + " failed: " + error);
  }
  consecutive_errors_ = 0;
}

void VideoSource::decode_next(std::unique_lock<std::mutex>& lock) {
  const std::int64_t index = next_;
  const std::uint64_t epoch = epoch_;
  lock.unlock();
  Picture picture;
  DecodeStatus status = DecodeStatus::Error;
  try {
    status = decoder_->read_picture(picture);
  } catch (const std::exception&) {
    status = DecodeStatus::Error;
  }
  lock.lock();
  if (epoch != epoch_) return;  // a seek arrived while decoding: this frame is stale
  switch (status) {
    case DecodeStatus::Ok:
      queue_.push({index, std::move(picture)});
      ++stats_.decoded;
      consecutive_errors_ = 0;
      next_ = index + 1;
      break;
    case DecodeStatus::Error: decode_failed(index); break;
    case DecodeStatus::End:
      if (index < limit_) {
        warn("the video ends at frame " + std::to_string(index) + " of " +
             std::to_string(props_.frames) + " declared");
        end_early(index);
      }
      at_end_ = true;
      break;
  }
  if (next_ >= limit_) at_end_ = true;
  changed_.notify_all();
}

void VideoSource::decode_failed(std::int64_t index) {
  ++stats_.decode_errors;
  ++consecutive_errors_;
  next_ = index + 1;
  warn("frame " + std::to_string(index) + " could not be decoded; skipped");
  if (consecutive_errors_ < options_.max_consecutive_errors) return;
  const std::int64_t end = index + 1 - consecutive_errors_;
  warn(std::to_string(consecutive_errors_) + " frames in a row failed: the video ends at frame " +
       std::to_string(end) + " of " + std::to_string(props_.frames) + " (truncated?)");
  end_early(end);
  at_end_ = true;
}

void VideoSource::end_early(std::int64_t end) {
  limit_ = std::max<std::int64_t>(end, 1);
  stats_.ended_early = true;
  stats_.end = limit_;
}

void VideoSource::request_seek(std::int64_t index) {
  queue_.clear();
  ++epoch_;
  next_ = std::clamp<std::int64_t>(index, 0, std::max<std::int64_t>(limit_ - 1, 0));
  target_ = index;
  seek_pending_ = true;
  at_end_ = false;
  consecutive_errors_ = 0;
  changed_.notify_all();
}

void VideoSource::seek(std::int64_t index) {
  std::lock_guard lock(mutex_);
  request_seek(index);
}

std::optional<VideoFrame> VideoSource::frame_at(std::int64_t index,
                                                std::chrono::nanoseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  std::unique_lock lock(mutex_);
  if (target_ != index) {
    target_ = index;
    changed_.notify_all();  // a paused decoder may now have work
  }
  bool sought = false;
  while (true) {
    if (auto f =
            queue_.take_upto(index, current_ ? std::optional(current_->index) : std::nullopt)) {
      current_ = std::move(f);
      changed_.notify_all();  // room in the queue
    }
    if (current_ && current_->index == index) return current_;

    // Will `index` arrive without a seek? Only if nothing else is queued before it and the
    // decoder is a little before it.
    // At the end of a looping video the decoder is about to wrap to frame 0.
    // -1: nothing more comes.
    const std::int64_t upcoming = at_end_ ? (loop_ && limit_ > 1 ? 0 : -1) : next_;
    const bool coming = queue_.empty() && !seek_pending_ && upcoming >= 0 && upcoming <= index &&
                        index - upcoming <= options_.max_wait_ahead;
    const bool pending = seek_pending_ && next_ == std::clamp<std::int64_t>(index, 0, limit_ - 1);
    const bool beyond_end =
        index >= limit_ && queue_.empty() && !loop_ && (at_end_ || next_ >= limit_);
    if (!coming && !pending) {
      if (!sought && !beyond_end && index >= 0) {
        request_seek(index);
        sought = true;
      } else {
        break;  // nothing better will come
      }
    }
    if (changed_.wait_until(lock, deadline) == std::cv_status::timeout) {
      // One last look: the frame may have landed just now.
      if (auto f =
              queue_.take_upto(index, current_ ? std::optional(current_->index) : std::nullopt)) {
        current_ = std::move(f);
        changed_.notify_all();
      }
      break;
    }
  }
  if (current_ && current_->index <= index) return current_;
  return std::nullopt;
}

void VideoSource::set_loop(bool loop) {
  std::lock_guard lock(mutex_);
  loop_ = loop;
  changed_.notify_all();
}

bool VideoSource::loop() const {
  std::lock_guard lock(mutex_);
  return loop_;
}

void VideoSource::set_paused(bool paused) {
  std::lock_guard lock(mutex_);
  paused_ = paused;
  changed_.notify_all();
}

bool VideoSource::paused() const {
  std::lock_guard lock(mutex_);
  return paused_;
}

VideoStats VideoSource::stats() const {
  std::lock_guard lock(mutex_);
  return stats_;
}

}  // namespace vdfx::io
