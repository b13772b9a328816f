/// @file
/// @brief Flares through the command line and the app (CPU paths): `vdfx render` draws the
/// sidecar's flares where their light is (fixed and auto), `vdfx eval` prints their intensity,
/// `vdfx validate` counts them, the editor's document keeps them, the player lays them out.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "app/editor/document.h"
#include "app/window/player.h"
#include "command_test_util.h"
#include "effects/view_camera.h"
#include "io/sidecar_validate.h"
#include "tests/image_centroid.h"
#include "xr/headset/eye_views.h"

namespace vdfx::app::testing {
namespace {

/// The test panorama's sidecar with one more flare entry (no rings unless asked: the tests
/// measure where the glare is).
std::string flare_sidecar(const std::string& style, const std::string& light, double intensity,
                          int rings = 0) {
  std::ostringstream s;
  s << R"(,
    {"type": "flare", "style": ")"
    << style << R"(", "light": )" << light << R"(, "settings": {"rings": )" << rings << R"(},
     "keyframes": [{"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 0, "params": {"intensity": )"
    << intensity << "}}]}";
  return exposure_sidecar(s.str());
}

/// Centroid (x, y) of how much brighter `with` is than `without` (green channel, which the test
/// panorama keeps at 128 so a weak flare never clips), above half its largest difference.
cv::Point2d brightening_centroid(const cv::Mat& with, const cv::Mat& without) {
  cv::Mat a, b, d;
  with.convertTo(a, CV_32F);
  without.convertTo(b, CV_32F);
  cv::extractChannel(a - b, d, 1);
  const Eigen::Vector2d c = test_images::half_max_centroid(d);
  return {c.x(), c.y()};
}

TEST(FlareCommands, RenderDrawsTheGlareOnTheLightAndNothingAtIntensityZero) {
  const auto dir = test_dir();
  write_test_panorama(dir);
  const std::string common = "--view 4,2 --fov 90 --size 200x120 ";
  write_text(dir / "s.vdfx.json", exposure_sidecar());
  const cv::Mat plain = render(dir, common, "plain.png");
  write_text(dir / "s.vdfx.json",
             flare_sidecar("directional", R"({"azimuth_deg": 10.0, "altitude_deg": 6.0})", 0.0));
  const cv::Mat off = render(dir, common, "off.png");
  EXPECT_EQ(cv::norm(plain, off, cv::NORM_INF), 0.0);  // intensity 0: not drawn at all
  write_text(dir / "s.vdfx.json",
             flare_sidecar("directional", R"({"azimuth_deg": 10.0, "altitude_deg": 6.0})", 0.3));
  const cv::Mat on = render(dir, common, "on.png");
  const auto cam = effects::ViewCamera::from_horizontal_fov({{4.0, 2.0}, 0.0}, 90.0, 200, 120);
  const Eigen::Vector2d light = *cam.project(effects::to_unit({10.0, 6.0}));
  const cv::Point2d c = brightening_centroid(on, plain);
  EXPECT_NEAR(c.x, light.x(), 1.0);
  EXPECT_NEAR(c.y, light.y(), 1.0);
}

TEST(FlareCommands, RenderFindsAnAutoLightInTheFrame) {
  const auto dir = test_dir();
  write_test_panorama(dir);
  // A white disc (the "sun") at about (20, 10) on the panorama.
  cv::Mat pano = cv::imread((dir / "pano.png").string());
  const Eigen::Vector2d uv = effects::to_equirect_uv({20.0, 10.0});
  cv::circle(pano,
             cv::Point(static_cast<int>(uv.x() * pano.cols), static_cast<int>(uv.y() * pano.rows)),
             2, cv::Scalar::all(255), cv::FILLED);
  cv::imwrite((dir / "pano.png").string(), pano);
  const std::string common = "--view 14,4 --fov 90 --size 200x120 ";
  write_text(dir / "s.vdfx.json", exposure_sidecar());
  const cv::Mat plain = render(dir, common, "plain.png");
  write_text(dir / "s.vdfx.json", flare_sidecar("directional", R"("auto")", 0.3));
  const cv::Mat on = render(dir, common, "on.png");
  const auto cam = effects::ViewCamera::from_horizontal_fov({{14.0, 4.0}, 0.0}, 90.0, 200, 120);
  const Eigen::Vector2d sun = *cam.project(effects::to_unit({20.0, 10.0}));
  const cv::Point2d c = brightening_centroid(on, plain);
  // Within a degree (1.1 px per degree here) of the disc drawn on a 256 x 128 panorama.
  EXPECT_NEAR(c.x, sun.x(), 2.0);
  EXPECT_NEAR(c.y, sun.y(), 2.0);
}

TEST(FlareCommands, HmdEyesSeeTheHeadsetPlaneWithItsDisparity) {
  const auto dir = test_dir();
  write_test_panorama(dir);
  write_text(dir / "s.vdfx.json", exposure_sidecar());
  const std::string common = "--view 0,0 --hmd generic90 --size 288x320 ";
  const cv::Mat plain_l = render(dir, common + "--eye left", "plain_l.png");
  const cv::Mat plain_r = render(dir, common + "--eye right", "plain_r.png");
  write_text(dir / "s.vdfx.json",
             flare_sidecar("headset", R"({"azimuth_deg": 0.0, "altitude_deg": 8.0})", 0.3));
  const cv::Mat left = render(dir, common + "--eye left", "left.png");
  const cv::Mat right = render(dir, common + "--eye right", "right.png");
  // The glare sits on the 5 cm plane at C = A + d / cos(8 deg) l; each eye projects that point.
  const xr::HmdProfile p = xr::load_hmd_profile("generic90");
  const Eigen::Vector3d C =
      (0.05 / std::cos(8.0 * effects::kDegToRad)) * effects::to_unit({0.0, 8.0});
  for (const xr::Eye e : xr::kEyes) {
    const double side = (e == xr::Eye::Left ? -0.5 : 0.5) * p.ipd_m;
    const effects::ViewCamera cam = effects::ViewCamera::from_tangents(
        Eigen::Matrix3d::Identity(), p.eye(e).fov.tangents(), 288, 320);
    const Eigen::Vector2d expected = *cam.project(C - Eigen::Vector3d(side, 0, 0));
    const cv::Point2d c = e == xr::Eye::Left ? brightening_centroid(left, plain_l)
                                             : brightening_centroid(right, plain_r);
    EXPECT_NEAR(c.x, expected.x(), 1.0) << xr::eye_name(e);
    EXPECT_NEAR(c.y, expected.y(), 1.0) << xr::eye_name(e);
  }
}

TEST(FlareCommands, EvalPrintsIntensitiesValidateCountsFlares) {
  const auto dir = test_dir();
  write_text(dir / "s.vdfx.json", flare_sidecar("headset", R"("auto")", 2.5));
  const CommandResult v = run_vdfx("validate " + (dir / "s.vdfx.json").string());
  EXPECT_NE(v.output.find("valid (2 effects, 3 keyframes)"), std::string::npos) << v.output;
  const CommandResult r = run_vdfx("eval " + (dir / "s.vdfx.json").string() + " --at 0,0,0");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  ASSERT_EQ(j["flares"].size(), 1u);
  EXPECT_NEAR(j["flares"][0]["intensity"].get<double>(), 2.5, 1e-9);
  write_text(dir / "bad.vdfx.json", flare_sidecar("anamorphic", R"("auto")", 2.5));
  const CommandResult bad = run_vdfx("validate " + (dir / "bad.vdfx.json").string());
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.output.find("/effects/1/style: unknown flare style"), std::string::npos)
      << bad.output;
}

TEST(FlareDocument, TheEditorsDocumentKeepsTheFlaresItDoesNotEdit) {
  const io::SidecarReport r =
      io::validate_sidecar_text(flare_sidecar("headset", R"("auto")", 2.5), "s");
  ASSERT_TRUE(r.ok()) << r.to_string();
  Document doc(*r.sidecar, DocumentOptions{{.async = false}});
  doc.add_keyframe(effects::EffectType::Tint, {{10.0, 0.0}, 0, {1.2, 1.0, 0.8}});
  const io::Sidecar saved = doc.sidecar();
  ASSERT_EQ(saved.flares.size(), 1u);
  EXPECT_EQ(saved.flares, r.sidecar->flares);
}

TEST(FlarePlayer, FlaresAreLaidOutForTheHeadPoseAndNeedAFrameForAnAutoLight) {
  const io::SidecarReport r = io::validate_sidecar_text(
      flare_sidecar("directional", R"({"azimuth_deg": 5.0, "altitude_deg": 0.0})", 1.0), "s");
  ASSERT_TRUE(r.ok()) << r.to_string();
  io::VideoProperties video;
  video.fps = {30, 1};
  video.frames = 1;
  Player player(*r.sidecar, video);
  xr::Pose head;
  head.position = {0.0, 1.6, 0.0};
  const auto layouts = player.flares(head, 0, nullptr);
  ASSERT_EQ(layouts.size(), 1u);
  EXPECT_LT(
      (layouts[0].light_point - (Eigen::Vector3d(0, 1.6, 0) + 100.0 * effects::to_unit({5.0, 0.0})))
          .norm(),
      1e-9);
  // Looking away beyond the fade: nothing.
  head.orientation = glm::angleAxis(glm::radians(60.0), glm::dvec3(0, 1, 0));
  EXPECT_TRUE(player.flares(head, 0, nullptr).empty());

  const io::SidecarReport a =
      io::validate_sidecar_text(flare_sidecar("directional", R"("auto")", 1.0), "s");
  Player auto_player(*a.sidecar, video);
  EXPECT_TRUE(auto_player.flares({}, 0, nullptr).empty());  // no frame yet: no light
  io::Picture frame;                                        // an RGB picture, as a still decodes
  frame.rgb = cv::Mat(128, 256, CV_8UC3, cv::Scalar::all(40));
  cv::circle(frame.rgb, cv::Point(128, 64), 2, cv::Scalar::all(255), cv::FILLED);
  EXPECT_EQ(auto_player.flares({}, 0, &frame).size(), 1u);
}

}  // namespace
}  // namespace vdfx::app::testing
