/// @file
/// @brief File helpers every test binary shares: fresh output folders under the build tree, whole
/// files read back, and the repository's recordings.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/support/test_paths.h"

namespace vdfx::test_files {

/// Empties and returns VDFX_TEST_OUTPUT_DIR / relative (build/tests/output/...).
inline std::filesystem::path fresh_dir(const std::filesystem::path& relative) {
  const auto d = std::filesystem::path(VDFX_TEST_OUTPUT_DIR) / relative;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

/// The whole file, byte for byte ("" when it cannot be opened).
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The committed recordings (recordings/ at the repository root).
inline std::filesystem::path recordings_dir() {
  return std::filesystem::path(VDFX_SOURCE_DIR) / "recordings";
}

}  // namespace vdfx::test_files
