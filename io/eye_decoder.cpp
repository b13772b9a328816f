/// @file
/// @brief eye_decoder: one eye's image of each decoded frame.
#include "io/eye_decoder.h"

namespace vdfx::io {
namespace {

class EyeDecoder final : public FrameDecoder {
 public:
  EyeDecoder(std::unique_ptr<FrameDecoder> inner, const effects::StereoLayout& layout,
             effects::EyeIndex eye)
      : inner_(std::move(inner)), props_(inner_->properties()) {
    const effects::PixelRect r = effects::eye_rect(layout, eye, props_.width, props_.height);
    rect_ = cv::Rect(r.x, r.y, r.width, r.height);
    props_.width = r.width;
    props_.height = r.height;
  }
  const VideoProperties& properties() const override { return props_; }
  std::int64_t next_index() const override { return inner_->next_index(); }
  void seek(std::int64_t index) override { inner_->seek(index); }
  DecodeStatus read(cv::Mat& out) override {
    cv::Mat frame;
    const DecodeStatus s = inner_->read(frame);
    if (s == DecodeStatus::Ok) out = frame(rect_).clone();
    return s;
  }
  // read_picture: the default (read() wrapped as an RGB picture), so it is cut too.
  std::optional<std::int64_t> timestamp(std::int64_t index) const override {
    return inner_->timestamp(index);
  }

 private:
  std::unique_ptr<FrameDecoder> inner_;
  VideoProperties props_;
  cv::Rect rect_;
};

}  // namespace

std::unique_ptr<FrameDecoder> eye_decoder(std::unique_ptr<FrameDecoder> decoder,
                                          const effects::StereoLayout& layout,
                                          effects::EyeIndex eye) {
  if (!layout.stereo()) return decoder;
  return std::make_unique<EyeDecoder>(std::move(decoder), layout, eye);
}

}  // namespace vdfx::io
