/// @file
/// @brief One printf-formatted number as a string, for the editor's status texts and panels.
#pragma once

#include <cstdio>
#include <string>

namespace vdfx::app {

/// `format` holds one double conversion ("%+.1f stops").
inline std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

}  // namespace vdfx::app
