/// @file
/// @brief `vdfx replay` on the committed editor recordings: the resulting sidecars field by
/// field, byte-identical on every run, frames written, malformed recordings rejected with the line.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>
#include <sstream>

#include "app/editor/replay.h"
#include "editor_scripts.h"
#include "editor_test_util.h"
#include "io/input_error.h"
#include "tests/support/test_paths.h"
#include "tests/test_files.h"
#include "ui/colour_wheel.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;
using effects::EffectType;

const fs::path kRecordings = test_files::recordings_dir();
const fs::path kSunrise = "/usr/share/blender/datafiles/studiolights/world/sunrise.exr";

using test_files::slurp;

fs::path clip(const fs::path& dir) {
  const fs::path p = dir / "clip.avi";
  cv::VideoWriter w(p.string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 30.0,
                    cv::Size(128, 64));
  for (int i = 0; i < test::kClipFrames; ++i)
    w.write(cv::Mat(64, 128, CV_8UC3, cv::Scalar(40 + i, 90, 160)));
  return p;
}

/// Replays recordings/NAME over a fresh synthetic clip in `dir`, writing dir/out.vdfx.json.
ReplayOptions clip_replay(const fs::path& dir, const std::string& name) {
  ReplayOptions o;
  o.recording = kRecordings / name;
  o.video = clip(dir);
  o.sidecar_out = dir / "out.vdfx.json";
  return o;
}

int run(const std::string& args, std::string* err = nullptr) {
  const fs::path log = fs::path(VDFX_TEST_OUTPUT_DIR) / "editor" / "replay_stderr.txt";
  const int rc = std::system(
      (std::string(VDFX_BINARY) + " replay " + args + " 2>" + log.string() + " >/dev/null")
          .c_str());
  if (err) *err = slurp(log);
  return WEXITSTATUS(rc);
}

const effects::EffectTrack& track(const io::Sidecar& s, EffectType t) {
  for (const auto& e : s.effects)
    if (e.type == t) return e;
  throw std::runtime_error("no track " + std::string(effects::effect_name(t)));
}

void expect_key(const effects::Keyframe& k, double az, double alt, std::int64_t frame,
                std::vector<double> params) {
  EXPECT_NEAR(k.direction.azimuth_deg, az, 0.05);
  EXPECT_NEAR(k.direction.altitude_deg, alt, 0.05);
  EXPECT_EQ(k.frame, frame);
  ASSERT_EQ(k.params.size(), params.size());
  for (std::size_t i = 0; i < params.size(); ++i) EXPECT_NEAR(k.params[i], params[i], 0.011) << i;
}

TEST(ReplaySessions, PlaceExposureUndoRedoIsByteIdenticalTwice) {
  const auto dir = test::temp_dir("replay_place");
  const std::string common = (kRecordings / "editor_place_exposure.vdrec.jsonl").string() +
                             " --video " + kSunrise.string();
  ASSERT_EQ(run(common + " --sidecar-out " + (dir / "a.vdfx.json").string()), 0);
  ASSERT_EQ(run(common + " --sidecar-out " + (dir / "b.vdfx.json").string() + " --frames " +
                (dir / "frames").string()),
            0);
  EXPECT_EQ(slurp(dir / "a.vdfx.json"), slurp(dir / "b.vdfx.json"));
  const io::Sidecar s = io::read_sidecar(dir / "a.vdfx.json");
  ASSERT_EQ(s.effects.size(), 1u);
  const auto& ks = track(s, EffectType::Exposure).keyframes;
  ASSERT_EQ(ks.size(), 2u);
  expect_key(ks[0], -40.0, 0.0, 0, {2.0});
  expect_key(ks[1], 40.0, 10.0, 0, {-1.5});
  EXPECT_EQ(s.video.frames, 1);
  for (int i = 0; i < 5; ++i) {
    const cv::Mat png =
        cv::imread((dir / "frames" / ("replay_00" + std::to_string(i) + ".png")).string());
    ASSERT_FALSE(png.empty()) << i;
    EXPECT_EQ(png.size(), cv::Size(1280, 720));
  }
}

