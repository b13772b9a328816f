/// @file
/// @brief The command line as a script uses it: exit codes, messages that say where, and
/// output that parses (validate, eval, render on the CPU path, hmd).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "command_test_util.h"

namespace vdfx::app::testing {
namespace {

TEST(Commands, HelpAndUsageErrors) {
  EXPECT_EQ(run_vdfx("--help").exit_code, 0);
  EXPECT_EQ(run_vdfx("").exit_code, 2);
  const CommandResult unknown = run_vdfx("frobnicate");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.output.find("unknown command 'frobnicate'"), std::string::npos);
  for (const char* cmd : {"eval", "render", "validate", "hmd"})
    EXPECT_EQ(run_vdfx(std::string(cmd) + " --help").exit_code, 0) << cmd;
  EXPECT_EQ(run_vdfx("render --bogus-flag").exit_code, 2);
}

TEST(Commands, ValidateListsEveryProblemWithPointers) {
  const auto dir = test_dir();
  write_text(dir / "ok.vdfx.json", exposure_sidecar());
  const CommandResult ok = run_vdfx("validate " + (dir / "ok.vdfx.json").string());
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_NE(ok.output.find("valid (1 effects, 2 keyframes)"), std::string::npos) << ok.output;

  std::string broken = exposure_sidecar();
  broken.replace(broken.find("\"frame\": 0"), 10, "\"frame\": 7");      // beyond 1 frame
  broken.replace(broken.find("\"stops\": -1.0"), 13, "\"stops\": 99");  // out of range
  write_text(dir / "broken.vdfx.json", broken);
  const CommandResult bad = run_vdfx("validate " + (dir / "broken.vdfx.json").string());
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.output.find("broken.vdfx.json"), std::string::npos) << bad.output;
  EXPECT_NE(bad.output.find("/effects/0/keyframes/0/frame"), std::string::npos) << bad.output;
  EXPECT_NE(bad.output.find("/effects/0/keyframes/1/params/stops"), std::string::npos)
      << bad.output;
  EXPECT_NE(bad.output.find("2 problems"), std::string::npos) << bad.output;

  EXPECT_EQ(run_vdfx("validate " + (dir / "missing.vdfx.json").string()).exit_code, 1);
}

TEST(Commands, EvalPrintsParsableJsonPerView) {
  const auto dir = test_dir();
  write_text(dir / "s.vdfx.json", exposure_sidecar());
  const CommandResult r =
      run_vdfx("eval " + (dir / "s.vdfx.json").string() + " --at 90,0,0 --at -90,0,0 --at 0,0,0");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::istringstream lines(r.output);
  std::string line;
  std::vector<nlohmann::json> objects;
  while (std::getline(lines, line)) objects.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(objects.size(), 3u);
  // Keyframes are reproduced, and halfway between them the symmetric layout gives 0.
  EXPECT_NEAR(objects[0]["effects"]["exposure"]["stops"].get<double>(), 1.0, 1e-9);
  EXPECT_NEAR(objects[1]["effects"]["exposure"]["stops"].get<double>(), -1.0, 1e-9);
  EXPECT_NEAR(objects[2]["effects"]["exposure"]["stops"].get<double>(), 0.0, 1e-9);
  EXPECT_TRUE(objects[0]["effects"]["exposure"]["active"].get<bool>());
  EXPECT_FALSE(objects[0]["effects"]["blur"]["active"].get<bool>());
  EXPECT_EQ(objects[0]["effects"]["tint"]["gain"].size(), 3u);
  EXPECT_DOUBLE_EQ(objects[1]["at"]["azimuth_deg"].get<double>(), -90.0);

  EXPECT_EQ(run_vdfx("eval " + (dir / "s.vdfx.json").string() + " --at 0,0").exit_code, 2);
  const CommandResult beyond = run_vdfx("eval " + (dir / "s.vdfx.json").string() + " --at 0,0,5");
  EXPECT_EQ(beyond.exit_code, 1);
  EXPECT_NE(beyond.output.find("frame 5"), std::string::npos) << beyond.output;
}

