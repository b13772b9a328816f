/// @file
/// @brief Writing a video with libavcodec/libavformat: Y'CbCr pictures encoded (libx264, libx265
/// or any libavcodec encoder), audio streams copied from another file untouched, the caller's
/// timestamps kept, and Spherical Video V2 metadata (equirectangular, mono) when asked for.
///
/// Used by `vdfx export` and by tests and benchmarks to make their clips with the same libraries
/// the decoder reads them with.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "effects/stereo_layout.h"
#include "io/frame_time.h"
#include "io/picture.h"

namespace vdfx::io {

/// Which audio packets to copy: presentation times in [start, end) (units of `time_base`),
/// shifted so that `start` becomes 0 (the video's timestamps are shifted the same way by the
/// caller).
struct AudioWindow {
  std::int64_t start = 0;
  std::int64_t end = INT64_MAX;
  Rational time_base{1, 1};
};

struct EncoderSettings {
  std::string codec = "libx264";  //!< a libavcodec encoder name ("libx264", "libx265", "ffv1")
  int width = 0, height = 0;
  Rational frame_rate{30, 1};  //!< nominal rate (rate control, container headers)
  Rational time_base{0, 1};    //!< unit of the timestamps given to write(); 0: 1 / frame_rate
  /// Pixel layout and colour tags: 8- or 10-bit (16-bit planes), subsampling 4:2:0 / 4:2:2 / 4:4:4,
  /// matrix, range, chroma siting (left or top-left for 4:2:0). Pictures given to write() must
  /// match it.
  YcbcrInfo ycbcr;
  int crf = -1;        //!< x264/x265 constant rate factor (0: lossless x264); -1: encoder default
  std::string preset;  //!< x264/x265 preset ("medium"); empty: encoder default
  int gop = 0;         //!< key frame interval; 0: encoder default
  int max_b_frames = -1;  //!< -1: encoder default
  int threads = 0;        //!< 0: the encoder picks (x264/x265: all cores)
  std::map<std::string, std::string> codec_options;  //!< further AVOptions of the encoder
  bool spherical_equirect = false;  //!< Spherical Video V2 equirectangular + `stereo`'s mode
  /// With spherical_equirect: the st3d stereo mode (mono, top-bottom, left-right, right-left as
  /// side-by-side inverted) and, for coverage 180, the equi bounds of a centred half turn.
  /// Without it, a stereo mode alone is written (a flat 3D video); mono writes nothing.
  effects::StereoLayout stereo;
  int display_rotation_deg = 0;  //!< clockwise display rotation written as the display matrix
  std::filesystem::path copy_audio_from;    //!< copy every audio stream of this file (empty: none)
  std::optional<AudioWindow> audio_window;  //!< default: every audio packet, times unchanged
  /// Container format chosen from this name's extension (default: the written path's), and the
  /// name messages give. Lets a caller write a temporary file whose own name says nothing.
  std::filesystem::path format_from;
  bool faststart = true;  //!< MP4/MOV: index at the front (one extra pass over the file at the end)
};

/// What copying `from`'s audio streams (EncoderSettings::copy_audio_from) cannot keep, one note
/// per stream, for the user: libavformat 5.1 writes no spatial audio box (MP4/MOV `SA3D`), so a
/// 4-channel track (first-order ambisonics, or one the demuxer marks ambisonic) is copied with
/// its channel layout but without that box. Empty when nothing is lost or `from` has no audio.
std::vector<std::string> audio_copy_notes(const std::filesystem::path& from);

class VideoEncoder {
 public:
  /// Opens the encoder and writes the header. Throws io::InputError naming `path` (or the audio
  /// file) for what a user chose wrong (unknown container, encoder, audio that the container
  /// cannot hold), std::runtime_error for anything else. write() and finish() likewise throw
  /// io::InputError "NAME: cannot write the video (REASON)" when the disk or file system fails
  /// (full, over quota, read-only, an I/O error; NAME is format_from when given), and
  /// std::runtime_error for a failure of the encoder or muxer.
  static std::unique_ptr<VideoEncoder> create(const std::filesystem::path& path,
                                              const EncoderSettings& settings);
  virtual ~VideoEncoder() = default;
  /// Encodes one picture (Y'CbCr matching the settings) with presentation time `pts` (units of
  /// the settings' time base, strictly increasing).
  virtual void write(const Picture& picture, std::int64_t pts) = 0;
  /// Drains the encoder, copies the remaining audio and writes the trailer. Nothing more may be
  /// written; without it the file is incomplete.
  virtual void finish() = 0;
  /// Time base the video stream ended up with in the container.
  virtual Rational stream_time_base() const = 0;
};

}  // namespace vdfx::io
