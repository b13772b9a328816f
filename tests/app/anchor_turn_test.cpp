/// @file
/// @brief The world anchor through the commands, on a turning clip (docs/anchors.md): the demo
/// room's panorama turned 45 degrees a frame, the sidecar's camera given, an exposure keyframe on
/// the window in the world. At every frame the exposure `vdfx eval` prints at the window's
/// direction of the video frame, and the one `vdfx render` applies there (view and per-pixel
/// mode, CPU), stay within 0.05 stops of the keyframe; fixed in the picture (the video anchor) it
/// falls to neutral half a turn on. An anchor naming what the sidecar lacks is exit 1 with the
/// file and the pointer in every command that reads a sidecar.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "app/export/view_render.h"
#include "app/suggest/suggest.h"
#include "command_test_util.h"
#include "io/sidecar.h"
#include "io/sidecar_sets.h"
#include "tests/app/turning_clip_files.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;
using bench::kRoomWindow;
using bench::kWindowStops;

using testing::applied_stops;
using testing::kTurnFrames;
using Clip = testing::TurningClipFiles;

const Clip& turning_clip() {
  return testing::turning_clip_files();
}

effects::Direction window_at(std::int64_t f) {
  return testing::turning_window_at(f);
}

/// `vdfx eval` at the window's direction of every frame: the exposure each prints.
std::vector<double> eval_at_window(const fs::path& sidecar) {
  std::string args = "eval " + sidecar.string();
  for (int f = 0; f < kTurnFrames; ++f) {
    const effects::Direction d = window_at(f);
    std::ostringstream at;
    at.precision(17);
    at << " --at " << d.azimuth_deg << "," << d.altitude_deg << "," << f;
    args += at.str();
  }
  const testing::CommandResult r = testing::run_vdfx(args);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  std::vector<double> stops;
  std::istringstream lines(r.output);
  for (std::string line; std::getline(lines, line);) {
    const nlohmann::json j = nlohmann::json::parse(line);
    stops.push_back(j["effects"]["exposure"]["stops"].get<double>());
  }
  return stops;
}

TEST(AnchorTurn, EvalAtTheWindowStaysOnTheKeyframeWhileTheCameraTurns) {
  const Clip& c = turning_clip();
  const std::vector<double> world = eval_at_window(c.anchored), video = eval_at_window(c.fixed);
  ASSERT_EQ(world.size(), static_cast<std::size_t>(kTurnFrames));
  ASSERT_EQ(video.size(), static_cast<std::size_t>(kTurnFrames));
  for (int f = 0; f < kTurnFrames; ++f) EXPECT_NEAR(world[f], kWindowStops, 1e-9) << "frame " << f;
  EXPECT_NEAR(video[4], 0.0, 0.1) << "fixed in the picture, half a turn on: near the neutral key";
}

cv::Mat render_window(const fs::path& sidecar, int f, effects::RenderMode mode) {
  RenderRequest r;
  r.look = window_at(f);
  r.frame = f;
  r.hfov_deg = 20.0;
  r.width = r.height = 32;
  r.mode = mode;
  cv::Mat rgb8 = render_request(turning_clip().video, io::read_sidecar(sidecar), r), f32;
  rgb8.convertTo(f32, CV_32FC3);
  return f32;
}

TEST(AnchorTurn, RenderAppliesTheWindowsExposureAtEveryFrameInBothModes) {
  const Clip& c = turning_clip();
  for (const effects::RenderMode mode : {effects::RenderMode::View, effects::RenderMode::Pixel}) {
    double fixed_worst = 0.0;
    for (int f = 0; f < kTurnFrames; ++f) {
      SCOPED_TRACE("frame " + std::to_string(f) +
                   (mode == effects::RenderMode::View ? " view" : " pixel"));
      const cv::Mat plain = render_window(c.plain, f, mode);
      EXPECT_NEAR(applied_stops(render_window(c.anchored, f, mode), plain), kWindowStops, 0.05);
      fixed_worst =
          std::max(fixed_worst,
                   std::abs(applied_stops(render_window(c.fixed, f, mode), plain) - kWindowStops));
    }
    EXPECT_GT(fixed_worst, 1.0) << "the video anchor leaves the window";
  }
}

/// The pixels of an equirect image within a 16 x 8 patch around `d` (wrapping in azimuth).
cv::Mat patch(const cv::Mat& equirect, const effects::Direction& d) {
  const Eigen::Vector2d uv = effects::to_equirect_uv(d);
  const int cx = static_cast<int>(uv.x() * equirect.cols),
            cy = static_cast<int>(uv.y() * equirect.rows);
  cv::Mat out(8, 16, equirect.type());
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x)
      equirect.row(std::clamp(cy - 4 + y, 0, equirect.rows - 1))
          .col(((cx - 8 + x) % equirect.cols + equirect.cols) % equirect.cols)
          .copyTo(out.row(y).col(x));
  return out;
}

