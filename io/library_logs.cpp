/// @file
/// @brief quiet_library_logs and QuietStderr.
#include "io/library_logs.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <opencv2/core/utils/logger.hpp>

namespace vdfx::io {

namespace {
std::atomic<bool> g_quiet{false};
}  // namespace

void quiet_library_logs() {
  cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
  // OpenCV reads this when it first sets FFmpeg up (at the first video opened) and hands it to
  // av_log_set_level; -8 is AV_LOG_QUIET. A value the user set is kept.
  ::setenv("OPENCV_FFMPEG_LOGLEVEL", "-8", /*overwrite=*/0);
  g_quiet = true;
}

bool library_logs_quiet() {
  return g_quiet;
}

QuietStderr::QuietStderr() {
  if (!g_quiet) return;
  std::fflush(stderr);
  const int null_fd = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
  if (null_fd < 0) return;
  saved_ = ::fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 0);
  if (saved_ >= 0) ::dup2(null_fd, STDERR_FILENO);
  ::close(null_fd);
}

QuietStderr::~QuietStderr() {
  if (saved_ < 0) return;
  std::fflush(stderr);
  ::dup2(saved_, STDERR_FILENO);
  ::close(saved_);
}

}  // namespace vdfx::io
