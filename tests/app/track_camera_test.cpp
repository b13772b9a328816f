/// @file
/// @brief The camera tracker (app/track/camera_tracker.h) on clips of a real panorama turned along
/// known paths and encoded with x264: orientation against the truth, frame 0 the world, frames
/// that cannot be tracked held and reported, the left eye of a stereo video, a VR180 image; and
/// its parts: the robust rotation fit and the rotation averaging.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <random>

#include "app/track/analysis_frame.h"
#include "app/track/camera_estimate.h"
#include "app/track/rotation_fit.h"
#include "app/track/rotation_graph.h"
#include "io/frame_decoder.h"
#include "tests/app/command_test_util.h"
#include "tests/app/track_test_util.h"

namespace vdfx::app::track {
namespace {

namespace fs = std::filesystem;
using app::testing::test_dir;
using app::testing::write_camera_clip;
using bench::orientation_errors;

CameraEstimate track_clip(const fs::path& clip, const effects::StereoLayout& layout = {},
                          CameraTrackOptions options = {}) {
  const auto decoder = io::open_frame_decoder(clip);
  return estimate_camera(*decoder, layout, options);
}

TEST(TrackCamera, FollowsATurnWithinATenthOfADegree) {
  // A full turn in 10 s (1.2 degrees a frame at 30 fps) with the horizon tilting: 3 s of it.
  const auto clip = write_camera_clip(test_dir() / "turn.mp4", bench::CameraPath::Turn, 90, 512);
  const CameraEstimate e = track_clip(clip.path);
  ASSERT_EQ(e.track.orientation.size(), 90u);
  EXPECT_TRUE(e.track.held.empty());
  EXPECT_EQ(e.track.orientation[0].coeffs(), Eigen::Quaterniond::Identity().coeffs());
  const auto err = orientation_errors(e.track.orientation, clip.truth);
  EXPECT_LE(err.rms, 0.1);
  EXPECT_LE(err.max, 0.3);
  EXPECT_GE(e.track.keyframes, 9);
  EXPECT_GT(e.track.links, e.track.keyframes);  // links reach past the previous key frame
}

TEST(TrackCamera, FollowsAShakeOfSeveralDegreesAFrame) {
  const auto clip = write_camera_clip(test_dir() / "shake.mp4", bench::CameraPath::Shake, 60, 512);
  double fastest = 0.0;  // the path is as rough as it says
  for (std::size_t i = 1; i < clip.truth.size(); ++i)
    fastest = std::max(fastest, bench::rotation_error_deg(clip.truth[i - 1], clip.truth[i]));
  EXPECT_GE(fastest, 4.0);
  const auto err = orientation_errors(track_clip(clip.path).track.orientation, clip.truth);
  EXPECT_LE(err.rms, 0.1);
  EXPECT_LE(err.max, 0.3);
}

TEST(TrackCamera, HoldsAFrameItCannotTrackAndPicksUpAfterIt) {
  // A black frame (a cut to black, a frame that decodes as nothing) in the middle of a turn.
  const fs::path file = test_dir() / "black.mp4";
  const auto truth = bench::camera_path(bench::CameraPath::Turn, 60, 30.0);
  const cv::Mat world = bench::world_panorama("forest", 1024);
  bench::encode_clip(file, 512, 256, 60, 30, [&](int i) {
    return i == 30 ? cv::Mat(256, 512, CV_8UC3, cv::Scalar::all(0))
                   : bench::camera_view(world, truth[i], 512, 256);
  });
  const CameraEstimate e = track_clip(file);
  EXPECT_EQ(e.track.held, std::vector<std::int64_t>{30});
  std::vector<Eigen::Quaterniond> got = e.track.orientation, want = truth;
  got.erase(got.begin() + 30);
  want.erase(want.begin() + 30);
  const auto err = orientation_errors(got, want);
  EXPECT_LE(err.rms, 0.1);
  EXPECT_LE(err.max, 0.3);
  // Held means the previous frame's orientation.
  EXPECT_EQ(e.track.orientation[30].coeffs(), e.track.orientation[29].coeffs());
}

TEST(TrackCamera, ReadsTheLeftEyeOfAStereoVideo) {
  // Top-bottom: the left eye (on top) turns, the right eye's picture stands still; following the
  // wrong eye would find no motion at all.
  const fs::path file = test_dir() / "stereo.mp4";
  const auto truth = bench::camera_path(bench::CameraPath::Shake, 40, 30.0);
  const cv::Mat world = bench::world_panorama("forest", 1024);
  const cv::Mat still = bench::camera_view(bench::world_panorama("city", 1024),
                                           Eigen::Quaterniond::Identity(), 512, 256);
  bench::encode_clip(file, 512, 512, 40, 30, [&](int i) {
    cv::Mat frame;
    cv::vconcat(bench::camera_view(world, truth[i], 512, 256), still, frame);
    return frame;
  });
  const CameraEstimate e = track_clip(file, {effects::StereoMode::TopBottom, 360});
  const auto err = orientation_errors(e.track.orientation, truth);
  EXPECT_LE(err.rms, 0.1);
  EXPECT_LE(err.max, 0.3);
}

TEST(TrackCamera, FollowsAVr180Image) {
  // A half turn: the image spans azimuth -90..90; corners leave it at the side edges.
  const fs::path file = test_dir() / "vr180.mp4";
  const auto truth = bench::camera_path(bench::CameraPath::Shake, 40, 30.0);
  const cv::Mat world = bench::world_panorama("forest", 1024);
  bench::encode_clip(file, 256, 256, 40, 30,
                     [&](int i) { return bench::camera_view(world, truth[i], 256, 256, 180); });
  const CameraEstimate e = track_clip(file, {effects::StereoMode::Mono, 180});
  EXPECT_EQ(e.width, 512);
  const auto err = orientation_errors(e.track.orientation, truth);
  EXPECT_LE(err.rms, 0.15);
  EXPECT_LE(err.max, 0.4);
}

TEST(TrackCamera, ReducesAFrameAsAreaAveragingDoes) {
  // A 4K-sized luma plane to the default analysis size: halvings then one non-integer step, about
  // as OpenCV's one-step area average (which is ten times slower at this factor).
  cv::Mat big(1920, 3840, CV_8U), ref;
  cv::randu(big, 0, 255);
  cv::GaussianBlur(big, big, cv::Size(0, 0), 2.0);
  const cv::Mat small = reduce_area(big, cv::Size(512, 256));
  ASSERT_EQ(small.size(), cv::Size(512, 256));
  cv::resize(big, ref, cv::Size(512, 256), 0, 0, cv::INTER_AREA);
  cv::Mat diff;
  cv::absdiff(small, ref, diff);
  EXPECT_LT(cv::mean(diff)[0], 2.0);
  // Exact halvings are OpenCV's own 2x2 means, and the size asked for is the size returned.
  cv::Mat half;
  cv::resize(big, half, cv::Size(1920, 960), 0, 0, cv::INTER_AREA);
  EXPECT_EQ(cv::norm(reduce_area(big, cv::Size(1920, 960)), half, cv::NORM_INF), 0.0);
  EXPECT_EQ(reduce_area(big, cv::Size(700, 300)).size(), cv::Size(700, 300));
}

TEST(RotationFit, FindsTheRotationOfTheInliersAmongManyOutliers) {
  std::mt19937 rng(7);
  std::normal_distribution<double> g(0.0, 1.0);
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.3, -1.0, 0.5).normalized()).toRotationMatrix();
  std::vector<Eigen::Vector3d> a, b;
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d v = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    a.push_back(v);
    // Two in five pairs are wrong (moving subjects): they point anywhere.
    b.push_back(i % 5 < 2 ? Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized() : r * v);
  }
  const RotationFit fit = fit_rotation(a, b, 1e-3);
  ASSERT_TRUE(fit.ok());
  EXPECT_EQ(fit.inliers, 120);
  EXPECT_LT(rotation_angle(fit.rotation * r.transpose()), 1e-9);
  for (int i = 0; i < 200; ++i) EXPECT_EQ(fit.inlier[i] != 0, i % 5 >= 2) << i;
  EXPECT_FALSE(fit_rotation({a.begin(), a.begin() + 5}, {b.begin(), b.begin() + 5}, 1e-3).ok());
}

