/// @file
/// @brief The runtime tests' fixture: a fresh environment per test (runtime, core validation
/// layer, read-back folder), the runtime's knobs cleared, scripts written from samples, and the
/// layer's report checked at the end.
#pragma once

#include <gtest/gtest.h>
#include <openxr/openxr.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "tests/openxr_runtime/test_runtime_env.h"

namespace vdfx::test_runtime {

/// One hand of a script sample (the recording format's fields).
struct HandSample {
  std::array<double, 4> q{1.0, 0.0, 0.0, 0.0};
  std::array<double, 3> p{0.2, 1.3, -0.3};
  double trigger = 0.0, squeeze = 0.0;
  std::array<double, 2> stick{0.0, 0.0};
  bool primary = false, secondary = false, menu = false, stick_click = false;
};

struct ScriptLine {
  ScriptLine(std::int64_t t, double yaw = 0.0, std::array<double, 3> p = {0.0, 1.6, 0.0})
      : t_ns(t), yaw_deg(yaw), head_p(p) {}
  std::int64_t t_ns = 0;
  double yaw_deg = 0.0;  //!< head turned left about +y
  std::array<double, 3> head_p{0.0, 1.6, 0.0};
  std::optional<HandSample> left;  //!< absent: not tracked
  std::optional<HandSample> right;
};

class RuntimeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const char* name :
         {"VDFX_TEST_RUNTIME_SCRIPT", "VDFX_TEST_RUNTIME_HMD", "VDFX_TEST_RUNTIME_CONTROLLER",
          "VDFX_TEST_RUNTIME_NO_HMD", "VDFX_TEST_RUNTIME_NO_OPENGL",
          "VDFX_TEST_RUNTIME_SWAPCHAIN_FORMATS", "VDFX_TEST_RUNTIME_LOSS_PENDING_NS",
          "VDFX_TEST_RUNTIME_EXIT_AFTER_FRAMES", "VDFX_TEST_RUNTIME_OUTPUT_DIR",
          "VDFX_TEST_RUNTIME_CAPTURE", "VDFX_TEST_RUNTIME_SWITCH_CONTEXT",
          "VDFX_TEST_RUNTIME_REFRESH_RATES", "VDFX_TEST_RUNTIME_PLACEHOLDER_FRAMES"}) {
      unsetenv(name);
    }
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "." + info->name();
    for (char& c : name) c = (c == '/') ? '_' : c;
    env_ = std::make_unique<OpenXrTestEnvironment>(name);
    ASSERT_EQ(env_->missing_prerequisites(), "");
    env_->apply();
  }

  void TearDown() override {
    if (!layer_off_ && !errors_expected_) {
      EXPECT_EQ(env_->validation_errors(), "");
    }
  }

  /// For the test that the layer's reports are seen: this test makes them on purpose.
  void expect_validation_errors() { errors_expected_ = true; }

  /// For tests of the runtime's own refusals: the layer would stop such calls before the
  /// runtime sees them.
  void without_layer() {
    unsetenv("XR_ENABLE_API_LAYERS");
    layer_off_ = true;
  }

  static void set(const char* name, const std::string& value) { setenv(name, value.c_str(), 1); }

  /// Writes a script (a recording in vdfx's format) into the test's folder and selects it.
  std::string script(const std::vector<ScriptLine>& lines, const std::string& hmd = "sim") {
    using nlohmann::json;
    const std::string path = (env_->dir() / "script.vdrec.jsonl").string();
    std::ofstream out(path);
    out << json{{"format", "vdfx.recording"},
                {"version", 1},
                {"hmd", hmd},
                {"video", nullptr},
                {"note", "test script"}}
               .dump()
        << "\n";
    for (const ScriptLine& l : lines) {
      const double half = l.yaw_deg * 3.14159265358979323846 / 360.0;
      json j{{"t_ns", l.t_ns},
             {"head", {{"q", {std::cos(half), 0.0, std::sin(half), 0.0}}, {"p", l.head_p}}}};
      const auto hand = [](const HandSample& h, bool left) {
        json b = left ? json{{"x", h.primary},
                             {"y", h.secondary},
                             {"menu", h.menu},
                             {"stick", h.stick_click}}
                      : json{{"a", h.primary}, {"b", h.secondary}, {"stick", h.stick_click}};
        return json{{"aim", {{"q", h.q}, {"p", h.p}}},
                    {"trigger", h.trigger},
                    {"squeeze", h.squeeze},
                    {"stick", h.stick},
                    {"buttons", b}};
      };
      if (l.left) j["left"] = hand(*l.left, true);
      if (l.right) j["right"] = hand(*l.right, false);
      out << j.dump() << "\n";
    }
    set("VDFX_TEST_RUNTIME_SCRIPT", path);
    return path;
  }

  nlohmann::json read_json(const std::filesystem::path& p) {
    std::ifstream in(p);
    return nlohmann::json::parse(in);
  }
  nlohmann::json session_json() { return read_json(env_->output_dir() / "session.json"); }

  OpenXrTestEnvironment& env() { return *env_; }

 private:
  std::unique_ptr<OpenXrTestEnvironment> env_;
  bool layer_off_ = false;
  bool errors_expected_ = false;
};

/// XrTime of frame k on the runtime's clock at `period` ns a frame.
inline XrTime frame_time(std::int64_t k, std::int64_t period = 11111111) {
  return 1'000'000'000 + k * period;
}

}  // namespace vdfx::test_runtime
