/// @file
/// @brief Synchronous frame decoding behind one interface: FFmpeg's libavformat/libavcodec for
/// videos (io/frame_decoder_libav.cpp), a still image as a one-frame video. io/video_source.h runs
/// a decoder on a worker thread.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "io/frame_time.h"
#include "io/picture.h"
#include "io/tone_map.h"
#include "io/video_layout.h"

namespace vdfx::io {

struct VideoProperties {
  std::filesystem::path path;
  /// Frames per second. Constant-rate videos: exact, from the timestamps (30000/1001); variable
  /// rate: the average rate; stills: DecoderOptions::still_fps.
  Rational fps;
  std::int64_t frames = 0;  //!< frames present (presentation order); stills: 1
  int width = 0;            //!< as displayed (after rotation)
  int height = 0;
  bool is_still = false;
  std::string backend;  //!< "libav" or "image"
  std::string codec;    //!< decoder name ("h264", "hevc"); empty for stills
  /// The container's own frame count when it declares one (0: none). More than `frames` means
  /// the file was cut short.
  std::int64_t declared_frames = 0;
  bool variable_rate = false;  //!< frame durations differ (docs/inputs.md, "Variable frame rate")
  int rotation_deg = 0;        //!< display rotation applied to every frame, clockwise: 0/90/180/270
  Rational time_base{0, 1};    //!< unit of FrameDecoder::timestamp (num/den seconds); 0: none
  /// The stream's transfer characteristic as FFmpeg names it ("bt709", "smpte2084",
  /// "arib-std-b67", "iec61966-2-1", ...); empty when the stream does not say (stills: "").
  std::string transfer;
  /// The stream's stereo and spherical tags (io/video_layout.h); stills: none.
  StereoTags stereo_tags;
  /// Bits per code value of the decoded Y'CbCr planes (10 for HEVC Main10, ProRes); 8 for RGB
  /// codecs and stills.
  int bit_depth = 8;
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
  /// Decodes frame next_index() into `out` as RGB (layout of DecoderOptions::format; Y'CbCr video
  /// converted by io::to_rgb, the CPU reference) and moves on by one.
  virtual DecodeStatus read(cv::Mat& out) = 0;
  /// Like read(), but hands the picture over as the decoder made it (Y'CbCr planes for most
  /// videos, no conversion and no copy). Default: read() wrapped as an RGB picture.
  virtual DecodeStatus read_picture(Picture& out) {
    out = Picture{};
    return read(out.rgb);
  }
  /// The container's presentation timestamp of frame `index` in properties().time_base units,
  /// when the file has timestamps (exports keep them).
  virtual std::optional<std::int64_t> timestamp(std::int64_t /*index*/) const {
    return std::nullopt;
  }
};

struct DecoderOptions {
  PixelFormat format = PixelFormat::Rgb8;
  Rational still_fps{30, 1};  //!< nominal rate of a still (any time shows frame 0)
  ToneMapSettings tone;       //!< for EXR/HDR stills
  /// A seek at most this many frames forward decodes forward instead of seeking the file.
  std::int64_t max_forward_grab = 16;
  /// Decoder threads (frame and slice threading); 0: one per core.
  int threads = 0;
};

/// A still (io::is_still_image_path) or a video. Throws io::InputError naming the file and the
/// reason: missing, a folder, not a readable media file, no video stream or no decoder for it,
/// no frames, or first frame not decodable.
std::unique_ptr<FrameDecoder> open_frame_decoder(const std::filesystem::path& path,
                                                 const DecoderOptions& options = {});

std::unique_ptr<FrameDecoder> create_libav_decoder(const std::filesystem::path& path,
                                                   const DecoderOptions& options);
std::unique_ptr<FrameDecoder> create_still_decoder(const std::filesystem::path& path,
                                                   const DecoderOptions& options);

}  // namespace vdfx::io
