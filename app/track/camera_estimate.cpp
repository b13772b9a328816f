/// @file
/// @brief estimate_camera (camera_estimate.h).
#include "app/track/camera_estimate.h"

#include <algorithm>
#include <chrono>
#include <ctime>

#include "app/track/analysis_frame.h"

namespace vdfx::app::track {
namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::duration d) {
  return std::chrono::duration<double>(d).count();
}

/// CPU time of the calling thread, seconds.
double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

CameraEstimate estimate_camera(io::FrameDecoder& decoder, const effects::StereoLayout& layout,
                               CameraTrackOptions options,
                               const std::function<void(double)>& tick) {
  const io::VideoProperties& p = decoder.properties();
  const effects::PixelRect eye =
      effects::eye_rect(layout, effects::EyeIndex::Left, p.width, p.height);
  // Pixels per turn of the eye's image: more analysis pixels than that add nothing.
  const int per_turn = eye.width * 360 / layout.coverage_deg;
  options.width = std::max(64, std::min(options.width, per_turn) / 2 * 2);
  options.coverage_deg = layout.coverage_deg;
  CameraEstimate out;
  out.width = options.width;
  CameraTracker tracker(options);
  const cv::Size size = tracker.grid().size();
  const std::int64_t frames = p.is_still ? 1 : p.frames;
  decoder.seek(0);
  io::Picture picture;
  for (std::int64_t f = 0; f < frames; ++f) {
    const auto t0 = Clock::now();
    const io::DecodeStatus status = decoder.read_picture(picture);
    const auto t1 = Clock::now();
    const double c1 = thread_cpu_seconds();
    tracker.add(status == io::DecodeStatus::Ok ? analysis_grey(picture, layout, size) : cv::Mat());
    out.analysis_cpu_seconds += thread_cpu_seconds() - c1;
    out.decode_seconds += seconds(t1 - t0);
    out.analysis_seconds += seconds(Clock::now() - t1);
    if (tick) tick(static_cast<double>(f + 1) / static_cast<double>(frames));
  }
  const auto t2 = Clock::now();
  const double c2 = thread_cpu_seconds();
  out.track = tracker.finish();
  out.analysis_cpu_seconds += thread_cpu_seconds() - c2;
  out.analysis_seconds += seconds(Clock::now() - t2);
  return out;
}

}  // namespace vdfx::app::track
