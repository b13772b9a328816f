/// @file
/// @brief `vdfx edit` and `vdfx play` with `--runtime openxr` against the simulated OpenXR
/// runtime (Debian's loader, the core validation layer on): the session's lifecycle, LOSS_PENDING
/// mid-edit, a scripted trigger press placing a keyframe at the scripted gaze, a headset
/// recording replaying in the sim to the same sidecar, each error's message and exit code, SIGINT
/// ending the session through the runtime's lifecycle, and `vdfx hmd openxr` (the refresh rate
/// read or measured, every format by name).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <glm/gtc/quaternion.hpp>

#include "effects/coords.h"
#include "io/sidecar.h"
#include "tests/app/openxr_test_support.h"
#include "tests/app/signal_test_support.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;
using testing::gaze_script;
using testing::write_script;

class OpenXrCmd : public testing::OpenXrTest {
 protected:
  void SetUp() override {
    OpenXrTest::SetUp();
    pano_ = testing::write_test_panorama(dir());
    sidecar_ = dir() / "pano.vdfx.json";
    testing::write_text(sidecar_, testing::exposure_sidecar());
  }
  /// The editor on the panorama with a new sidecar, small eyes, no visible window.
  testing::CommandResult edit(const fs::path& sidecar, const std::string& more = "") const {
    return run("edit " + pano_.string() + " --sidecar " + sidecar.string() +
               " --runtime openxr --hidden --scale 0.1 " + more);
  }
  std::vector<std::string> states() const {
    std::vector<std::string> out;
    const nlohmann::json session = session_json();
    for (const auto& s : session["states"]) {
      std::string name = s["state"];
      out.push_back(name.substr(std::string("XR_SESSION_STATE_").size()));
    }
    return out;
  }
  fs::path pano_, sidecar_;
};

TEST_F(OpenXrCmd, PlayRunsFromIdleToFocusedAndOutToExitingWhenTheScriptEnds) {
  write_script(dir() / "s.vdrec.jsonl", gaze_script(20.0, 0.0, 30));
  knob("VDFX_TEST_RUNTIME_SCRIPT", (dir() / "s.vdrec.jsonl").string());
  const auto r = run("play " + pano_.string() + " --sidecar " + sidecar_.string() +
                     " --runtime openxr --hidden --scale 0.1");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("the OpenXR runtime ended the session (EXITING)"), std::string::npos)
      << r.output;
  const std::vector<std::string> want = {"IDLE",    "READY",   "SYNCHRONIZED", "VISIBLE",
                                         "FOCUSED", "VISIBLE", "SYNCHRONIZED", "STOPPING",
                                         "IDLE",    "EXITING"};
  EXPECT_EQ(states(), want);
  const nlohmann::json s = session_json();
  EXPECT_GE(s["frames_ended"].get<int>(), 25) << "about one frame per script step";
  EXPECT_EQ(s["frames_ended"], s["frames_waited"]) << "every waited frame was ended";
}

TEST_F(OpenXrCmd, EscapeLikeEndsLeaveThroughTheRuntimesStates) {
  // --frames N: vdfx asks to leave (xrRequestExitSession) before the script is over.
  write_script(dir() / "s.vdrec.jsonl", gaze_script(0.0, 0.0, 400));
  knob("VDFX_TEST_RUNTIME_SCRIPT", (dir() / "s.vdrec.jsonl").string());
  const auto r = run("play " + pano_.string() + " --sidecar " + sidecar_.string() +
                     " --runtime openxr --hidden --scale 0.1 --frames 12");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("ended the session"), std::string::npos) << "vdfx asked: " << r.output;
  const std::vector<std::string> st = states();
  ASSERT_FALSE(st.empty());
  EXPECT_EQ(st.back(), "EXITING");
  EXPECT_NE(std::find(st.begin(), st.end(), "STOPPING"), st.end());
  EXPECT_LT(session_json()["frames_ended"].get<int>(), 30) << "left long before the script end";
}

