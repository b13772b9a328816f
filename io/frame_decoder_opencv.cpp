/// @file
/// @brief Video decoding through OpenCV videoio, with exact seeking.
///
/// Seeking: OpenCV's CAP_PROP_POS_FRAMES is exact for most files (its FFmpeg backend seeks to
/// the key frame before and decodes forward, counting frames by timestamp), but not promised for
/// every container. So a seek is verified: after setting the position the backend must report
/// that same position; when it does not, the decoder counts frames itself, grabbing forward from
/// the position the backend did report (or from a reopened file's frame 0). Short forward seeks
/// just grab.
#include <cmath>
#include <stdexcept>
#include <string>

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "io/frame_decoder.h"
#include "io/image_source.h"
#include "io/input_error.h"
#include "io/library_logs.h"

namespace vdfx::io {
namespace {

class OpenCvDecoder final : public FrameDecoder {
 public:
  OpenCvDecoder(const std::filesystem::path& path, const DecoderOptions& options) : options_(options) {
    const std::string name = path.string();
    {
      // The backends print their own complaints about a damaged file; vdfx reports it itself.
      const QuietStderr quiet;
      open_or_throw(name);
    }
    const double fps = cap_.get(cv::CAP_PROP_FPS);
    const double count = cap_.get(cv::CAP_PROP_FRAME_COUNT);
    const int w = static_cast<int>(cap_.get(cv::CAP_PROP_FRAME_WIDTH));
    const int h = static_cast<int>(cap_.get(cv::CAP_PROP_FRAME_HEIGHT));
    if (!(fps > 0.0) || !std::isfinite(fps))
      throw InputError(name + ": the video declares no frame rate (" + std::to_string(fps) + ")");
    if (!(count >= 1.0) || !std::isfinite(count))
      throw InputError(name + ": the video declares no frame count (stream without an index?)");
    check_frame_size(name, w, h);  // before any frame is decoded
    props_ = {path, fps_to_rational(fps), std::llround(count), w, h, false, cap_.getBackendName()};
    // Fail now, with a clear message, rather than on the decode thread later.
    cv::Mat first;
    if (!cap_.read(first) || first.empty())
      throw InputError(name + ": cannot decode the first frame (corrupt or unsupported codec)");
    if (w <= 0 || h <= 0) {
      check_frame_size(name, first.cols, first.rows);
      props_.width = first.cols;
      props_.height = first.rows;
    }
    next_ = 1;
  }

  const VideoProperties& properties() const override { return props_; }
  std::int64_t next_index() const override { return next_; }

  void seek(std::int64_t index) override {
    if (index < 0 || index >= props_.frames)
      throw std::out_of_range("frame " + std::to_string(index) + " is outside the video (0.." +
                              std::to_string(props_.frames - 1) + ")");
    if (index == next_ && !lost_) return;
    if (!lost_ && index > next_ && index - next_ <= options_.max_forward_grab) {
      grab_to(index);
      return;
    }
    cap_.set(cv::CAP_PROP_POS_FRAMES, static_cast<double>(index));
    const double pos = cap_.get(cv::CAP_PROP_POS_FRAMES);
    const auto at = std::isfinite(pos) ? std::llround(pos) : -1;
    if (at == index) {
      next_ = index;
      lost_ = false;
      return;
    }
    // The backend landed elsewhere: count frames ourselves from a position we can trust.
    if (at >= 0 && at < index) {
      next_ = at;
    } else {
      open_or_throw(props_.path.string());
      next_ = 0;
    }
    lost_ = false;
    grab_to(index);
  }

  DecodeStatus read(cv::Mat& out) override {
    if (next_ >= props_.frames) return DecodeStatus::End;
    if (lost_) {
      // After a failed frame the backend's position is unknown: go to the next frame exactly.
      try {
        seek(next_);
      } catch (const std::exception&) {
        ++next_;
        return DecodeStatus::Error;
      }
    }
    cv::Mat bgr;
    const bool ok = cap_.read(bgr) && !bgr.empty() && bgr.channels() == 3 && bgr.depth() == CV_8U;
    ++next_;
    if (!ok) {
      lost_ = true;
      return DecodeStatus::Error;
    }
    cv::Mat rgb;
    cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
    if (options_.format == PixelFormat::RgbF32) rgb.convertTo(out, CV_32FC3, 1.0 / 255.0);
    else out = rgb;
    return DecodeStatus::Ok;
  }

 private:
  void open_or_throw(const std::string& name) {
    cap_.release();
    try {
      cap_.open(name, cv::CAP_ANY);
    } catch (const cv::Exception& e) {
      throw InputError(name + ": cannot open as a video: " + e.what());
    }
    if (!cap_.isOpened())
      throw InputError(name + ": cannot open as a video (no OpenCV backend reads it: corrupt, "
                              "truncated or unsupported)");
  }

  void grab_to(std::int64_t index) {
    while (next_ < index) {
      if (!cap_.grab()) {
        lost_ = true;
        throw std::runtime_error("cannot decode up to frame " + std::to_string(index) +
                                 " (stopped at " + std::to_string(next_) + ")");
      }
      ++next_;
    }
  }

  DecoderOptions options_;
  VideoProperties props_;
  cv::VideoCapture cap_;
  std::int64_t next_ = 0;
  bool lost_ = false;  //!< the backend's position is not known to be next_
};

}  // namespace

std::unique_ptr<FrameDecoder> create_opencv_decoder(const std::filesystem::path& path,
                                                    const DecoderOptions& options) {
  return std::make_unique<OpenCvDecoder>(path, options);
}

}  // namespace vdfx::io
