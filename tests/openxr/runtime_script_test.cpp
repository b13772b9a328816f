/// @file
/// @brief The runtime's GL-free parts: its script reader against vdfx's recording reader (the
/// same samples from every committed recording, the same files refused at the same line), its
/// variables' values, and its binding-path resolution.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "io/input_error.h"
#include "io/recording.h"
#include "tests/openxr_runtime/config.h"
#include "tests/openxr_runtime/interaction_profiles.h"
#include "tests/openxr_runtime/script.h"
#include "tests/support/test_paths.h"

namespace vdfx::test_runtime {
namespace {

void expect_same_pose(const ScriptPose& a, const io::RecordedPose& b) {
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(a.q[i], b.q[i], 1e-12);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(a.p[i], b.p[i]);
}

void expect_same_hand(const std::optional<ScriptHand>& a,
                      const std::optional<io::RecordedHand>& b) {
  ASSERT_EQ(a.has_value(), b.has_value());
  if (!a) return;
  expect_same_pose(a->aim, b->aim);
  EXPECT_EQ(a->trigger, b->trigger);
  EXPECT_EQ(a->squeeze, b->squeeze);
  EXPECT_EQ(a->stick, b->stick);
  EXPECT_EQ(a->primary, b->primary);
  EXPECT_EQ(a->secondary, b->secondary);
  EXPECT_EQ(a->menu, b->menu);
  EXPECT_EQ(a->stick_click, b->stick_click);
}

TEST(RuntimeScript, ReadsEveryCommittedRecordingAsVdfxDoes) {
  int files = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::filesystem::path(VDFX_SOURCE_DIR) / "recordings")) {
    if (entry.path().extension() != ".jsonl") continue;
    SCOPED_TRACE(entry.path().string());
    ++files;
    const io::Recording rec = io::read_recording(entry.path());
    const Script script = read_script(entry.path().string());
    EXPECT_EQ(script.hmd, rec.header.hmd);
    std::size_t n = 0;
    for (const io::RecordingLine& line : rec.lines) {
      const auto* sample = std::get_if<io::RecordedSample>(&line.value);
      if (!sample) continue;  // HID lines: the runtime plays the samples
      ASSERT_LT(n, script.samples.size());
      const ScriptSample& s = script.samples[n++];
      EXPECT_EQ(s.t_ns, sample->t_ns);
      expect_same_pose(s.head, sample->head);
      expect_same_hand(s.left, sample->left);
      expect_same_hand(s.right, sample->right);
    }
    EXPECT_EQ(n, script.samples.size());
    // Step, as vdfx's replay: the sample at or before a time holds until the next.
    EXPECT_EQ(script.at(script.samples[0].t_ns), &script.samples[0]);
    EXPECT_EQ(script.at(script.end_ns() + 1), &script.samples.back());
  }
  EXPECT_GE(files, 10);
}

struct BadScript {
  const char* name;
  const char* line;  //!< the third line, after a good header and a good first sample
};

const char* const kHeader =
    R"({"format":"vdfx.recording","version":1,"hmd":"sim","video":null,"note":""})";
const char* const kGood = R"({"t_ns":100,"head":{"q":[1,0,0,0],"p":[0,1.6,0]}})";

const BadScript kBad[] = {
    {"TimeGoesBack", R"({"t_ns":50,"head":{"q":[1,0,0,0],"p":[0,1.6,0]}})"},
    {"SameTime", R"({"t_ns":100,"head":{"q":[1,0,0,0],"p":[0,1.6,0]}})"},
    {"NotUnit", R"({"t_ns":200,"head":{"q":[0.9,0,0,0],"p":[0,1.6,0]}})"},
    {"MissingHead", R"({"t_ns":200})"},
    {"UnknownField", R"({"t_ns":200,"head":{"q":[1,0,0,0],"p":[0,1.6,0]},"tail":1})"},
    {"TriggerAboveOne",
     R"({"t_ns":200,"head":{"q":[1,0,0,0],"p":[0,1.6,0]},"right":{"aim":{"q":[1,0,0,0],"p":[0,0,0]},"trigger":1.5,"squeeze":0,"stick":[0,0],"buttons":{"a":false,"b":false,"stick":false}}})"},
    {"StickOutOfRange",
     R"({"t_ns":200,"head":{"q":[1,0,0,0],"p":[0,1.6,0]},"right":{"aim":{"q":[1,0,0,0],"p":[0,0,0]},"trigger":0,"squeeze":0,"stick":[0,2],"buttons":{"a":false,"b":false,"stick":false}}})"},
    {"LeftHandWithA",
     R"({"t_ns":200,"head":{"q":[1,0,0,0],"p":[0,1.6,0]},"left":{"aim":{"q":[1,0,0,0],"p":[0,0,0]},"trigger":0,"squeeze":0,"stick":[0,0],"buttons":{"a":false,"b":false,"stick":false}}})"},
    {"NegativeTime", R"({"t_ns":-5,"head":{"q":[1,0,0,0],"p":[0,1.6,0]}})"},
    {"NotJson", R"({"t_ns":200,"head":)"},
    {"Blank", ""},
};

class RuntimeScriptRefuses : public ::testing::TestWithParam<BadScript> {};