/// Rotations about random axes, each `step_rad` from the last.
std::vector<Eigen::Matrix3d> random_walk(int n, double step_rad, std::mt19937& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<Eigen::Matrix3d> q{Eigen::Matrix3d::Identity()};
  for (int i = 1; i < n; ++i)
    q.push_back(q.back() *
                Eigen::AngleAxisd(step_rad, Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized())
                    .toRotationMatrix());
  return q;
}

TEST(RotationGraph, LinksFarBackKeepTheErrorFromAddingUp) {
  std::mt19937 rng(11);
  std::normal_distribution<double> g(0.0, 1.0);
  const int n = 100;
  const std::vector<Eigen::Matrix3d> truth = random_walk(n, 0.1, rng);
  // Every link measured with 0.05 degrees of error about a random axis.
  const auto measured = [&](int i, int j) {
    const Eigen::Matrix3d noise =
        Eigen::AngleAxisd(0.05 * effects::kDegToRad,
                          Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized())
            .toRotationMatrix();
    return RotationLink{i, j, noise * truth[j].transpose() * truth[i], 1.0};
  };
  std::vector<RotationLink> chain, tied;
  for (int j = 1; j < n; ++j) {
    chain.push_back(measured(j - 1, j));
    tied.push_back(chain.back());
    for (int d = 2; j - d >= 0; d *= 2) tied.push_back(measured(j - d, j));
  }
  // The chained estimate, as frame-to-frame tracking would have it, starts both solves.
  std::vector<Eigen::Matrix3d> chained{Eigen::Matrix3d::Identity()};
  for (const RotationLink& l : chain) chained.push_back(chained.back() * l.rotation.transpose());
  std::vector<Eigen::Matrix3d> averaged = chained;
  average_rotations(averaged, tied);
  const auto worst = [&](const std::vector<Eigen::Matrix3d>& q) {
    double w = 0.0;
    for (int i = 0; i < n; ++i) w = std::max(w, rotation_angle(q[i].transpose() * truth[i]));
    return w * effects::kRadToDeg;
  };
  EXPECT_EQ(averaged[0], Eigen::Matrix3d::Identity());
  EXPECT_LT(worst(averaged), 0.5 * worst(chained));
  EXPECT_LT(worst(averaged), 0.1);
  // Exact links: the truth itself.
  std::vector<RotationLink> exact = tied;
  for (RotationLink& l : exact) l.rotation = truth[l.to].transpose() * truth[l.from];
  std::vector<Eigen::Matrix3d> solved = chained;
  EXPECT_LT(average_rotations(solved, exact), 1e-9);
  EXPECT_LT(worst(solved), 1e-7);
}

}  // namespace
}  // namespace vdfx::app::track
