/// @file
/// @brief Khronos's own OpenXR client, hello_xr (Debian's libopenxr-utils), on the simulated
/// runtime through Debian's loader with the core validation layer on: it runs a scripted
/// session to its end, and what it submitted is read back. The runtime must behave as a runtime
/// to an app that was not written for it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/openxr/child_process.h"
#include "tests/openxr_runtime/test_runtime_env.h"
#include "tests/support/test_paths.h"

namespace vdfx::test_runtime {
namespace {

using nlohmann::json;

const std::filesystem::path kData = VDFX_OPENXR_TEST_DATA_DIR;

json read_json(const std::filesystem::path& p) {
  std::ifstream in(p);
  return json::parse(in);
}

std::vector<std::string> state_names(const json& session) {
  std::vector<std::string> out;
  for (const auto& s : session.at("states")) out.push_back(s.at("state"));
  return out;
}

/// Runs hello_xr -g OpenGL on `script` with the tiny90 headset; the environment's validation
/// log and read-back folder hold the rest.
ChildResult run_hello_xr(const OpenXrTestEnvironment& env, const std::string& script,
                         const std::string& capture) {
  auto vars = env.variables();
  vars.emplace_back("VDFX_TEST_RUNTIME_SCRIPT", (kData / script).string());
  vars.emplace_back("VDFX_TEST_RUNTIME_HMD", (kData / "tiny90.json").string());
  vars.emplace_back("VDFX_TEST_RUNTIME_CAPTURE", capture);
  // Xvfb lacks the XFree86-VidModeExtension that hello_xr's window code calls unchecked.
  vars.emplace_back("LD_PRELOAD", VDFX_XF86VIDMODE_SHIM);
  return run_child({VDFX_HELLO_XR, "-g", "OpenGL", "-v"}, vars, env.dir() / "hello_xr.log", 300);
}

/// The prerequisites, checked so that a machine without them fails with the reason.
std::string missing(const OpenXrTestEnvironment& env) {
  std::string m = env.missing_prerequisites();
  if (std::string(VDFX_HELLO_XR).empty()) {
    m += "Khronos's hello_xr was not found when CMake ran: install libopenxr-utils "
         "(.ci/deps.sh) and configure again.";
  }
  return m;
}

void expect_clean_run(const OpenXrTestEnvironment& env, const ChildResult& r) {
  ASSERT_FALSE(r.timed_out) << r.output;
  EXPECT_EQ(r.exit_code, 0) << r.output;
  // The layer was loaded (so "no error" below means something) and reported no error.
  EXPECT_NE(r.output.find("Core Validation output type"), std::string::npos) << r.output;
  EXPECT_EQ(env.validation_errors(), "");
  // The runtime refused nothing hello_xr asked (its refusals are logged with this prefix).
  EXPECT_EQ(r.output.find("vdfx-test-runtime:"), std::string::npos) << r.output;
}

/// The sRGB encoding of an 8-bit linear value: what the runtime's read-back shows for a
/// linear swapchain (hello_xr picks GL_RGBA8 from the runtime's list).
int displayed(double linear) {
  const double x = std::round(linear * 255.0) / 255.0;
  const double e = x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
  return static_cast<int>(std::lround(e * 255.0));
}

TEST(HelloXr, RunsAScriptedSessionToItsEndValidationClean) {
  OpenXrTestEnvironment env("HelloXr.ScriptedSession");
  ASSERT_EQ(missing(env), "");
  const ChildResult r = run_hello_xr(env, "hello_xr_grab.vdrec.jsonl", "5,20");
  expect_clean_run(env, r);
  // hello_xr saw the whole lifecycle, and left when the runtime said EXITING.
  EXPECT_NE(r.output.find("XR_SESSION_STATE_IDLE->XR_SESSION_STATE_EXITING"), std::string::npos);
  const json session = read_json(env.output_dir() / "session.json");
  const std::vector<std::string> expected{
      "XR_SESSION_STATE_IDLE",         "XR_SESSION_STATE_READY",    "XR_SESSION_STATE_SYNCHRONIZED",
      "XR_SESSION_STATE_VISIBLE",      "XR_SESSION_STATE_FOCUSED",  "XR_SESSION_STATE_VISIBLE",
      "XR_SESSION_STATE_SYNCHRONIZED", "XR_SESSION_STATE_STOPPING", "XR_SESSION_STATE_IDLE",
      "XR_SESSION_STATE_EXITING"};
  EXPECT_EQ(state_names(session), expected);
  // The script ends at 300 ms: frame 28 (311 ms at 90 Hz) is the first past it and starts the
  // way out, so hello_xr waited 29 frames.
  EXPECT_EQ(session.at("frames_waited"), 29);
  EXPECT_EQ(session.at("interaction_profiles").at(0).at("profile"),
            "/interaction_profiles/oculus/touch_controller");
}

TEST(HelloXr, SubmittedFramesReadBackNonEmptyAtTheScriptedPoses) {
  OpenXrTestEnvironment env("HelloXr.ReadBack");
  ASSERT_EQ(missing(env), "");
  const ChildResult r = run_hello_xr(env, "hello_xr_grab.vdrec.jsonl", "5,20");
  expect_clean_run(env, r);
  const json hmd = read_json(kData / "tiny90.json");
  const double ipd = hmd.at("ipd_m");
  for (const int frame : {5, 20}) {
    SCOPED_TRACE("frame " + std::to_string(frame));
    char name[32];
    std::snprintf(name, sizeof name, "frame-%06d", frame);
    const auto folder = env.output_dir() / name;
    const json f = read_json(folder / "frame.json");
    ASSERT_EQ(f.at("layers").size(), 1u);
    const json& layer = f.at("layers").at(0);
    EXPECT_EQ(layer.at("type"), "projection");
    EXPECT_EQ(layer.at("space"), "LOCAL");  // hello_xr's default app space
    ASSERT_EQ(layer.at("views").size(), 2u);
    // The head turns 10 degrees left at 100 ms (frame 9 on): each eye sits IPD/2 beside it.
    const double yaw = frame >= 9 ? glm::radians(10.0) : 0.0;
    const glm::dquat head = glm::angleAxis(yaw, glm::dvec3(0, 1, 0));
    for (int eye = 0; eye < 2; ++eye) {
      SCOPED_TRACE(eye == 0 ? "left eye" : "right eye");
      const json& view = layer.at("views").at(eye);
      const glm::dvec3 want =
          glm::dvec3(0, 1.6, 0) + head * glm::dvec3((eye == 0 ? -0.5 : 0.5) * ipd, 0, 0);
      for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(view.at("pose_in_local").at("p").at(i), want[i], 1e-5);
      const json& fov = hmd.at("eyes").at(eye == 0 ? "left" : "right").at("fov_deg");
      EXPECT_NEAR(view.at("fov").at("angleLeft"), glm::radians(double(fov.at("angleLeft"))), 1e-6);
      EXPECT_NEAR(view.at("fov").at("angleUp"), glm::radians(double(fov.at("angleUp"))), 1e-6);
      const cv::Mat png = cv::imread((folder / view.at("image")).string(), cv::IMREAD_UNCHANGED);
      ASSERT_EQ(png.cols, 360);
      ASSERT_EQ(png.rows, 400);
      // The background is hello_xr's clear colour (DarkSlateGray, linear) as displayed.
      const cv::Vec4b corner = png.at<cv::Vec4b>(2, 2);  // B, G, R, A
      EXPECT_NEAR(corner[2], displayed(0.184313729), 1);
      EXPECT_NEAR(corner[1], displayed(0.309803933), 1);
      EXPECT_NEAR(corner[0], displayed(0.309803933), 1);
      // Straight ahead (the forward pixel follows the asymmetric FOV) is hello_xr's cube that
      // hangs 2 m in front of the view: most of a 21x21 square there is not background.
      const double tl = std::tan(glm::radians(double(fov.at("angleLeft"))));
      const double tr = std::tan(glm::radians(double(fov.at("angleRight"))));
      const int cx = static_cast<int>(png.cols * -tl / (tr - tl));
      int cube = 0;
      for (int y = 190; y <= 210; ++y) {
        for (int x = cx - 10; x <= cx + 10; ++x) {
          const cv::Vec4b p = png.at<cv::Vec4b>(y, x);
          cube += std::abs(p[2] - corner[2]) + std::abs(p[1] - corner[1]) > 6;
        }
      }
      EXPECT_GT(cube, 21 * 21 / 2);
    }
  }
}

TEST(HelloXr, GrabbingVibratesTheHandThatGrabs) {
  OpenXrTestEnvironment env("HelloXr.Grab");
  ASSERT_EQ(missing(env), "");
  const ChildResult r = run_hello_xr(env, "hello_xr_grab.vdrec.jsonl", "none");
  expect_clean_run(env, r);
  // hello_xr vibrates a hand whose grab (Touch: squeeze/value) is above 0.9; the script squeezes
  // the right hand from 100 ms to 200 ms.
  const json session = read_json(env.output_dir() / "session.json");
  const json& haptics = session.at("haptics");
  ASSERT_FALSE(haptics.empty());
  for (const json& h : haptics) {
    EXPECT_EQ(h.at("action"), "vibrate_hand");
    EXPECT_EQ(h.at("subaction"), "/user/hand/right");
    EXPECT_EQ(h.at("outputs"), json::array({"/user/hand/right/output/haptic"}));
    EXPECT_FLOAT_EQ(h.at("amplitude").get<float>(), 0.5f);
    const std::int64_t t = h.at("time_ns").get<std::int64_t>() - 1'000'000'000;
    EXPECT_GE(t, 100'000'000);
    EXPECT_LT(t, 200'000'000);
  }
}

TEST(HelloXr, QuitsWithItsOwnQuitActionBeforeTheScriptEnds) {
  OpenXrTestEnvironment env("HelloXr.Quit");
  ASSERT_EQ(missing(env), "");
  const ChildResult r = run_hello_xr(env, "hello_xr_quit.vdrec.jsonl", "none");
  expect_clean_run(env, r);
  // hello_xr's quit action is the left menu click: pressed at 100 ms of a 2 s script, it calls
  // xrRequestExitSession, and the session ends long before the script would end it.
  const json session = read_json(env.output_dir() / "session.json");
  const json& states = session.at("states");
  ASSERT_GE(states.size(), 3u);
  EXPECT_EQ(states.at(states.size() - 3).at("state"), "XR_SESSION_STATE_STOPPING");
  EXPECT_EQ(states.back().at("state"), "XR_SESSION_STATE_EXITING");
  const std::int64_t stop = states.at(states.size() - 3).at("time_ns").get<std::int64_t>();
  EXPECT_GE(stop, 1'100'000'000);
  EXPECT_LT(stop, 1'150'000'000);
  EXPECT_LT(session.at("frames_waited").get<int>(), 20);
}

}  // namespace
}  // namespace vdfx::test_runtime
