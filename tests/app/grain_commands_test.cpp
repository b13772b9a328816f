/// @file
/// @brief Grain through the command line and the app (CPU paths): `vdfx render` draws the
/// sidecar's shader grain and nothing at intensity 0, refuses a volumetric grain without --gpu
/// (usage, exit 2), `vdfx eval` prints each grain's intensity and size, `vdfx validate` counts
/// them, the editor's document keeps them, the player lays them out once per frame.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "app/editor/document.h"
#include "app/window/player.h"
#include "command_test_util.h"
#include "io/sidecar_validate.h"

namespace vdfx::app::testing {
namespace {

std::string grain_entry(const std::string& style, double intensity, double size, int seed = 4) {
  std::ostringstream s;
  s << R"(,
    {"type": "grain", "style": ")"
    << style << R"(", "seed": )" << seed << R"(,
     "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 0, "params": {"intensity": )"
    << intensity << R"(, "size": )" << size << "}}]}";
  return s.str();
}

TEST(GrainCommands, RenderDrawsShaderGrainAndNothingAtIntensityZero) {
  const auto dir = test_dir();
  write_test_panorama(dir);
  // 30 degrees over 200 px and grain of size 2 (8 mrad cells, 3 px): resolved, not band-limited.
  const std::string common = "--view 4,2 --fov 30 --size 200x120 ";
  write_text(dir / "s.vdfx.json", exposure_sidecar());
  const cv::Mat plain = render(dir, common, "plain.png");
  for (const char* style : {"surface", "headset"}) {
    write_text(dir / "s.vdfx.json", exposure_sidecar(grain_entry(style, 0.0, 2.0)));
    EXPECT_EQ(cv::norm(plain, render(dir, common, "off.png"), cv::NORM_INF), 0.0) << style;
    write_text(dir / "s.vdfx.json", exposure_sidecar(grain_entry(style, 0.8, 2.0)));
    const cv::Mat on = render(dir, common, "on.png");
    EXPECT_GT(mean_abs_diff(on, plain), 3.0) << style;
    // The same sidecar renders the same grain (seed, frame and display time fix it).
    EXPECT_EQ(cv::norm(on, render(dir, common, "again.png"), cv::NORM_INF), 0.0) << style;
    // Another seed, another pattern of about the same strength.
    write_text(dir / "s.vdfx.json", exposure_sidecar(grain_entry(style, 0.8, 2.0, 5)));
    const cv::Mat other = render(dir, common, "other.png");
    EXPECT_GT(mean_abs_diff(on, other), 2.0) << style;
  }
}

TEST(GrainCommands, VolumetricGrainWithoutGpuIsAUsageError) {
  const auto dir = test_dir();
  write_test_panorama(dir);
  write_text(dir / "s.vdfx.json", exposure_sidecar(grain_entry("surface", 0.5, 1.0) +
                                                   grain_entry("free_cloud", 0.5, 1.0)));
  const CommandResult r = run_vdfx(
      "render " + (dir / "pano.png").string() + " --sidecar " + (dir / "s.vdfx.json").string() +
      " --view 0,0 --fov 90 --size 64x48 --out " + (dir / "x.png").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(
      r.output.find("grain #2 (free_cloud) is volumetric and renders on the GPU only: add --gpu"),
      std::string::npos)
      << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

TEST(GrainCommands, EvalPrintsEachGrainAndValidateCountsThem) {
  const auto dir = test_dir();
  write_text(dir / "s.vdfx.json", exposure_sidecar(grain_entry("object_cloud", 0.25, 2.0) +
                                                   grain_entry("headset", 1.0, 0.5)));
  const CommandResult e = run_vdfx("eval " + (dir / "s.vdfx.json").string() + " --at 0,0,0");
  ASSERT_EQ(e.exit_code, 0) << e.output;
  const auto j = nlohmann::json::parse(e.output);
  ASSERT_EQ(j["grains"].size(), 2u);
  EXPECT_EQ(j["grains"][0]["style"], "object_cloud");
  EXPECT_DOUBLE_EQ(j["grains"][0]["intensity"].get<double>(), 0.25);
  EXPECT_DOUBLE_EQ(j["grains"][0]["size"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(j["grains"][1]["size"].get<double>(), 0.5);
  const CommandResult v = run_vdfx("validate " + (dir / "s.vdfx.json").string());
  EXPECT_EQ(v.exit_code, 0);
  EXPECT_NE(v.output.find("valid (3 effects, 4 keyframes)"), std::string::npos) << v.output;
}

TEST(GrainCommands, TheEditorsDocumentKeepsGrainOnSave) {
  const io::SidecarReport r = io::validate_sidecar_text(
      exposure_sidecar(grain_entry("free_cloud", 0.3, 1.0) + grain_entry("surface", 0.7, 2.0)),
      "s");
  ASSERT_TRUE(r.ok()) << r.to_string();
  const Document doc(*r.sidecar);
  EXPECT_EQ(doc.sidecar().grains, r.sidecar->grains);
}

TEST(GrainCommands, PlayerLaysOutItsGrainOncePerFrameFromTheHead) {
  const io::SidecarReport r = io::validate_sidecar_text(
      exposure_sidecar(grain_entry("surface", 0.6, 1.0) + grain_entry("headset", 0.0, 1.0)), "s");
  ASSERT_TRUE(r.ok());
  io::VideoProperties props;
  props.fps = io::Rational{30, 1};
  props.frames = 1;
  Player player(*r.sidecar, props);
  xr::Pose head;
  head.position = {0.1, 1.6, 0.0};
  const auto layers = player.grains(head, 25'000'000, 0);
  ASSERT_EQ(layers.size(), 1u);  // the headset grain is at intensity 0: no layer
  EXPECT_EQ(layers[0].style, effects::GrainStyle::Surface);
  EXPECT_EQ(layers[0].refresh, 1);  // 25 ms with the default 20 ms refresh
  EXPECT_EQ(layers[0].head.position, Eigen::Vector3d(0.1, 1.6, 0.0));
  EXPECT_DOUBLE_EQ(layers[0].params.intensity, 0.6);
}

}  // namespace
}  // namespace vdfx::app::testing
