/// @file
/// @brief ThumbnailWorker: timeline thumbnails decoded off the frame thread.
#include "app/editor/thumbnail_worker.h"

#include <algorithm>
#include <chrono>
#include <opencv2/imgproc.hpp>
#include <utility>

#include "io/eye_decoder.h"
#include "io/frame_decoder.h"

namespace vdfx::app {

ThumbnailWorker::ThumbnailWorker(std::filesystem::path video, int count, cv::Size size,
                                 effects::StereoLayout layout)
    : thread_([this, v = std::move(video), count, size, layout] { run(v, count, size, layout); }) {}

ThumbnailWorker::~ThumbnailWorker() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

std::vector<std::int64_t> ThumbnailWorker::frames_for(std::int64_t frame_count, int count) {
  std::vector<std::int64_t> out;
  for (int k = 0; k < count; ++k)
    out.push_back(
        std::min(frame_count - 1, static_cast<std::int64_t>((k + 0.5) * frame_count / count)));
  return out;
}

void ThumbnailWorker::run(std::filesystem::path video, int count, cv::Size size,
                          effects::StereoLayout layout) {
  std::vector<cv::Mat> thumbs;
  std::string problem;
  try {
    io::DecoderOptions o;
    o.format = io::PixelFormat::Rgb8;
    o.max_forward_grab = 48;  // reading on beats a seek back to the keyframe for nearby frames
    auto decoder =
        io::eye_decoder(io::open_frame_decoder(video, o), layout, effects::EyeIndex::Left);
    const std::int64_t frames = std::max<std::int64_t>(1, decoder->properties().frames);
    cv::Mat rgb, small;
    for (const std::int64_t f : frames_for(frames, count)) {
      if (stop_) return;
      if (decoder->next_index() != f) decoder->seek(f);
      if (decoder->read(rgb) != io::DecodeStatus::Ok || rgb.empty()) {
        thumbs.push_back(cv::Mat(size, CV_8UC3, cv::Scalar::all(0)));  // a dark cell, not a gap
        continue;
      }
      cv::resize(rgb, small, size, 0, 0, cv::INTER_AREA);
      cv::cvtColor(small, small, cv::COLOR_RGB2BGR);
      thumbs.push_back(small.clone());
    }
  } catch (const std::exception& e) {
    problem = std::string("no timeline thumbnails: ") + e.what();
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (problem.empty()) done_ = std::move(thumbs);
  problem_ = problem;
  finished_ = true;
}

std::optional<std::vector<cv::Mat>> ThumbnailWorker::take() {
  std::lock_guard<std::mutex> lock(mutex_);
  return std::exchange(done_, std::nullopt);
}

bool ThumbnailWorker::wait(std::chrono::milliseconds timeout) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < end) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (finished_) return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

std::string ThumbnailWorker::problem() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return problem_;
}

}  // namespace vdfx::app