TEST_F(OpenXrCmd, LossPendingMidEditLeavesWithTheDocumentSaved) {
  // A keyframe placed at frames 10-20, then the headset is lost at 0.4 s of the session.
  write_script(dir() / "s.vdrec.jsonl", gaze_script(-35.0, 5.0, 200, 10, 20));
  knob("VDFX_TEST_RUNTIME_SCRIPT", (dir() / "s.vdrec.jsonl").string());
  knob("VDFX_TEST_RUNTIME_LOSS_PENDING_NS", "400000000");
  const fs::path out = dir() / "lost.vdfx.json";
  const auto r = edit(out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("LOSS_PENDING"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("saved"), std::string::npos) << r.output;
  const std::vector<std::string> st = states();
  ASSERT_FALSE(st.empty());
  EXPECT_EQ(st.back(), "LOSS_PENDING");
  const io::Sidecar s = io::read_sidecar(out);
  ASSERT_EQ(s.effects.size(), 1u);
  EXPECT_EQ(s.effects[0].keyframes.size(), 1u);
  EXPECT_FALSE(fs::exists(fs::path(out.string() + ".autosave"))) << "a clean exit";
}

/// The angle between two directions, degrees.
double angle_deg(const effects::Direction& a, const effects::Direction& b) {
  const Eigen::Vector3d u = effects::to_unit(a), v = effects::to_unit(b);
  return std::atan2(u.cross(v).norm(), u.dot(v)) * effects::kRadToDeg;
}

TEST_F(OpenXrCmd, TriggerPressPlacesAKeyframeAtTheScriptedGaze) {
  struct Gaze {
    double az, alt;
  };
  for (const Gaze g : {Gaze{30.0, 10.0}, Gaze{-150.0, -35.0}}) {
    SCOPED_TRACE("gaze " + std::to_string(g.az) + ", " + std::to_string(g.alt));
    write_script(dir() / "s.vdrec.jsonl", gaze_script(g.az, g.alt, 45, 15, 30));
    knob("VDFX_TEST_RUNTIME_SCRIPT", (dir() / "s.vdrec.jsonl").string());
    const fs::path out = dir() / "placed.vdfx.json";
    fs::remove(out);
    const auto r = edit(out);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const io::Sidecar s = io::read_sidecar(out);
    ASSERT_EQ(s.effects.size(), 1u) << r.output;
    ASSERT_EQ(s.effects[0].keyframes.size(), 1u);
    const effects::Keyframe& k = s.effects[0].keyframes[0];
    EXPECT_LT(angle_deg(k.direction, {g.az, g.alt}), 0.1)
        << k.direction.azimuth_deg << ", " << k.direction.altitude_deg;
    // The controller's pulse: once, on the right hand, when the trigger let go.
    const nlohmann::json haptics = session_json()["haptics"];
    ASSERT_EQ(haptics.size(), 1u) << haptics.dump();
    EXPECT_EQ(haptics[0]["subaction"], "/user/hand/right");
    EXPECT_GE(haptics[0]["frame"].get<int>(), 30) << "not before the release";
  }
}

TEST_F(OpenXrCmd, HeadsetRecordingReplaysInTheSimToTheSameSidecar) {
  write_script(dir() / "s.vdrec.jsonl", gaze_script(60.0, -10.0, 45, 12, 25));
  knob("VDFX_TEST_RUNTIME_SCRIPT", (dir() / "s.vdrec.jsonl").string());
  const fs::path live = dir() / "live.vdfx.json", rec = dir() / "session.vdrec.jsonl";
  const auto r = edit(live, "--record " + rec.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const io::Recording recording = io::read_recording(rec);
  EXPECT_EQ(recording.header.hmd, "openxr");
  EXPECT_GE(recording.lines.size(), 40u);

  const fs::path replayed = dir() / "replayed.vdfx.json";
  const auto p =
      testing::run_vdfx("replay " + rec.string() + " --video " + fs::absolute(pano_).string() +
                        " --sidecar-out " + replayed.string());
  ASSERT_EQ(p.exit_code, 0) << p.output;
  const std::string a = test_files::slurp(live), b = test_files::slurp(replayed);
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(a, b) << "the replay's sidecar differs from the headset session's";
  EXPECT_NE(a.find("\"keyframes\""), std::string::npos);
}

TEST_F(OpenXrCmd, EachErrorIsAMessageWithItsExitCode) {
  struct Row {
    const char* name;
    const char* knob;
    const char* value;
    const char* args;
    int exit_code;
    const char* message;
  };
  const Row rows[] = {
      {"no runtime", "XR_RUNTIME_JSON", "/nonexistent/runtime.json", "", 1,
       "no OpenXR runtime: install Monado, or set XR_RUNTIME_JSON"},
      {"no headset", "VDFX_TEST_RUNTIME_NO_HMD", "always", "", 1,
       "no headset connected: the OpenXR runtime 'vdfx test runtime' answers "
       "XR_ERROR_FORM_FACTOR_UNAVAILABLE"},
      {"no OpenGL", "VDFX_TEST_RUNTIME_NO_OPENGL", "1", "", 1,
       "does not offer XR_KHR_opengl_enable"},
      {"no format", "VDFX_TEST_RUNTIME_SWAPCHAIN_FORMATS", "GL_DEPTH_COMPONENT24", "", 1,
       "offers no swapchain format vdfx can render to (it offers: GL_DEPTH_COMPONENT24"},
      {"input", "VDFX_TEST_RUNTIME_CAPTURE", "none", "--input hid", 2,
       "with --runtime openxr the input is the headset's controllers"},
      {"sim option", "VDFX_TEST_RUNTIME_CAPTURE", "none", "--fov 90", 2,
       "--fov does nothing with --runtime openxr"},
  };
  for (const Row& row : rows) {
    SCOPED_TRACE(row.name);
    knobs_.clear();
    knob(row.knob, row.value);
    const auto r = run("play " + pano_.string() + " --sidecar " + sidecar_.string() +
                       " --runtime openxr --hidden --scale 0.1 --frames 5 " + row.args);
    EXPECT_EQ(r.exit_code, row.exit_code) << r.output;
    EXPECT_NE(r.output.find(row.message), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("Error ["), std::string::npos) << "loader noise: " << r.output;
  }
  // A headset that turns up within the wait is used.
  knobs_.clear();
  knob("VDFX_TEST_RUNTIME_NO_HMD", "5");
  const auto r = run("play " + pano_.string() + " --sidecar " + sidecar_.string() +
                     " --runtime openxr --hidden --scale 0.1 --frames 5");
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST_F(OpenXrCmd, HmdOpenxrPrintsWhatTheRuntimeOffers) {
  const auto r = run("hmd openxr");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* want :
       {"runtime        vdfx test runtime", "left view      1440x1600 recommended",
        "GL_SRGB8_ALPHA8", "vdfx renders   GL_SRGB8_ALPHA8", "refresh        90 Hz",
        "world space    STAGE", "/interaction_profiles/valve/index_controller",
        "/interaction_profiles/microsoft/motion_controller", "XR_KHR_opengl_enable"})
    EXPECT_NE(r.output.find(want), std::string::npos) << want << "\n" << r.output;
  knob("XR_RUNTIME_JSON", "/nonexistent/runtime.json");
  const auto none = run("hmd openxr");
  EXPECT_EQ(none.exit_code, 1) << none.output;
  EXPECT_NE(none.output.find("no OpenXR runtime"), std::string::npos) << none.output;
}

TEST_F(OpenXrCmd, SigintEndsTheSessionThroughTheRuntimesLifecycle) {
  // A long script: the session would run for minutes; SIGINT once frame 5 has been shown.
  write_script(dir() / "s.vdrec.jsonl", gaze_script(0.0, 0.0, 5000));
  knob("VDFX_TEST_RUNTIME_SCRIPT", (dir() / "s.vdrec.jsonl").string());
  knob("VDFX_TEST_RUNTIME_CAPTURE", "5");
  std::vector<std::pair<std::string, std::string>> env = env_->variables();
  env.insert(env.end(), knobs_.begin(), knobs_.end());
  testing::VdfxProcess play({"play", pano_.string(), "--sidecar", sidecar_.string(), "--runtime",
                             "openxr", "--hidden", "--scale", "0.1"},
                            dir() / "play.log", env);
  ASSERT_TRUE(play.wait_until([&] { return fs::exists(frame_dir(5) / "frame.json"); }))
      << play.output();
  play.signal(SIGINT);
  const int status = play.wait();
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT)
      << testing::describe_status(status) << "\n"
      << play.output();
  EXPECT_NE(play.output().find("vdfx play: stopped by SIGINT after "), std::string::npos)
      << play.output();
  // The runtime saw the session ended in order: asked to exit, ended, destroyed.
  const nlohmann::json session = session_json();
  std::vector<std::string> calls;
  for (const auto& c : session["lifecycle_calls"]) calls.push_back(c["call"]);
  EXPECT_EQ(calls, (std::vector<std::string>{"xrBeginSession", "xrRequestExitSession",
                                             "xrEndSession", "xrDestroySession"}));
  EXPECT_EQ(states().back(), "EXITING");
  EXPECT_LT(session["frames_ended"].get<int>(), 4000) << "left long before the script's end";
}

TEST_F(OpenXrCmd, HmdOpenxrReadsTheDisplaysRatesOrMeasuresThemPastPlaceholderFrames) {
  // Monado's first frames predict a placeholder 16 ms apart ("62.5 Hz"): measured past them.
  knob("VDFX_TEST_RUNTIME_PLACEHOLDER_FRAMES", "5");
  const auto measured = run("hmd openxr");
  ASSERT_EQ(measured.exit_code, 0) << measured.output;
  EXPECT_NE(measured.output.find("refresh        90 Hz (measured: the median interval of the "
                                 "display times the runtime predicted for 30 frames"),
            std::string::npos)
      << measured.output;
  EXPECT_EQ(measured.output.find("62.5"), std::string::npos) << measured.output;
  // With XR_FB_display_refresh_rate the display's own rates, read, not measured.
  knob("VDFX_TEST_RUNTIME_REFRESH_RATES", "72,90,120");
  const auto read = run("hmd openxr");
  ASSERT_EQ(read.exit_code, 0) << read.output;
  EXPECT_NE(read.output.find("refresh        90 Hz (XR_FB_display_refresh_rate; the display "
                             "offers 72, 90, 120 Hz)"),
            std::string::npos)
      << read.output;
  const nlohmann::json session = session_json();
  EXPECT_EQ(session["frames_waited"], 0) << "read, so no frame was run to measure";
}

TEST_F(OpenXrCmd, HmdOpenxrNamesEverySwapchainFormat) {
  knob("VDFX_TEST_RUNTIME_SWAPCHAIN_FORMATS",
       "GL_RGBA16F,GL_SRGB8_ALPHA8,GL_DEPTH24_STENCIL8,GL_DEPTH32F_STENCIL8,GL_R11F_G11F_B10F");
  const auto r = run("hmd openxr");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // GL_DEPTH32F_STENCIL8 (0x8CAD) was printed as a number.
  EXPECT_NE(r.output.find("\nformats        GL_RGBA16F, GL_SRGB8_ALPHA8, GL_DEPTH24_STENCIL8, "
                          "GL_DEPTH32F_STENCIL8, GL_R11F_G11F_B10F\n"),
            std::string::npos)
      << r.output;
}

}  // namespace
}  // namespace vdfx::app
