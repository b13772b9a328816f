/// @file
/// @brief Shared by the io tests: a fresh per-test folder under the build tree.
#pragma once

#include <filesystem>
#include <string>

namespace vdfx::io::testing {

/// Empties and returns build/tests/output/io/NAME.
inline std::filesystem::path temp_dir(const std::string& name) {
  const auto d = std::filesystem::path(VDFX_TEST_OUTPUT_DIR) / "io" / name;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

}  // namespace vdfx::io::testing
