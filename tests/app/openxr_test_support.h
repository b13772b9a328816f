/// @file
/// @brief What the OpenXR backend's tests share: the simulated runtime's environment with the
/// core validation layer on (tests/openxr_runtime/test_runtime_env.h, checked after each test),
/// scripts written as vdfx recordings (the runtime plays them as the headset and controllers), and
/// the runtime's read-back folder (docs/openxr.md, "Testing without a headset").
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <optional>
#include <string>
#include <vector>

#include "io/recording.h"
#include "tests/app/command_test_util.h"
#include "tests/openxr_runtime/test_runtime_env.h"
#include "tests/test_files.h"
#include "xr/input/input_state_io.h"

namespace vdfx::app::testing {

/// The runtime's frame period for generic90 (90 Hz), and so the script's sample spacing.
inline constexpr std::int64_t kXrFrameNs = 11'111'111;

/// One step of a script: where the head looks and the right trigger; both hands tracked, the
/// right aim 20 degrees right of and 25 above the gaze (clear of the panels on the grips), the
/// left one down at its own panel.
struct ScriptStep {
  double azimuth_deg = 0.0, altitude_deg = 0.0;
  double trigger = 0.0;
};

/// Writes `steps` as a recording, one sample per frame period from t = one period.
inline void write_script(const std::filesystem::path& path, const std::vector<ScriptStep>& steps) {
  io::RecordingHeader h;
  h.hmd = "generic90";
  h.note = "OpenXR test script";
  io::RecordingWriter w(path, h);
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const ScriptStep& s = steps[i];
    xr::InputState in = xr::neutral_input_state(static_cast<std::int64_t>(i + 1) * kXrFrameNs);
    in.head_tracked = true;
    in.head.orientation = xr::look_rotation(s.azimuth_deg, s.altitude_deg);
    in.right.tracked = in.left.tracked = true;
    in.right.aim = {{0.2, 1.3, -0.3}, xr::look_rotation(s.azimuth_deg + 20, s.altitude_deg + 25)};
    in.left.aim = {{-0.2, 1.3, -0.3}, xr::look_rotation(-40.0, -30.0)};
    in.right.trigger = s.trigger;
    w.write(xr::to_recorded_sample(in));
  }
}

/// `n` steps looking at (az, alt), the right trigger pulled over steps [press, release).
inline std::vector<ScriptStep> gaze_script(double az, double alt, int n, int press = -1,
                                           int release = -1) {
  std::vector<ScriptStep> v(static_cast<std::size_t>(n), ScriptStep{az, alt, 0.0});
  for (int i = std::max(press, 0); i < release && i < n; ++i)
    v[static_cast<std::size_t>(i)].trigger = 1.0;
  return v;
}

/// A test with the simulated runtime and the core validation layer: every run's layer report is
/// checked for errors when the test ends.
class OpenXrTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string("app.") + info->test_suite_name() + "." + info->name();
    for (char& c : name) c = c == '/' ? '_' : c;
    env_.emplace(name);
    ASSERT_EQ(env_->missing_prerequisites(), "");
  }
  void TearDown() override {
    if (env_) {
      EXPECT_EQ(env_->validation_errors(), "") << "the core validation layer reported";
    }
  }

  const std::filesystem::path& dir() const { return env_->dir(); }
  std::filesystem::path runtime_out() const { return env_->output_dir(); }

  /// Sets a runtime knob (VDFX_TEST_RUNTIME_*) for the next runs.
  void knob(const std::string& name, const std::string& value) { knobs_[name] = value; }

  /// `vdfx ARGS` with the runtime, the layer and the knobs, under a time limit.
  CommandResult run(const std::string& args, int timeout_s = 300) const {
    std::string prefix = "env";
    for (const auto& [k, v] : env_->variables()) prefix += " " + k + "=" + v;
    for (const auto& [k, v] : knobs_) prefix += " " + k + "=" + v;
    return run_vdfx(args, prefix + " timeout " + std::to_string(timeout_s) + " ");
  }

  /// The runtime's session.json of the last run.
  nlohmann::json session_json() const {
    return nlohmann::json::parse(test_files::slurp(runtime_out() / "session.json"));
  }

  /// frame.json of a captured frame (VDFX_TEST_RUNTIME_CAPTURE).
  nlohmann::json frame_json(std::int64_t frame) const {
    return nlohmann::json::parse(test_files::slurp(frame_dir(frame) / "frame.json"));
  }
  std::filesystem::path frame_dir(std::int64_t frame) const {
    char name[32];
    std::snprintf(name, sizeof name, "frame-%06lld", static_cast<long long>(frame));
    return runtime_out() / name;
  }

  std::optional<test_runtime::OpenXrTestEnvironment> env_;
  std::map<std::string, std::string> knobs_;
};

}  // namespace vdfx::app::testing