TEST(Commands, EvalManyViewsPrintsThemInOrderAndABadViewWinsOverABadSidecar) {
  // From 64 views eval reads the views beside the sidecar and evaluates the second half on a
  // second thread: the lines still follow the options, and the errors come as read in turn.
  const auto dir = test_dir();
  write_text(dir / "s.vdfx.json", exposure_sidecar());
  std::string views;
  for (int i = 0; i < 150; ++i) views += " --at " + std::to_string(-149 + 2 * i) + ",0,0";
  const CommandResult r = run_vdfx("eval " + (dir / "s.vdfx.json").string() + views);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::istringstream lines(r.output);
  std::string line;
  int n = 0;
  while (std::getline(lines, line)) {
    const nlohmann::json j = nlohmann::json::parse(line);
    ASSERT_DOUBLE_EQ(j["at"]["azimuth_deg"].get<double>(), -149.0 + 2 * n) << n;
    ++n;
  }
  EXPECT_EQ(n, 150);

  const std::string missing = (dir / "missing.vdfx.json").string();
  const CommandResult bad_view = run_vdfx("eval " + missing + views + " --at 0,0,x");
  EXPECT_EQ(bad_view.exit_code, 2) << bad_view.output;
  EXPECT_NE(bad_view.output.find("'0,0,x'"), std::string::npos) << bad_view.output;
  const CommandResult bad_file = run_vdfx("eval " + missing + views);
  EXPECT_EQ(bad_file.exit_code, 1) << bad_file.output;
  EXPECT_NE(bad_file.output.find("missing.vdfx.json"), std::string::npos) << bad_file.output;
}

TEST(Commands, RenderViewAndPixelModes) {
  const auto dir = test_dir();
  write_test_panorama(dir);
  write_text(dir / "s.vdfx.json", exposure_sidecar());
  const std::string common = "--frame 0 --fov 90 --size 160x90 ";
  const cv::Mat bright = render(dir, common + "--view 90,0", "bright.png");
  const cv::Mat dark = render(dir, common + "--view -90,0", "dark.png");
  const cv::Mat pixel = render(dir, common + "--view 0,0 --mode pixel", "pixel.png");
  const cv::Mat view = render(dir, common + "--view 0,0 --mode view", "view.png");
  ASSERT_FALSE(bright.empty());
  ASSERT_EQ(bright.size(), cv::Size(160, 90));
  // Looking at the +1 stop keyframe is brighter than looking at the -1 stop one.
  EXPECT_GT(cv::mean(bright)[1], 1.5 * cv::mean(dark)[1]);
  // Pixel mode grades exposure across the view (left half towards -90 darker than right half);
  // view mode applies the centre's parameters (0 stops) to the whole view.
  const cv::Rect left(0, 0, 80, 90), right(80, 0, 80, 90);
  const double pixel_ratio = cv::mean(pixel(right))[1] / cv::mean(pixel(left))[1];
  const double view_ratio = cv::mean(view(right))[1] / cv::mean(view(left))[1];
  EXPECT_GT(pixel_ratio, view_ratio * 1.3) << pixel_ratio << " vs " << view_ratio;
}