/// The last frame image of editor_place_exposure over the sunrise (BGR), starting from `start`
/// (an empty sidecar when null); the written sidecar goes to `out`.
cv::Mat last_replay_frame(const fs::path& dir, const io::Sidecar* start,
                          io::Sidecar* out = nullptr) {
  ReplayOptions o;
  o.recording = kRecordings / "editor_place_exposure.vdrec.jsonl";
  o.video = kSunrise;
  o.sidecar_out = dir / "out.vdfx.json";
  o.frames_dir = dir / "frames";
  o.width = 320;
  o.height = 180;
  if (start) {
    fs::create_directories(dir);
    o.sidecar_in = dir / "in.vdfx.json";
    io::write_sidecar(*o.sidecar_in, *start);
  }
  const ReplayResult r = run_replay(o);
  if (out) *out = r.sidecar;
  if (r.images.empty()) return {};
  return cv::imread(r.images.back().string());
}

double mean_difference(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat d;
  cv::absdiff(a, b, d);
  const cv::Scalar m = cv::mean(d);
  return (m[0] + m[1] + m[2]) / 3.0;
}

TEST(ReplaySessions, FramesShowTheSidecarsFlareAndGrain) {
  const auto root = test::temp_dir("replay_layers");
  io::Sidecar base;
  const cv::Mat plain = last_replay_frame(root / "plain", nullptr, &base);
  ASSERT_FALSE(plain.empty());
  base.effects.clear();
  // A flare whose fixed light sits where the session ends looking (az 40, alt 10), strong
  // everywhere; then a headset grain at full intensity.
  io::Sidecar with_flare = base;
  effects::FlareEffect f;
  f.light = effects::Direction{40.0, 10.0};
  f.keyframes = {{{40.0, 10.0}, 0, {4.0}}};
  with_flare.flares = {f};
  const cv::Mat flared = last_replay_frame(root / "flare", &with_flare);
  ASSERT_FALSE(flared.empty());
  EXPECT_GT(mean_difference(flared, plain), 2.0) << "the flare is drawn";
  // Brighter on the whole: a flare only adds light.
  EXPECT_GT(cv::mean(flared)[1], cv::mean(plain)[1]);

  io::Sidecar with_grain = base;
  effects::GrainEffect g;
  g.style = effects::GrainStyle::Headset;
  // Size 4: at 320 px over 90 degrees, grain of size 1 is finer than a pixel and band-limited away.
  g.keyframes = {{{40.0, 10.0}, 0, {1.0, 4.0}}};
  with_grain.grains = {g};
  const cv::Mat grained = last_replay_frame(root / "grain", &with_grain);
  ASSERT_FALSE(grained.empty());
  EXPECT_GT(mean_difference(grained, plain), 2.0) << "the grain is drawn";
}

TEST(ReplaySessions, AllWidgetsSessionGivesEveryEffect) {
  const auto dir = test::temp_dir("replay_all");
  const ReplayOptions o = clip_replay(dir, "editor_all_widgets.vdrec.jsonl");
  const io::Sidecar s = run_replay(o).sidecar;
  ASSERT_EQ(s.video.frames, test::kClipFrames);
  ASSERT_EQ(s.effects.size(), 6u);
  expect_key(track(s, EffectType::Blur).keyframes.at(0), 0.0, 0.0, 0, {2.0});
  const Eigen::Vector3d g = ui::tint_gain_from_hue_sat(120.0, 0.6);
  const Eigen::Vector3d gn = effects::normalize_tint(g);
  expect_key(track(s, EffectType::Tint).keyframes.at(0), 30.0, 0.0, 0, {gn[0], gn[1], gn[2]});
  const auto& exposure = track(s, EffectType::Exposure).keyframes;
  ASSERT_EQ(exposure.size(), 1u);  // +1 at (30, 0) deleted (redo after undo), -1 at (-30, 0) left
  expect_key(exposure[0], -30.0, 0.0, 45, {-1.0});
  expect_key(track(s, EffectType::Saturation).keyframes.at(0), -30.0, 0.0, 45, {0.5});
  const auto& contrast = track(s, EffectType::Contrast).keyframes;
  ASSERT_EQ(contrast.size(), 1u);  // the second placement replaced the first
  expect_key(contrast[0], -30.0, 0.0, 45, {2.0});
  const auto& vignette = track(s, EffectType::Vignette);
  ASSERT_EQ(vignette.keyframes.size(), 1u);
  expect_key(vignette.keyframes[0], -30.0, 0.0, 45, {60.0, 40.0});
  ASSERT_TRUE(vignette.interpolation.has_value());
  EXPECT_NEAR(vignette.interpolation->exponent, 1.5, 1e-9);
  // Deterministic: the same bytes again.
  const std::string first = slurp(o.sidecar_out);
  run_replay(o);
  EXPECT_EQ(slurp(o.sidecar_out), first);
}

