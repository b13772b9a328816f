/// @file
/// @brief `vdfx export --baked --stabilize` (docs/export.md, "Stabilised"): a real panorama seen by
/// a camera turning along known orientations (the sidecar's camera, source "given"), encoded with
/// x264. Stabilised, every frame shows the world as frame 0 does, where the plain export turns;
/// the effects are those of the plain export, moved with the picture (the contract: the picture's
/// direction w shows the video at q_f^-1 w q_f, checked against bench::camera_view); a sidecar
/// without camera motion is exit 1 naming it.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "app/bench/media.h"
#include "app/bench/track_clips.h"
#include "io/frame_decoder.h"
#include "tests/app/command_test_util.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;
using testing::run_vdfx;
using testing::test_dir;
using testing::write_text;

constexpr int kW = 256, kH = 128, kFrames = 6;

/// Frame f's camera: 25 degrees more yaw a frame, and a growing tilt.
Eigen::Quaterniond camera_at(int f) {
  return Eigen::Quaterniond(
      Eigen::AngleAxisd(25.0 * f * effects::kDegToRad, Eigen::Vector3d::UnitY()) *
      Eigen::AngleAxisd(3.0 * f * effects::kDegToRad, Eigen::Vector3d::UnitX()));
}

/// `effects` (a JSON array) and, with `camera`, the turning camera's orientations.
std::string sidecar(const std::string& effects, bool camera) {
  std::ostringstream s;
  s << R"({"format": "vdfx.sidecar", "version": 1, "video": {"path": "turn.mp4", "fps": 30.0, )"
    << R"("frames": )" << kFrames << R"(, "width": )" << kW << R"(, "height": )" << kH
    << R"(}, "interpolation": {"exponent": 1.0, "time_scale": 1.0}, "effects": )" << effects;
  if (camera) {
    s << R"(, "camera": {"source": "given", "orientation": [)";
    for (int f = 0; f < kFrames; ++f) {
      const Eigen::Quaterniond q = camera_at(f);
      s << (f ? ", " : "") << "[" << q.w() << ", " << q.x() << ", " << q.y() << ", " << q.z()
        << "]";
    }
    s << "]}";
  }
  s << "}";
  return s.str();
}

/// Exposure -0.5 stops everywhere (one keyframe).
const char* kEverywhere = R"([{"type": "exposure", "keyframes": [
  {"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 0, "params": {"stops": -0.5}}]}])";
/// Exposure +1 stop at azimuth 0 of the video frame, -1 stop behind.
const char* kDirectional = R"([{"type": "exposure", "keyframes": [
  {"azimuth_deg": 0.0, "altitude_deg": 0.0, "frame": 0, "params": {"stops": 1.0}},
  {"azimuth_deg": 180.0, "altitude_deg": 0.0, "frame": 0, "params": {"stops": -1.0}}]}])";

struct Clip {
  fs::path dir, video;
};

Clip turning_clip() {
  Clip c{test_dir(), {}};
  const cv::Mat world = bench::world_panorama("forest", 2 * kW);
  c.video = bench::encode_clip(c.dir / "turn.mp4", kW, kH, kFrames, 30, [&](int i) {
    return bench::camera_view(world, camera_at(i), kW, kH);
  });
  return c;
}

std::vector<cv::Mat> export_frames(const Clip& c, const std::string& name, const std::string& json,
                                   bool stabilize) {
  const fs::path side = c.dir / (name + ".vdfx.json"), out = c.dir / (name + ".mp4");
  write_text(side, json);
  const auto r = run_vdfx("export " + c.video.string() + " --sidecar " + side.string() +
                          " --baked " + out.string() + (stabilize ? " --stabilize" : ""));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  if (stabilize) {
    EXPECT_NE(r.output.find("stabilised"), std::string::npos) << r.output;
  }
  const auto d = io::open_frame_decoder(out);
  std::vector<cv::Mat> frames;
  for (cv::Mat m; d->read(m) == io::DecodeStatus::Ok;) frames.push_back(m.clone());
  EXPECT_EQ(frames.size(), static_cast<std::size_t>(kFrames));
  return frames;
}

/// Mean absolute difference (8-bit code values) over the rows away from the poles (their few
/// pixels stretch across the whole row and carry the most resampling error).
double mean_difference(const cv::Mat& a, const cv::Mat& b) {
  const cv::Rect band(0, kH / 8, kW, kH - kH / 4);
  cv::Mat diff;
  cv::absdiff(a(band), b(band), diff);
  const cv::Scalar m = cv::mean(diff);
  return (m[0] + m[1] + m[2]) / 3.0;
}

TEST(ExportStabilize, EveryFrameShowsTheWorldAsFrameZeroDoes) {
  const Clip c = turning_clip();
  const auto plain = export_frames(c, "plain", sidecar(kEverywhere, true), false);
  const auto stable = export_frames(c, "stable", sidecar(kEverywhere, true), true);
  ASSERT_EQ(stable.size(), static_cast<std::size_t>(kFrames));
  for (int f = 1; f < kFrames; ++f) {
    EXPECT_GT(mean_difference(plain[f], plain[0]), 12.0) << f;   // the plain export turns
    EXPECT_LT(mean_difference(stable[f], stable[0]), 5.0) << f;  // the stabilised one holds
  }
  // The exposure is in the picture: -0.5 stops darker than the plain frame 0 of no effect.
  const cv::Mat world0 =
      bench::camera_view(bench::world_panorama("forest", 2 * kW), camera_at(0), kW, kH);
  EXPECT_LT(cv::mean(stable[0])[1], 0.85 * cv::mean(world0)[1]);
}

TEST(ExportStabilize, EffectsAreThePlainExportsMovedWithThePicture) {
  const Clip c = turning_clip();
  const auto plain = export_frames(c, "plain", sidecar(kDirectional, true), false);
  const auto stable = export_frames(c, "stable", sidecar(kDirectional, true), true);
  ASSERT_EQ(stable.size(), static_cast<std::size_t>(kFrames));
  for (int f = 0; f < kFrames; ++f) {
    // The picture's direction w shows the plain frame at q_f^-1 w (camera_view: n shows q n).
    const cv::Mat want = bench::camera_view(plain[f], camera_at(f).inverse(), kW, kH);
    EXPECT_LT(mean_difference(stable[f], want), 5.0) << f;
  }
  // A directional effect turns with the video: stabilised frames differ where it lies.
  EXPECT_GT(mean_difference(stable[kFrames - 1], stable[0]), 6.0);
}

TEST(ExportStabilize, NeedsTheSidecarsCameraMotion) {
  const Clip c{test_dir(), {}};
  const fs::path side = c.dir / "s.vdfx.json", video = c.dir / "still.png";
  write_text(side, sidecar(kEverywhere, false));
  cv::imwrite(video.string(), cv::Mat(kH, kW, CV_8UC3, cv::Scalar(90, 120, 150)));
  const auto r = run_vdfx("export " + video.string() + " --sidecar " + side.string() + " --baked " +
                          (c.dir / "o.mp4").string() + " --stabilize");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(
      r.output.find(side.string() + ": --stabilize: the sidecar has no camera motion: run vdfx "
                                    "track camera"),
      std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(c.dir / "o.mp4"));
}

}  // namespace
}  // namespace vdfx::app
