/// @file
/// @brief Keeping the media libraries quiet: vdfx reports every failure itself, with the file and
/// the place, so what OpenCV, FFmpeg (through OpenCV) and OpenCV's own container parsers print on
/// their own only buries that message. `vdfx --verbose` leaves them on.
#pragma once

namespace vdfx::io {

/// Silences the libraries from now on: OpenCV's log (also its GStreamer backend's warnings),
/// FFmpeg's av_log as OpenCV sets it up (OPENCV_FFMPEG_LOGLEVEL, unless the user set it), and
/// makes QuietStderr effective. Call once, early, before any video is opened.
void quiet_library_logs();

/// True once quiet_library_logs() ran.
bool library_logs_quiet();

/// While it lives, and only when library_logs_quiet(): the process's stderr goes to /dev/null.
/// For one library call that writes to stderr itself (OpenCV's AVI parser prints "Unexpected list
/// type" on a damaged file) and whose failure vdfx then reports. Use only on the thread that
/// owns the terminal's messages, around calls that take a moment, never around vdfx's own output.
class QuietStderr {
 public:
  QuietStderr();
  ~QuietStderr();
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;

 private:
  int saved_ = -1;
};

}  // namespace vdfx::io