TEST(ReplaySessions, MoveKeyframeSessionMovesRetimesAndReEditsIt) {
  const auto dir = test::temp_dir("replay_move");
  const ReplayOptions o = clip_replay(dir, "editor_move_keyframe.vdrec.jsonl");
  const io::Sidecar s = run_replay(o).sidecar;
  ASSERT_EQ(s.video.frames, test::kClipFrames);
  ASSERT_EQ(s.effects.size(), 1u);
  const auto& exposure = track(s, EffectType::Exposure);
  EXPECT_FALSE(exposure.interpolation.has_value());
  ASSERT_EQ(exposure.keyframes.size(), 2u);
  expect_key(exposure.keyframes[0], -20.0, 0.0, 0, {1.0});   // A untouched
  expect_key(exposure.keyframes[1], 55.0, 10.0, 30, {2.5});  // B moved, retimed, re-valued
  // The 0.5 set after deselecting went to the tool's chosen value: both keyframes kept theirs
  // (above). Deterministic:
  const std::string first = slurp(o.sidecar_out);
  run_replay(o);
  EXPECT_EQ(slurp(o.sidecar_out), first);
}

TEST(ReplaySessions, SidecarInIsTheStartingPoint) {
  const auto dir = test::temp_dir("replay_in");
  io::Sidecar start = test::empty_sidecar(1);
  start.effects.push_back({EffectType::Contrast, std::nullopt, {{{100.0, 0.0}, 0, {3.0}}}});
  io::write_sidecar(dir / "in.vdfx.json", start);
  ASSERT_EQ(run((kRecordings / "editor_place_exposure.vdrec.jsonl").string() + " --video " +
                kSunrise.string() + " --sidecar-in " + (dir / "in.vdfx.json").string() +
                " --sidecar-out " + (dir / "out.vdfx.json").string()),
            0);
  const io::Sidecar s = io::read_sidecar(dir / "out.vdfx.json");
  EXPECT_EQ(track(s, EffectType::Contrast).keyframes.size(), 1u);
  EXPECT_EQ(track(s, EffectType::Exposure).keyframes.size(), 2u);
}

TEST(ReplaySessions, MalformedRecordingExitsOneWithFileAndLine) {
  const auto dir = test::temp_dir("replay_bad");
  std::ifstream in(kRecordings / "editor_place_exposure.vdrec.jsonl");
  std::ofstream out(dir / "bad.vdrec.jsonl");
  std::string line;
  for (int n = 1; std::getline(in, line) && n <= 5; ++n)
    out << (n == 4 ? std::string("{\"t_ns\": oops}") : line) << "\n";
  out.close();
  std::string err;
  EXPECT_EQ(run((dir / "bad.vdrec.jsonl").string() + " --video " + kSunrise.string() +
                    " --sidecar-out " + (dir / "o.vdfx.json").string(),
                &err),
            1);
  EXPECT_NE(err.find("bad.vdrec.jsonl:4"), std::string::npos) << err;
  EXPECT_EQ(run("--video x --sidecar-out y"), 2);
}

TEST(ReplaySessions, DemoPlacesTheSunKeyframes) {
  const auto dir = test::temp_dir("replay_demo");
  ReplayOptions o;
  o.recording = kRecordings / "demo.vdrec.jsonl";
  o.video = kSunrise;
  o.sidecar_out = dir / "demo.vdfx.json";
  const io::Sidecar s = run_replay(o).sidecar;
  const auto& exposure = track(s, EffectType::Exposure).keyframes;
  ASSERT_EQ(exposure.size(), 2u);
  expect_key(exposure[0], 36.0, 8.0, 0, {-1.0});
  expect_key(exposure[1], -144.0, 0.0, 0, {1.0});
}

}  // namespace
}  // namespace vdfx::app
