/// @file
/// @brief quiet_library_logs.
#include "io/library_logs.h"

#include <atomic>
#include <opencv2/core/utils/logger.hpp>

extern "C" {
#include <libavutil/log.h>
}

namespace vdfx::io {

namespace {
std::atomic<bool> g_quiet{false};
}  // namespace

void quiet_library_logs() {
  cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
  av_log_set_level(AV_LOG_QUIET);
  g_quiet = true;
}

bool library_logs_quiet() {
  return g_quiet;
}

}  // namespace vdfx::io