TEST_P(RuntimeScriptRefuses, WhatVdfxRefusesAtTheSameLine) {
  const auto dir = std::filesystem::path(VDFX_TEST_RUNTIME_OUTPUT_ROOT) / "RuntimeScriptRefuses";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / (std::string(GetParam().name) + ".vdrec.jsonl")).string();
  // A fourth good line keeps the bad one from being a tolerated truncated last line.
  std::ofstream(path) << kHeader << "\n"
                      << kGood << "\n"
                      << GetParam().line << "\n"
                      << R"({"t_ns":900,"head":{"q":[1,0,0,0],"p":[0,1.6,0]}})"
                      << "\n";
  std::string vdfx_message, runtime_message;
  try {
    io::read_recording(path);
  } catch (const io::InputError& e) {
    vdfx_message = e.what();
  }
  try {
    read_script(path);
  } catch (const std::runtime_error& e) {
    runtime_message = e.what();
  }
  EXPECT_NE(vdfx_message.find(path + ":3"), std::string::npos) << vdfx_message;
  EXPECT_NE(runtime_message.find(path + ":3"), std::string::npos) << runtime_message;
}

INSTANTIATE_TEST_SUITE_P(Lines, RuntimeScriptRefuses, ::testing::ValuesIn(kBad),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(RuntimeScript, ATruncatedLastLineIsDroppedWithAWarning) {
  const auto dir = std::filesystem::path(VDFX_TEST_RUNTIME_OUTPUT_ROOT) / "RuntimeScript";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "truncated.vdrec.jsonl").string();
  std::ofstream(path) << kHeader << "\n"
                      << kGood << "\n"
                      << R"({"t_ns":200,"he)";
  const Script s = read_script(path);
  EXPECT_EQ(s.samples.size(), 1u);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find(path + ":3"), std::string::npos);
  EXPECT_EQ(io::read_recording(path).warnings.size(), 1u);
}

TEST(RuntimeConfig, CaptureAndFormatValues) {
  EXPECT_EQ(parse_capture_spec("").mode, CaptureSpec::Mode::Last);
  EXPECT_EQ(parse_capture_spec("all").mode, CaptureSpec::Mode::All);
  EXPECT_EQ(parse_capture_spec("none").mode, CaptureSpec::Mode::None);
  const CaptureSpec list = parse_capture_spec("0, 10,20-25");
  EXPECT_TRUE(list.wants(0));
  EXPECT_TRUE(list.wants(10));
  EXPECT_TRUE(list.wants(20));
  EXPECT_TRUE(list.wants(25));
  EXPECT_FALSE(list.wants(1));
  EXPECT_FALSE(list.wants(26));
  EXPECT_THROW(parse_capture_spec("25-20"), std::runtime_error);
  EXPECT_THROW(parse_capture_spec("1,x"), std::runtime_error);
  const auto formats = parse_swapchain_formats("GL_RGBA16F,GL_SRGB8_ALPHA8");
  ASSERT_EQ(formats.size(), 2u);
  EXPECT_EQ(formats[0].name, "GL_RGBA16F");
  EXPECT_TRUE(formats[1].srgb);
  EXPECT_TRUE(parse_swapchain_formats("none").empty());
  try {
    parse_swapchain_formats("GL_RGB8");
    ADD_FAILURE() << "GL_RGB8 accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("unknown format 'GL_RGB8' (known: GL_SRGB8_ALPHA8"),
              std::string::npos)
        << e.what();
  }
}

TEST(RuntimeProfiles, BindingPathsResolveToTheSpecsComponents) {
  const InteractionProfile* touch =
      find_interaction_profile("/interaction_profiles/oculus/touch_controller");
  ASSERT_NE(touch, nullptr);
  const auto trigger_bool =
      resolve_binding(*touch, "/user/hand/right/input/trigger", XR_ACTION_TYPE_BOOLEAN_INPUT);
  ASSERT_TRUE(trigger_bool);  // Touch's trigger has no click: its value, past half way
  EXPECT_EQ(trigger_bool->component->subpath, "/input/trigger/value");
  EXPECT_EQ(trigger_bool->hand, 1);
  EXPECT_FALSE(resolve_binding(*touch, "/user/hand/left/input/a/click",
                               XR_ACTION_TYPE_BOOLEAN_INPUT));  // A is on the right
  EXPECT_FALSE(
      resolve_binding(*touch, "/user/hand/left/input/trigger/value", XR_ACTION_TYPE_POSE_INPUT));
  EXPECT_FALSE(
      resolve_binding(*touch, "/user/head/input/trigger/value", XR_ACTION_TYPE_FLOAT_INPUT));
  const InteractionProfile* vive =
      find_interaction_profile("/interaction_profiles/htc/vive_controller");
  ASSERT_NE(vive, nullptr);
  const auto squeeze =
      resolve_binding(*vive, "/user/hand/left/input/squeeze", XR_ACTION_TYPE_FLOAT_INPUT);
  ASSERT_TRUE(squeeze);  // the Vive's squeeze is a click: a float action reads 0 or 1
  EXPECT_EQ(squeeze->component->subpath, "/input/squeeze/click");
  ScriptHand h;
  h.squeeze = 0.7;
  EXPECT_FLOAT_EQ(component_value(*squeeze->component, h).f, 1.0f);
  EXPECT_EQ(interaction_profiles().size(), 5u);
}

}  // namespace
}  // namespace vdfx::test_runtime