TEST(Commands, RenderHmdEyeWithCpuPredistortion) {
  const auto dir = test_dir();
  write_test_panorama(dir, 8);  // a fine grid, so displacement shows
  write_text(dir / "s.vdfx.json", exposure_sidecar());
  const std::string common = "--view 0,0 --hmd cardboard-v1 --eye left --size 96x108 ";
  const cv::Mat plain = render(dir, common + "--distort none", "plain.png");
  const cv::Mat exact = render(dir, common + "--distort pixel", "pixel.png");
  const cv::Mat mesh = render(dir, common + "--distort mesh:33", "mesh.png");
  ASSERT_EQ(plain.size(), cv::Size(96, 108));
  cv::Mat diff;
  cv::absdiff(plain, exact, diff);
  // The lens centre is a fixed point of the pre-distortion and displacement grows with the
  // radius: the centre stays put while the border band moves.
  const double centre = cv::mean(diff(cv::Rect(44, 50, 8, 8)))[1];
  const double border = cv::mean(diff(cv::Rect(0, 0, 96, 12)))[1];
  EXPECT_LT(centre, 0.5) << "centre " << centre;
  EXPECT_GT(border, 5.0) << "border " << border;
  cv::absdiff(exact, mesh, diff);
  EXPECT_LT(cv::mean(diff)[1], 2.0);  // a 33x33 mesh is close to the exact mapping

  const CommandResult no_hmd = run_vdfx(
      "render " + (dir / "pano.png").string() + " --sidecar " + (dir / "s.vdfx.json").string() +
      " --view 0,0 --fov 90 --size 8x8 --distort pixel --out " + (dir / "x.png").string());
  EXPECT_EQ(no_hmd.exit_code, 2);
  const CommandResult bad_hmd = run_vdfx(
      "render " + (dir / "pano.png").string() + " --sidecar " + (dir / "s.vdfx.json").string() +
      " --view 0,0 --hmd no-such-headset --out " + (dir / "x.png").string());
  EXPECT_EQ(bad_hmd.exit_code, 1) << bad_hmd.output;
}

TEST(Commands, RenderBlurAndBakeOptionsAreChecked) {
  const auto dir = test_dir();
  write_test_panorama(dir);
  write_text(dir / "s.vdfx.json", exposure_sidecar());
  const std::string base =
      "render " + (dir / "pano.png").string() + " --sidecar " + (dir / "s.vdfx.json").string() +
      " --view 0,0 --fov 90 --size 8x8 --out " + (dir / "x.png").string() + " ";
  const struct {
    const char* args;
    const char* message;  //!< must appear in the output
  } cases[] = {{"--gpu --blur gaussian", "--blur: 'gaussian': expected exact or pyramid"},
               {"--blur pyramid", "pyramid needs --gpu"},
               {"--gpu --mode pixel --bake 0x8", "--bake: '0x8'"}};
  for (const auto& c : cases) {
    // Rejected before any GL context opens, so no display is needed.
    const CommandResult r = run_vdfx(base + c.args, "env -u DISPLAY ");
    EXPECT_EQ(r.exit_code, 2) << c.args << ": " << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << ": " << r.output;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

TEST(Commands, RenderBadInputSaysWhere) {
  const auto dir = test_dir();
  write_test_panorama(dir);
  write_text(dir / "s.vdfx.json", exposure_sidecar());
  const CommandResult missing = run_vdfx(
      "render " + (dir / "nope.mp4").string() + " --sidecar " + (dir / "s.vdfx.json").string() +
      " --view 0,0 --fov 90 --size 8x8 --out " + (dir / "x.png").string());
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.output.find("nope.mp4"), std::string::npos) << missing.output;
  const CommandResult frame = run_vdfx(
      "render " + (dir / "pano.png").string() + " --sidecar " + (dir / "s.vdfx.json").string() +
      " --view 0,0 --frame 3 --fov 90 --size 8x8 --out " + (dir / "x.png").string());
  EXPECT_EQ(frame.exit_code, 1);
  EXPECT_NE(frame.output.find("frame 3"), std::string::npos) << frame.output;
  write_text(dir / "corrupt.png", "not a png at all");
  const CommandResult corrupt = run_vdfx(
      "render " + (dir / "corrupt.png").string() + " --sidecar " + (dir / "s.vdfx.json").string() +
      " --view 0,0 --fov 90 --size 8x8 --out " + (dir / "x.png").string());
  EXPECT_EQ(corrupt.exit_code, 1);
  EXPECT_NE(corrupt.output.find("corrupt.png"), std::string::npos) << corrupt.output;
}

}  // namespace
}  // namespace vdfx::app::testing
