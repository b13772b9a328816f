/// @file
/// @brief Shared by the io tests: a fresh per-test folder under the build tree.
#pragma once

#include <filesystem>
#include <string>

#include "tests/test_files.h"

namespace vdfx::io::testing {

/// Empties and returns build/tests/output/io/NAME.
inline std::filesystem::path temp_dir(const std::string& name) {
  return test_files::fresh_dir(std::filesystem::path("io") / name);
}

}  // namespace vdfx::io::testing
