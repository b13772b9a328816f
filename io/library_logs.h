/// @file
/// @brief Keeping the media libraries quiet: vdfx reports every failure itself, with the file and
/// the place, so what FFmpeg's libav* (videos) and OpenCV (images) print on their own only buries
/// that message. `vdfx --verbose` leaves them on.
#pragma once

namespace vdfx::io {

/// Silences the libraries from now on: OpenCV's log, FFmpeg's av_log (io/libav_util.h keeps it
/// quiet when it sets its level). Call once, early, before any video is opened.
void quiet_library_logs();

/// True once quiet_library_logs() ran.
bool library_logs_quiet();

}  // namespace vdfx::io
