/// @file
/// @brief Synchronous frame decoding behind one interface: OpenCV videoio for videos, a still
/// image as a one-frame video. io/video_source.h runs a decoder on a worker thread.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <opencv2/core.hpp>
#include <string>

#include "io/frame_time.h"
#include "io/tone_map.h"

namespace vdfx::io {

/// Pixel layout of decoded frames. Both are RGB with display-encoded values (Rgb8: value / 255).
enum class PixelFormat { Rgb8, RgbF32 };

struct VideoProperties {
  std::filesystem::path path;
  Rational fps;              //!< stills: DecoderOptions::still_fps
  std::int64_t frames = 0;   //!< as the container declares it; stills: 1
  int width = 0;
  int height = 0;
  bool is_still = false;
  std::string backend;  //!< OpenCV backend name ("FFMPEG", "CV_MJPEG") or "image"
};

enum class DecodeStatus {
  Ok,     //!< the frame was decoded
  Error,  //!< this frame could not be decoded; the position still moved past it
  End     //!< no frame at this position (past the last frame)
};

class FrameDecoder {
 public:
  virtual ~FrameDecoder() = default;
  virtual const VideoProperties& properties() const = 0;
  /// The index the next read() decodes.
  virtual std::int64_t next_index() const = 0;
  /// Positions exactly so that the next read() decodes frame `index` (0 <= index < frames).
  /// Throws std::out_of_range for an index outside the video, std::runtime_error when the
  /// backend cannot get there.
  virtual void seek(std::int64_t index) = 0;
  /// Decodes frame next_index() into `out` (layout of DecoderOptions::format) and moves on by one.
  virtual DecodeStatus read(cv::Mat& out) = 0;
};

struct DecoderOptions {
  PixelFormat format = PixelFormat::Rgb8;
  Rational still_fps{30, 1};  //!< nominal rate of a still (any time shows frame 0)
  ToneMapSettings tone;       //!< for EXR/HDR stills
  /// A seek at most this many frames forward decodes forward instead of asking the backend.
  std::int64_t max_forward_grab = 16;
};

/// A still (io::is_still_image_path) or a video. Throws io::InputError naming the file and the
/// reason: missing, not openable by any OpenCV backend, no frame count or frame rate, or first
/// frame not decodable.
std::unique_ptr<FrameDecoder> open_frame_decoder(const std::filesystem::path& path,
                                                 const DecoderOptions& options = {});

std::unique_ptr<FrameDecoder> create_opencv_decoder(const std::filesystem::path& path,
                                                    const DecoderOptions& options);
std::unique_ptr<FrameDecoder> create_still_decoder(const std::filesystem::path& path,
                                                   const DecoderOptions& options);

}  // namespace vdfx::io
