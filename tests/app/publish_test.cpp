/// @file
/// @brief `vdfx publish` (docs/publish.md): the folder it writes, what it refuses and with which
/// exit code, and that an existing folder is replaced only whole. The page itself is tested in a
/// real browser (tests/publish/page_test.cjs).
#include <gtest/gtest.h>

#include <array>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "publish_test_util.h"

namespace vdfx::app::testing {
namespace {

namespace fs = std::filesystem;

using test_files::slurp;

/// player.json's video.eyes.<eye> as {x, y, width, height}.
std::array<int, 4> eye_rect_of(const nlohmann::json& manifest, const char* eye) {
  const nlohmann::json& r = manifest["video"]["eyes"][eye];
  return {r["x"].get<int>(), r["y"].get<int>(), r["width"].get<int>(), r["height"].get<int>()};
}

TEST(Publish, WritesThePageTheModuleTheShadersTheVideoAndTheSidecar) {
  if (!module_built()) GTEST_SKIP() << kNoModule;
  const Fixture f = make_fixture();
  const fs::path out = f.dir / "site";
  const CommandResult r = run_vdfx_headless(publish_args(f, out, "--title 'Dawn & <dusk>'"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::set<std::string> expected = {"index.html",
                                          "player.js",
                                          "renderer.js",
                                          "controls.js",
                                          "xr.js",
                                          "layers.js",
                                          "flare.js",
                                          "grain.js",
                                          "stabilize.js",
                                          "vdfx_player.js",
                                          "vdfx_player.wasm",
                                          "player.json",
                                          "video.mp4",
                                          "sidecar.vdfx.json",
                                          "shaders/fullscreen.vert",
                                          "shaders/video.frag",
                                          "shaders/mip_level.frag",
                                          "shaders/blur_1d.frag",
                                          "shaders/stack.frag",
                                          "shaders/stack_blur.frag",
                                          "shaders/flare.vert",
                                          "shaders/flare.frag",
                                          "shaders/grain.frag"};
  EXPECT_EQ(listing(out), expected);
  // The video and the sidecar are copied byte for byte, under fixed names.
  EXPECT_EQ(slurp(out / "video.mp4"), slurp(f.clip));
  EXPECT_EQ(slurp(out / "sidecar.vdfx.json"), slurp(f.sidecar));
  EXPECT_NE(slurp(out / "index.html").find("<title>Dawn &amp; &lt;dusk&gt;</title>"),
            std::string::npos);
  const auto manifest = nlohmann::json::parse(slurp(out / "player.json"));
  EXPECT_EQ(manifest["format"], "vdfx.publish");
  EXPECT_EQ(manifest["sidecar"], "sidecar.vdfx.json");
  EXPECT_EQ(manifest["sidecar_name"], "clip.vdfx.json");
  EXPECT_EQ(manifest["video"]["file"], "video.mp4");
  EXPECT_EQ(manifest["video"]["name"], "clip.mp4");
  EXPECT_EQ(manifest["video"]["codec"], "h264");
  EXPECT_EQ(manifest["video"]["frames"], kFrames);
  EXPECT_EQ(manifest["video"]["layout"], "mono");
  EXPECT_EQ(manifest["video"]["coverage"], 360);
  EXPECT_EQ(manifest["video"]["max_anisotropy"], 16.0);  // effects/pixel_footprint.h's default
  EXPECT_EQ(eye_rect_of(manifest, "left"), (std::array<int, 4>{0, 0, kW, kH}));
  EXPECT_EQ(eye_rect_of(manifest, "right"), (std::array<int, 4>{0, 0, kW, kH}));
  // Blur (bit 0), exposure (2) and saturation (3) have keyframes.
  EXPECT_EQ(manifest["stack_mask"], 1 + 4 + 8);
  // GLSL ES 3.00 with highp, the effects of the sidecar compiled in.
  const std::string stack = slurp(out / "shaders/stack_blur.frag");
  EXPECT_TRUE(stack.starts_with("#version 300 es\nprecision highp float;")) << stack.substr(0, 80);
  EXPECT_NE(stack.find("#define HAS_EXPOSURE 1"), std::string::npos);
  EXPECT_NE(stack.find("#define HAS_TINT 0"), std::string::npos);
  EXPECT_NE(stack.find("#define BLUR_MODE 1"), std::string::npos);
  EXPECT_TRUE(leftovers(out).empty());
}

// A video and a sidecar named with what a URL cannot hold as it is ('#', '?', '%', spaces,
// non-ASCII letters, a leading dash) are published under fixed names; their own names are the
// title and player.json's names (the page builds its URLs from the fixed ones).
TEST(Publish, FilesNamedWithUrlCharactersArePublishedUnderFixedNames) {
  if (!module_built()) GTEST_SKIP() << kNoModule;
  Fixture f = make_fixture();
  const std::string video_name = "-take#2 50%? \xc3\xa9t\xc3\xa9.MP4";
  const std::string sidecar_name = "-s#1 100%?.vdfx.json";
  fs::rename(f.clip, f.dir / video_name);
  fs::rename(f.sidecar, f.dir / sidecar_name);
  const fs::path out = f.dir / "site";
  // Run in the folder, the video named as it is: "--" before it, since it starts with a dash.
  const CommandResult r = run_command("cd " + f.dir.string() + " && env -u DISPLAY timeout 60 " +
                                      VDFX_BINARY + " publish --sidecar '" + sidecar_name +
                                      "' --out site -- '" + video_name + "' 2>&1");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(slurp(out / "video.mp4"), slurp(f.dir / video_name));
  EXPECT_EQ(slurp(out / "sidecar.vdfx.json"), slurp(f.dir / sidecar_name));
  const auto m = nlohmann::json::parse(slurp(out / "player.json"));
  EXPECT_EQ(m["video"]["file"], "video.mp4");
  EXPECT_EQ(m["video"]["name"], video_name);
  EXPECT_EQ(m["sidecar"], "sidecar.vdfx.json");
  EXPECT_EQ(m["sidecar_name"], sidecar_name);
  EXPECT_EQ(m["title"], video_name);
  EXPECT_NE(slurp(out / "index.html").find("<title>" + video_name + "</title>"), std::string::npos);
}

// The page draws flares and the shader grain styles; a volumetric grain is named as left out.
// An auto light is tracked by publish over every frame into lights.json (docs/publish.md).
TEST(Publish, TracksAutoLightsAndNamesTheVolumetricGrainThePageDoesNotDraw) {
  if (!module_built()) GTEST_SKIP() << kNoModule;
  const Fixture f = make_fixture();
  write_text(f.sidecar, R"({"format": "vdfx.sidecar", "version": 1,
    "video": {"path": "clip.mp4", "fps": 24.0, "frames": 12, "width": 128, "height": 64},
    "interpolation": {"exponent": 1.0, "time_scale": 1.0},
    "effects": [{"type": "grain", "style": "headset", "seed": 7, "settings": {"refresh_ms": 40.0},
      "keyframes": [{"azimuth_deg": 20.0, "altitude_deg": 10.0, "frame": 5,
                     "params": {"intensity": 0.5, "size": 1.0}}]},
      {"type": "grain", "style": "free_cloud", "seed": 3,
       "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 0,
                      "params": {"intensity": 0.5, "size": 1.0}}]},
      {"type": "flare", "style": "directional", "light": "auto",
       "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 0,
                      "params": {"intensity": 1.0}}]}]})");
  const fs::path out = f.dir / "site";
  const CommandResult r = run_vdfx_headless(publish_args(f, out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("does not draw grain #2 (free_cloud)"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("grain #1"), std::string::npos) << r.output;
  const auto manifest = nlohmann::json::parse(slurp(out / "player.json"));
  EXPECT_EQ(manifest["left_out"], nlohmann::json::array({"grain #2 (free_cloud)"}));
  EXPECT_EQ(manifest["stack_mask"], 0);
  EXPECT_EQ(manifest["lights"], "lights.json");
  const auto lights = nlohmann::json::parse(slurp(out / "lights.json"));
  EXPECT_EQ(lights["format"], "vdfx.lights");
  EXPECT_EQ(lights["frames"], kFrames);
  ASSERT_EQ(lights["lights"].size(), static_cast<std::size_t>(kFrames));
  // Every entry a direction or null (the fixture's clip has no sun: what the tracker found).
  for (const auto& l : lights["lights"])
    EXPECT_TRUE(l.is_null() || (l.contains("azimuth_deg") && l.contains("altitude_deg"))) << l;
}

// The page shows every layout vdfx reads (docs/stereo.md): the sidecar's record of a VR180
// side-by-side video reaches player.json with each eye's rectangle; nothing is refused.
TEST(Publish, AStereoVr180VideoIsPublishedWithItsLayoutInTheManifest) {
  if (!module_built()) GTEST_SKIP() << kNoModule;
  const Fixture f = make_fixture();
  write_text(f.sidecar, R"({"format": "vdfx.sidecar", "version": 1,
    "video": {"path": "clip.mp4", "fps": 24.0, "frames": 12, "width": 128, "height": 64,
              "layout": "left-right", "coverage": 180},
    "interpolation": {"exponent": 1.0, "time_scale": 1.0}, "effects": []})");
  const fs::path out = f.dir / "site";
  const CommandResult r = run_vdfx_headless(publish_args(f, out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("video h264, left-right 180"), std::string::npos) << r.output;
  const auto m = nlohmann::json::parse(slurp(out / "player.json"));
  EXPECT_EQ(m["video"]["layout"], "left-right");
  EXPECT_EQ(m["video"]["coverage"], 180);
  EXPECT_EQ(m["video"]["coverage_edge_deg"], 2.0);
  EXPECT_EQ(eye_rect_of(m, "left"), (std::array<int, 4>{0, 0, 64, 64}));
  EXPECT_EQ(eye_rect_of(m, "right"), (std::array<int, 4>{64, 0, 64, 64}));
  EXPECT_TRUE(leftovers(out).empty());
}

// --layout and --coverage override the stream's tags and the sidecar, as on every command that
// reads a video; a layout that does not split the frame is exit 1 naming the video and the
// option, and nothing is written.
TEST(Publish, LayoutOptionsReachTheManifestAndABadSplitIsRefused) {
  if (!module_built()) GTEST_SKIP() << kNoModule;
  const Fixture f = make_fixture();
  const fs::path out = f.dir / "site";
  CommandResult r = run_vdfx_headless(publish_args(f, out, "--layout right-left --coverage 360"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  auto m = nlohmann::json::parse(slurp(out / "player.json"));
  EXPECT_EQ(m["video"]["layout"], "right-left");
  EXPECT_EQ(m["video"]["coverage"], 360);
  EXPECT_EQ(eye_rect_of(m, "left"), (std::array<int, 4>{64, 0, 64, 64}));
  EXPECT_EQ(eye_rect_of(m, "right"), (std::array<int, 4>{0, 0, 64, 64}));

  // A still of odd height (H.264 has no odd 4:2:0 frames) split top-bottom.
  Fixture odd = f;
  odd.clip = f.dir / "odd.png";
  ASSERT_TRUE(cv::imwrite(odd.clip.string(), cv::Mat(65, 128, CV_8UC3, cv::Scalar(90, 120, 150))));
  const fs::path out2 = f.dir / "site2";
  r = run_vdfx_headless(publish_args(odd, out2, "--layout top-bottom --transcode h264"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("--layout: top-bottom needs an even frame height"), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(out2));
  EXPECT_EQ(run_vdfx_headless(publish_args(f, out, "--layout stacked")).exit_code, 2);
}

TEST(Publish, ABrokenSidecarIsExit1WithValidatesOwnMessageAndWritesNothing) {
  const Fixture f = make_fixture();
  write_text(f.sidecar, R"({"format": "vdfx.sidecar", "version": 1,
    "video": {"path": "clip.mp4", "fps": -24.0, "frames": 12, "width": 128, "height": 64},
    "effects": [{"type": "glow", "keyframes": []}]})");
  const fs::path out = f.dir / "site";
  const CommandResult r = run_vdfx_headless(publish_args(f, out));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  const CommandResult v = run_vdfx_headless("validate " + f.sidecar.string());
  ASSERT_EQ(v.exit_code, 1);
  // Every line validate prints, in publish's message.
  std::istringstream lines(v.output);
  for (std::string line; std::getline(lines, line);)
    EXPECT_NE(r.output.find(line), std::string::npos) << line << "\n---\n" << r.output;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_TRUE(leftovers(out).empty());
}

/// A clip in a codec no browser plays (MPEG-4 Part 2: the case of ProRes and DNxHR).
fs::path write_mpeg4_clip(const fs::path& dir) {
  fs::create_directories(dir);
  test_media::ClipSpec c;
  c.width = kW;
  c.height = kH;
  c.frames = 6;
  c.codec = "mpeg4";
  c.options.clear();
  c.max_b_frames = 0;
  c.frame = [](int i) { return test_media::smooth_frame(i, kW, kH); };
  return test_media::write_clip(dir / "clip.mp4", c);
}

TEST(Publish, ACodecBrowsersDoNotPlayIsRefusedNamingItAndTheOptionThenTranscoded) {
  if (!module_built()) GTEST_SKIP() << kNoModule;
  Fixture f = make_fixture();
  f.clip = write_mpeg4_clip(f.dir / "mpeg4");
  const fs::path out = f.dir / "site";
  const CommandResult r = run_vdfx_headless(publish_args(f, out));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("codec mpeg4"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--transcode h264"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));

  // A stereo layout given on the command line stays stereo through the transcode (the baked
  // export tags it st3d), so the published video says what player.json says.
  const CommandResult t =
      run_vdfx_headless(publish_args(f, out, "--transcode h264 --layout top-bottom"));
  ASSERT_EQ(t.exit_code, 0) << t.output;
  const auto manifest = nlohmann::json::parse(slurp(out / "player.json"));
  EXPECT_EQ(manifest["video"]["codec"], "h264");
  EXPECT_EQ(manifest["video"]["frames"], 6);
  EXPECT_EQ(manifest["video"]["layout"], "top-bottom");
  auto decoder = io::open_frame_decoder(out / "video.mp4", {});
  EXPECT_EQ(decoder->properties().codec, "h264");
  EXPECT_EQ(decoder->properties().stereo_tags.mode, effects::StereoMode::TopBottom);
  EXPECT_TRUE(leftovers(out).empty());
}

TEST(Publish, TranscodesToVp9) {
  if (!module_built()) GTEST_SKIP() << kNoModule;
  Fixture f = make_fixture();
  f.clip = write_mpeg4_clip(f.dir / "mpeg4");
  const fs::path out = f.dir / "site";
  const CommandResult t = run_vdfx_headless(publish_args(f, out, "--transcode vp9"));
  ASSERT_EQ(t.exit_code, 0) << t.output;
  EXPECT_EQ(io::open_frame_decoder(out / "video.mp4", {})->properties().codec, "vp9");
}

TEST(Publish, RefusesAnOutThatIsAnInputAFileOrAFolderItDidNotWrite) {
  const Fixture f = make_fixture();
  const std::string before = slurp(f.clip);
  CommandResult r = run_vdfx_headless(publish_args(f, f.clip));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(slurp(f.clip), before);

  const fs::path file = f.dir / "notes.txt";
  write_text(file, "mine");
  r = run_vdfx_headless(publish_args(f, file));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("this is a file"), std::string::npos) << r.output;

  const fs::path mine = f.dir / "photos";
  fs::create_directory(mine);
  write_text(mine / "a.jpg", "x");
  r = run_vdfx_headless(publish_args(f, mine));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("not one vdfx publish wrote"), std::string::npos) << r.output;
  EXPECT_EQ(listing(mine), std::set<std::string>{"a.jpg"});
  EXPECT_EQ(slurp(file), "mine");
}

TEST(Publish, WithoutTheModuleItIsAnInternalErrorNamingIt) {
  if (module_built()) GTEST_SKIP() << "the module is built";
  const Fixture f = make_fixture();
  const CommandResult r = run_vdfx_headless(publish_args(f, f.dir / "site"));
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("vdfx_player.wasm"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(f.dir / "site"));
}

TEST(Publish, UsageErrorsAreExit2) {
  const Fixture f = make_fixture();
  EXPECT_EQ(run_vdfx_headless("publish " + f.clip.string() + " --sidecar " + f.sidecar.string())
                .exit_code,
            2);
  EXPECT_EQ(run_vdfx_headless(publish_args(f, f.dir / "site", "--transcode av1")).exit_code, 2);
}

TEST(Publish, AnExistingFolderIsReplacedWholeAndKeptWholeWhenPublishFails) {
  if (!module_built()) GTEST_SKIP() << kNoModule;
  const Fixture f = make_fixture();
  const fs::path out = f.dir / "site";
  ASSERT_EQ(run_vdfx_headless(publish_args(f, out, "--title First")).exit_code, 0);
  write_text(out / "stray.txt", "from before");
  const std::set<std::string> first = listing(out);

  // A failing publish (the sidecar broken since) leaves the old folder exactly as it was.
  const std::string good = slurp(f.sidecar);
  write_text(f.sidecar, "{");
  EXPECT_EQ(run_vdfx_headless(publish_args(f, out, "--title Second")).exit_code, 1);
  EXPECT_EQ(listing(out), first);
  EXPECT_NE(slurp(out / "index.html").find("<title>First</title>"), std::string::npos);

  // A folder a killed publish left beside OUT (its process is gone) is removed by the next.
  const fs::path stale = out.parent_path() / ".site.publish-999999999";
  fs::create_directory(stale);
  write_text(stale / "index.html", "half");

  // A successful one replaces it whole: the new title, and nothing of the old folder left.
  write_text(f.sidecar, good);
  const CommandResult r = run_vdfx_headless(publish_args(f, out, "--title Second"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(slurp(out / "index.html").find("<title>Second</title>"), std::string::npos);
  EXPECT_FALSE(fs::exists(out / "stray.txt"));
  EXPECT_TRUE(leftovers(out).empty());
}

}  // namespace
}  // namespace vdfx::app::testing
