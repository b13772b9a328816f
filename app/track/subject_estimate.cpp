/// @file
/// @brief estimate_subject (subject_estimate.h).
#include "app/track/subject_estimate.h"

#include <algorithm>
#include <optional>
#include <string>

#include "app/track/analysis_frame.h"
#include "effects/equirect_sampler.h"
#include "io/input_error.h"

namespace vdfx::app::track {
namespace {

constexpr std::int64_t kChunk = 16;  // frames decoded at a time going backwards

struct Reader {
  io::FrameDecoder& decoder;
  const effects::StereoLayout& layout;
  cv::Size size;

  /// The next frame's analysis image (RGB CV_32FC3), or nothing where it fails to decode.
  std::optional<cv::Mat> next() {
    cv::Mat rgb;
    if (decoder.read(rgb) != io::DecodeStatus::Ok) return std::nullopt;
    const cv::Mat eye = effects::eye_image(rgb, layout, effects::EyeIndex::Left);
    const cv::Mat small = reduce_area(eye, size);
    cv::Mat out;
    small.convertTo(out, CV_32FC3, small.depth() == CV_8U ? 1.0 / 255.0 : 1.0);
    return out;
  }
};

SubjectSample held_sample(const std::vector<SubjectSample>& samples, std::int64_t from) {
  SubjectSample s = samples[static_cast<std::size_t>(from)];
  s.confidence = 0.0;
  s.seen = false;
  return s;
}

}  // namespace

SubjectEstimate estimate_subject(io::FrameDecoder& decoder, const effects::StereoLayout& layout,
                                 std::int64_t start, const Eigen::Vector3d& at,
                                 SubjectOptions options, const std::function<void(double)>& tick) {
  const io::VideoProperties& p = decoder.properties();
  const effects::PixelRect eye =
      effects::eye_rect(layout, effects::EyeIndex::Left, p.width, p.height);
  options.coverage_deg = layout.coverage_deg;
  SubjectEstimate out;
  out.width = std::min(SubjectTracker::equirect_width(options),
                       eye.width * 360 / layout.coverage_deg / 2 * 2);
  Reader reader{decoder, layout, cv::Size(out.width * layout.coverage_deg / 360, out.width / 2)};
  const std::int64_t frames = p.frames;
  out.samples.resize(static_cast<std::size_t>(frames));
  std::int64_t done = 0;
  const auto ticked = [&] {
    if (tick) tick(static_cast<double>(++done) / static_cast<double>(frames));
  };
  decoder.seek(start);
  const std::optional<cv::Mat> first = reader.next();
  if (!first)
    throw io::InputError(p.path.string() + ": frame " + std::to_string(start) +
                         " (--at) could not be decoded");
  SubjectTracker forwards(*first, at, options), backwards(*first, at, options);
  out.samples[static_cast<std::size_t>(start)] = forwards.start();
  ticked();
  for (std::int64_t f = start + 1; f < frames; ++f) {
    const std::optional<cv::Mat> img = reader.next();
    out.samples[static_cast<std::size_t>(f)] =
        img ? forwards.step(*img) : held_sample(out.samples, f - 1);
    ticked();
  }
  for (std::int64_t hi = start - 1; hi >= 0; hi -= kChunk) {
    const std::int64_t lo = std::max<std::int64_t>(0, hi - kChunk + 1);
    decoder.seek(lo);
    std::vector<std::optional<cv::Mat>> chunk;
    for (std::int64_t f = lo; f <= hi; ++f) chunk.push_back(reader.next());
    for (std::int64_t f = hi; f >= lo; --f) {
      const auto& img = chunk[static_cast<std::size_t>(f - lo)];
      out.samples[static_cast<std::size_t>(f)] =
          img ? backwards.step(*img) : held_sample(out.samples, f + 1);
      ticked();
    }
  }
  return out;
}

}  // namespace vdfx::app::track
