/// @file
/// @brief A still image as a one-frame video.
#include <stdexcept>
#include <string>

#include "io/frame_decoder.h"
#include "io/image_source.h"

namespace vdfx::io {
namespace {

class StillDecoder final : public FrameDecoder {
 public:
  StillDecoder(const std::filesystem::path& path, const DecoderOptions& options) {
    const LoadedImage img = load_image(path, options.tone);
    if (options.format == PixelFormat::RgbF32)
      image_ = img.rgb;
    else
      img.rgb.convertTo(image_, CV_8UC3, 255.0);  // rounds to nearest, saturates
    props_.path = path;
    props_.fps = options.still_fps;
    props_.frames = 1;
    props_.width = image_.cols;
    props_.height = image_.rows;
    props_.is_still = true;
    props_.backend = "image";
  }
  const VideoProperties& properties() const override { return props_; }
  std::int64_t next_index() const override { return next_; }
  void seek(std::int64_t index) override {
    if (index != 0)
      throw std::out_of_range("frame " + std::to_string(index) +
                              " of a still image (only frame 0)");
    next_ = 0;
  }
  DecodeStatus read(cv::Mat& out) override {
    if (next_ != 0) return DecodeStatus::End;
    out = image_.clone();  // the consumer may draw into it
    next_ = 1;
    return DecodeStatus::Ok;
  }

 private:
  VideoProperties props_;
  cv::Mat image_;
  std::int64_t next_ = 0;
};

}  // namespace

std::unique_ptr<FrameDecoder> create_still_decoder(const std::filesystem::path& path,
                                                   const DecoderOptions& options) {
  return std::make_unique<StillDecoder>(path, options);
}

}  // namespace vdfx::io
