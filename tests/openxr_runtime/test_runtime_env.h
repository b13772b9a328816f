/// @file
/// @brief For tests that run OpenXR code against the simulated runtime (link the CMake target
/// vdfx_test_runtime_env): the environment that selects the runtime and turns Khronos's core
/// validation layer on, and the check that the layer reported no error.
///
///   vdfx::test_runtime::OpenXrTestEnvironment env("my_test");   // a fresh folder under build/
///   ASSERT_EQ(env.missing_prerequisites(), "");
///   env.apply();            // in this process; or env.variables() for a child's environment
///   ... run the OpenXR code (VDFX_TEST_RUNTIME_* knobs set as needed) ...
///   EXPECT_EQ(env.validation_errors(), "");
///   // what the app submitted: env.output_dir() (docs/openxr.md, "Testing without a headset")
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace vdfx::test_runtime {

/// The runtime's manifest in the build tree (XR_RUNTIME_JSON).
inline const char* test_runtime_manifest() {
  return VDFX_TEST_RUNTIME_MANIFEST;
}

/// The folder holding the core validation layer's manifest ("" when CMake found none).
inline const char* core_validation_layer_dir() {
  return VDFX_OPENXR_CORE_VALIDATION_DIR;
}

class OpenXrTestEnvironment {
 public:
  /// `name` names a folder under the build tree's tests/openxr_output (emptied first) that holds
  /// the validation log and the runtime's read-back folder.
  explicit OpenXrTestEnvironment(const std::string& name)
      : dir_(std::filesystem::path(VDFX_TEST_RUNTIME_OUTPUT_ROOT) / name) {
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }

  const std::filesystem::path& dir() const { return dir_; }
  std::filesystem::path output_dir() const { return dir_ / "runtime"; }
  std::filesystem::path validation_log() const { return dir_ / "core_validation.txt"; }

  /// "" when the runtime and the layer are there; else what is missing and how to get it. A test
  /// asserts this is empty, so a machine without them fails with the message, never skips.
  std::string missing_prerequisites() const {
    std::string missing;
    if (!std::filesystem::is_regular_file(test_runtime_manifest())) {
      missing += std::string("the simulated runtime's manifest ") + test_runtime_manifest() +
                 " is missing (build the target vdfx_test_runtime). ";
    }
    if (std::string(core_validation_layer_dir()).empty()) {
      missing +=
          "Khronos's core validation layer was not found when CMake ran: install "
          "openxr-layer-corevalidation (.ci/deps.sh) and configure again. ";
    }
    return missing;
  }

  /// The variables, as NAME/VALUE pairs: the simulated runtime, the core validation layer on and
  /// writing to validation_log(), and the runtime's read-back folder.
  std::vector<std::pair<std::string, std::string>> variables() const {
    return {{"XR_RUNTIME_JSON", test_runtime_manifest()},
            {"XR_API_LAYER_PATH", core_validation_layer_dir()},
            {"XR_ENABLE_API_LAYERS", "XR_APILAYER_LUNARG_core_validation"},
            {"XR_CORE_VALIDATION_FILE_NAME", validation_log().string()},
            {"VDFX_TEST_RUNTIME_OUTPUT_DIR", output_dir().string()}};
  }

  /// Sets variables() in this process (the loader reads them when an instance is made).
  void apply() const {
    for (const auto& [name, value] : variables()) setenv(name.c_str(), value.c_str(), 1);
  }

  /// Every message of severity error the layer wrote, with the lines that follow it (its
  /// objects); "" when none. Warnings and information are not errors.
  std::string validation_errors() const {
    std::ifstream in(validation_log());
    std::ostringstream errors;
    bool in_error = false;
    for (std::string line; std::getline(in, line);) {
      if (!line.empty() && line[0] == '[') in_error = line.rfind("[VALID_ERROR", 0) == 0;
      if (in_error) errors << line << "\n";
    }
    return errors.str();
  }

 private:
  std::filesystem::path dir_;
};

}  // namespace vdfx::test_runtime