TEST(AnchorTurn, TheBakedExportDarkensTheWindowWhereverTheCameraHasTurned) {
  // Both keyframes are at frame 0, so the effect does not change in time: the export's grid cache
  // must still bake a new grid for every frame, whose rotation differs.
  const Clip& c = turning_clip();
  const fs::path out = c.dir / "baked.mp4";
  const testing::CommandResult r =
      testing::run_vdfx("export " + c.video.string() + " --sidecar " + c.anchored.string() +
                        " --baked " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (int f = 0; f < kTurnFrames; ++f) {
    SCOPED_TRACE("frame " + std::to_string(f));
    const cv::Mat in = load_equirect_frame(c.video, f, {}), baked = load_equirect_frame(out, f, {});
    const effects::Direction behind = bench::video_direction(
        {-149.0, -5.0}, bench::turning_yaw_deg(f, kTurnFrames, testing::kTurnDeg));
    EXPECT_NEAR(applied_stops(patch(baked, window_at(f)), patch(in, window_at(f))), kWindowStops,
                0.1);
    EXPECT_NEAR(applied_stops(patch(baked, behind), patch(in, behind)), 0.0, 0.1);
  }
}

TEST(AnchorTurn, AnExposureSuggestionForAWorldAnchoredEffectStaysOnTheRoom) {
  // The suggestion meters each sampled frame of the video; for a world-anchored exposure it fits
  // in the world, so the room keeps its exposure while the camera turns: at the window's
  // direction of the video frame it is the same at every sampled frame.
  const Clip& c = turning_clip();
  io::Sidecar sidecar = io::read_sidecar(c.anchored);
  sidecar.effects[0].keyframes.clear();
  suggest::SuggestRequest r;
  r.video = c.video;
  r.every = 2;
  r.tolerance = 0.1;
  const suggest::SuggestReport report = suggest::suggest_into(r, sidecar);
  ASSERT_EQ(report.effects.size(), 1u);
  EXPECT_LE(report.effects[0].fit.max_error, 0.1 + 1e-9);
  ASSERT_EQ(report.frames, (std::vector<std::int64_t>{0, 2, 4, 6, 7}));  // and the last
  EXPECT_EQ(sidecar.effects[0].anchor.kind, effects::Anchor::Kind::World);
  const effects::StackInterpolator stack = io::stack_of(sidecar);
  const double at_window = stack.evaluate(window_at(0), 0).exposure_stops;
  const effects::Direction behind = bench::video_direction({-149.0, -5.0}, 0.0);
  EXPECT_GT(std::abs(at_window - stack.evaluate(behind, 0).exposure_stops), 0.3)
      << "the window is metered apart from the rest of the room";
  for (const std::int64_t f : report.frames)
    EXPECT_NEAR(stack.evaluate(window_at(static_cast<int>(f)), f).exposure_stops, at_window, 0.2)
        << "frame " << f;
}

TEST(AnchorTurn, AnAnchorNamingNoTrackIsExitOneWithTheFileAndPointerInEveryCommand) {
  const Clip& c = turning_clip();
  const fs::path bad = c.dir / "bad.vdfx.json";
  std::string text = test_files::slurp(c.anchored);
  const std::string world = "\"anchor\": \"world\"";
  ASSERT_NE(text.find(world), std::string::npos) << text.substr(0, 800);
  text.replace(text.find(world), world.size(), "\"anchor\": \"track:nobody\"");
  testing::write_text(bad, text);
  const std::string v = c.video.string(), s = bad.string(), out = (c.dir / "o").string();
  const std::string rec = (c.dir / "short.vdrec.jsonl").string();
  testing::write_short_recording(rec);
  for (const std::string& args : {"validate " + s, "eval " + s + " --at 0,0,0",
                                  "render " + v + " --sidecar " + s +
                                      " --view 0,0 --fov 90 --size 16x8 --out " + out + ".png",
                                  "export " + v + " --sidecar " + s + " --baked " + out + ".mp4",
                                  "publish " + v + " --sidecar " + s + " --out " + out + "-site",
                                  "play " + v + " --sidecar " + s + " --frames 1 --hidden",
                                  "edit " + v + " --sidecar " + s + " --frames 1 --hidden",
                                  "replay " + rec + " --video " + v + " --sidecar-in " + s +
                                      " --sidecar-out " + out + ".vdfx.json"}) {
    const testing::CommandResult r = testing::run_vdfx_headless(args);
    EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(bad.string()), std::string::npos) << args << "\n" << r.output;
    EXPECT_NE(r.output.find("/effects/0/anchor"), std::string::npos) << args << "\n" << r.output;
  }
}

}  // namespace
}  // namespace vdfx::app
