/// @file
/// @brief Shared by the io tests: a fresh per-test folder under the build tree.
#pragma once

#include <filesystem>
#include <string>

#include "io/input_error.h"
#include "tests/test_files.h"

namespace vdfx::io::testing {

/// Empties and returns build/tests/output/io/NAME.
inline std::filesystem::path temp_dir(const std::string& name) {
  return test_files::fresh_dir(std::filesystem::path("io") / name);
}

/// The message of the io::InputError `f` throws ("" when it throws none).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace vdfx::io::testing
