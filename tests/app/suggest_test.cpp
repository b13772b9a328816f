/// @file
/// @brief `vdfx suggest` (docs/suggest.md): the metering model against an independent brute-force
/// computation, the exposure and gaze-guidance suggestions' values where they matter, the fewest
/// keyframes rule, and the command's bad input.
#include "app/suggest/suggest.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "app/editor/editor.h"
#include "effects/rbf_interpolator.h"
#include "io/frame_decoder.h"
#include "io/sidecar.h"
#include "tests/app/command_test_util.h"

namespace vdfx::app::suggest {
namespace {

using testing::run_vdfx_headless;
using testing::test_dir;

constexpr double kWindowAz = 60.0, kWindowAlt = 10.0, kWindowRadiusDeg = 25.0;

/// A 512x256 equirect (sRGB PNG): a bright window (value 250) of 25 degrees radius at (60, 10)
/// in a dim room (value 30).
std::filesystem::path write_window_panorama(const std::filesystem::path& dir) {
  cv::Mat img(256, 512, CV_8UC3);
  const Eigen::Vector3d window = effects::to_unit({kWindowAz, kWindowAlt});
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x) {
      const auto d = effects::from_equirect_uv({(x + 0.5) / img.cols, (y + 0.5) / img.rows});
      const double a = effects::angle_between(effects::to_unit(d), window) * effects::kRadToDeg;
      const uchar v = a < kWindowRadiusDeg ? 250 : 30;
      img.at<cv::Vec3b>(y, x) = {v, v, v};
    }
  const auto path = dir / "window.png";
  cv::imwrite(path.string(), img);
  return path;
}

double srgb_to_linear(double v) {
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

/// The metering model of docs/suggest.md computed at full resolution, pixel by pixel, without
/// the grid: per-pixel solid angle cos(altitude), centre weight exp(-theta^2 / (2 (fov/4)^2))
/// within fov/2. A VR180 image (coverage 180) spans azimuth -90..90: only its pixels count.
struct BruteMeter {
  cv::Mat image;  // CV_8UC3
  int coverage = 360;
  effects::Direction direction(int x, int y) const {
    return {((x + 0.5) / image.cols - 0.5) * coverage, 90.0 - (y + 0.5) * 180.0 / image.rows};
  }
  double level(const effects::Direction& view, double fov_deg = 90.0) const {
    const Eigen::Vector3d v = effects::to_unit(view);
    const double half = fov_deg / 2 * effects::kDegToRad, sigma = fov_deg / 4 * effects::kDegToRad;
    double sum = 0, weights = 0;
    for (int y = 0; y < image.rows; ++y)
      for (int x = 0; x < image.cols; ++x) {
        const effects::Direction d = direction(x, y);
        const double theta = effects::angle_between(effects::to_unit(d), v);
        if (theta > half) continue;
        const double w = std::cos(d.altitude_deg * effects::kDegToRad) *
                         std::exp(-theta * theta / (2 * sigma * sigma));
        const double lin = srgb_to_linear(image.at<cv::Vec3b>(y, x)[0] / 255.0);
        sum += w * std::log2(lin);
        weights += w;
      }
    return sum / weights;
  }
  double reference() const {
    double sum = 0, weights = 0;
    for (int y = 0; y < image.rows; ++y)
      for (int x = 0; x < image.cols; ++x) {
        const double alt = 90.0 - (y + 0.5) * 180.0 / image.rows;
        const double w = std::cos(alt * effects::kDegToRad);
        sum += w * std::log2(srgb_to_linear(image.at<cv::Vec3b>(y, x)[0] / 255.0));
        weights += w;
      }
    return sum / weights;
  }
};

/// The suggestion read back and evaluated as every player evaluates it.
struct Suggested {
  io::Sidecar sidecar;
  std::unique_ptr<effects::RbfInterpolator> exposure, saturation;
  double at(const effects::RbfInterpolator& f, const effects::Direction& d,
            std::int64_t frame = 0) const {
    return f.evaluate(d, frame)[0];
  }
};

Suggested read_suggestion(const std::filesystem::path& path) {
  Suggested s;
  s.sidecar = io::read_sidecar(path);
  for (const auto& t : s.sidecar.effects) {
    auto f = std::make_unique<effects::RbfInterpolator>(
        t.keyframes, 1, t.interpolation.value_or(s.sidecar.interpolation), s.sidecar.video.fps,
        effects::effect_spec(t.type).neutral());
    (t.type == effects::EffectType::Exposure ? s.exposure : s.saturation) = std::move(f);
  }
  return s;
}

TEST(SuggestMetering, GridLevelsFollowTheBruteForceModel) {
  const auto dir = test_dir();
  const BruteMeter brute{cv::imread(write_window_panorama(dir).string())};
  cv::Mat rgb;
  brute.image.convertTo(rgb, CV_32FC3, 1.0 / 255);
  const MeteringOptions options;
  const MeterGeometry geometry(options.grid_width);
  const LumaGrid grid = make_luma_grid(rgb, Transfer::Srgb, geometry, options, 0);
  EXPECT_NEAR(reference_level(std::span(&grid, 1), geometry), brute.reference(), 0.05);
  // log2 of area means against means of log2: cells straddling the window's edge differ, so
  // the grid's model reads up to a few tenths of a stop off there, far less elsewhere.
  for (const effects::Direction d :
       {effects::Direction{kWindowAz, kWindowAlt}, {-120, 0}, {0, 0}, {60, 60}, {180, -70}})
    EXPECT_NEAR(metered_level(grid, geometry, effects::to_unit(d), options), brute.level(d), 0.3)
        << d.azimuth_deg << "," << d.altitude_deg;
  // The window reads brighter than the room (a 90 degree view of it still holds some room).
  EXPECT_GT(brute.level({kWindowAz, kWindowAlt}) - brute.level({-120, 0}), 3.0);
}

TEST(SuggestExposure, DarkensTheWindowBrightensTheRoomWithinTolerance) {
  const auto dir = test_dir();
  const auto pano = write_window_panorama(dir);
  SuggestRequest r;
  r.video = pano;
  r.sidecar_out = dir / "out.vdfx.json";
  const SuggestReport report = run_suggest(r);
  ASSERT_EQ(report.effects.size(), 1u);
  EXPECT_TRUE(report.effects[0].fit.within_tolerance);
  EXPECT_LE(report.effects[0].fit.max_error, kExposureToleranceStops);
  EXPECT_EQ(report.transfer, "sRGB");
  // Fewest keyframes: a field this smooth needs a handful, far below the 400 samples.
  const std::size_t used = report.effects[0].fit.added.size();
  EXPECT_GE(used, 2u);
  EXPECT_LE(used, 40u);

  const Suggested s = read_suggestion(r.sidecar_out);
  ASSERT_TRUE(s.exposure);
  const BruteMeter brute{cv::imread(pano.string())};
  const double ref = brute.reference();
  EXPECT_LT(s.at(*s.exposure, {kWindowAz, kWindowAlt}), -1.0);
  EXPECT_GT(s.at(*s.exposure, {-120, 0}), 0.3);
  // Within the tolerance of the independently computed target where it was sampled (plus the
  // grid's own reading error, GridLevelsFollowTheBruteForceModel).
  for (const auto& d : sphere_directions(60)) {
    const double target = std::clamp(ref - brute.level(d), -8.0, 8.0);
    EXPECT_NEAR(s.at(*s.exposure, d), target, kExposureToleranceStops + 0.35)
        << d.azimuth_deg << "," << d.altitude_deg;
  }
}

TEST(SuggestExposure, StrengthScalesAndTighterToleranceNeedsMoreKeyframes) {
  const auto dir = test_dir();
  const auto pano = write_window_panorama(dir);
  SuggestRequest r;
  r.video = pano;
  r.sidecar_out = dir / "full.vdfx.json";
  const std::size_t loose = run_suggest(r).effects[0].fit.added.size();
  r.tolerance = 0.1;
  r.sidecar_out = dir / "tight.vdfx.json";
  const SuggestReport tight = run_suggest(r);
  EXPECT_GT(tight.effects[0].fit.added.size(), loose);
  EXPECT_LE(tight.effects[0].fit.max_error, 0.1);

  r.tolerance.reset();
  r.strength = 0.5;
  r.sidecar_out = dir / "half.vdfx.json";
  run_suggest(r);
  const Suggested full = read_suggestion(dir / "full.vdfx.json");
  const Suggested half = read_suggestion(dir / "half.vdfx.json");
  const effects::Direction window{kWindowAz, kWindowAlt};
  EXPECT_NEAR(half.at(*half.exposure, window), 0.5 * full.at(*full.exposure, window), 0.3);
}

TEST(SuggestExposure, TheBudgetStopsTheFitAndSaysSo) {
  const auto dir = test_dir();
  SuggestRequest r;
  r.video = write_window_panorama(dir);
  r.sidecar_out = dir / "out.vdfx.json";
  r.tolerance = 0.001;
  r.max_keyframes = 3;
  const SuggestReport report = run_suggest(r);
  EXPECT_EQ(report.effects[0].fit.added.size(), 3u);
  EXPECT_FALSE(report.effects[0].fit.within_tolerance);
  EXPECT_GT(report.effects[0].fit.max_error, 0.001);
}

TEST(SuggestExposure, SaysHowFarItIsFramesThenKeyframesWithTheLargestError) {
  const auto dir = test_dir();
  SuggestRequest r;
  r.video = write_window_panorama(dir);
  r.sidecar_out = dir / "out.vdfx.json";
  r.tolerance = 0.1;
  std::vector<ProgressStep> steps;
  Progress progress;
  progress.on_step = [&](const ProgressStep& s) { steps.push_back(s); };
  const SuggestReport report = run_suggest(r, &progress);
  const FitResult& fit = report.effects.at(0).fit;
  ASSERT_GE(steps.size(), 3u);
  // The one frame, metered; then the fit from no keyframes to what it placed.
  EXPECT_EQ(steps[0].phase, ProgressStep::Phase::Frames);
  EXPECT_EQ(steps[0].done, 1);
  EXPECT_EQ(steps[0].total, 1);
  EXPECT_EQ(steps[1].phase, ProgressStep::Phase::Keyframes);
  EXPECT_EQ(steps[1].done, 0);
  EXPECT_GT(steps[1].max_error, 1.0);  // the window's target, before any keyframe
  for (std::size_t i = 1; i < steps.size(); ++i) {
    EXPECT_EQ(steps[i].phase, ProgressStep::Phase::Keyframes);
    EXPECT_EQ(steps[i].effect, effects::EffectType::Exposure);
    EXPECT_EQ(steps[i].total, 256);
    EXPECT_DOUBLE_EQ(steps[i].tolerance, 0.1);
    if (i > 1) {
      EXPECT_GT(steps[i].done, steps[i - 1].done);
    }
  }
  EXPECT_EQ(steps.back().done, static_cast<std::int64_t>(fit.added.size()));
  EXPECT_DOUBLE_EQ(steps.back().max_error, fit.max_error);
  EXPECT_DOUBLE_EQ(progress.fraction.load(), 1.0);
}

TEST(SuggestExposure, OnTheSunrisePanoramaDarkensTheSunsSide) {
  const std::filesystem::path sunrise =
      "/usr/share/blender/datafiles/studiolights/world/sunrise.exr";
  ASSERT_TRUE(std::filesystem::exists(sunrise)) << "blender-data is in .ci/deps.sh";
  const auto dir = test_dir();
  SuggestRequest r;
  r.video = sunrise;
  r.sidecar_out = dir / "out.vdfx.json";
  run_suggest(r);
  const Suggested s = read_suggestion(r.sidecar_out);
  // The sun is at (36, 8) (recordings/README.md); the opposite side is the shadowed land.
  EXPECT_LT(s.at(*s.exposure, {36, 8}), -0.5);
  EXPECT_GT(s.at(*s.exposure, {-144, 0}), s.at(*s.exposure, {36, 8}) + 1.0);
}

/// A smooth field over `directions` x `frames` samples: a bright and a dark patch (Gaussian in
/// the angle, 30 and 45 degrees wide) drifting 5 degrees in azimuth a frame.
TargetField drifting_field(int directions, int frames) {
  TargetField field;
  for (int f = 0; f < frames; ++f)
    for (const auto& d : sphere_directions(directions)) {
      const Eigen::Vector3d u = effects::to_unit(d);
      const auto patch = [&](const effects::Direction& c, double width_deg) {
        const double theta = effects::angle_between(u, effects::to_unit(c)) * effects::kRadToDeg;
        return std::exp(-theta * theta / (2 * width_deg * width_deg));
      };
      const double v = 2.5 * patch({40.0 + 5 * f, 10}, 30) - 1.5 * patch({-120.0 + 5 * f, -20}, 45);
      field.add(d, f, std::span(&v, 1));
    }
  return field;
}

FitOptions drifting_options(double tolerance, double step_share) {
  FitOptions o;
  o.tolerance = tolerance;
  o.max_keyframes = 4096;
  o.fps = 1.0;
  o.settings.time_scale = effects::time_scale_from_deg_per_s(30.0);
  o.neutral = {0.0};
  o.step_share = step_share;
  return o;
}

/// The largest error of the keyframes `fit` placed over every sample of `field`, evaluated as a
/// player evaluates them (a fresh solve of the keyframes).
double largest_error(const TargetField& field, const FitOptions& o, const FitResult& fit) {
  const effects::RbfInterpolator f(fit.added, 1, o.settings, o.fps, o.neutral);
  double worst = 0.0;
  for (std::size_t s = 0; s < field.size(); ++s)
    worst = std::max(
        worst, std::abs(f.evaluate(field.directions[s], field.frames[s])[0] - field.values[s]));
  return worst;
}

TEST(SuggestFit, StepsOfSeveralKeyframesMeetTheToleranceWithAboutThePlainGreedyCount) {
  const TargetField field = drifting_field(1000, 3);
  const FitOptions plain_options = drifting_options(0.01, 0.0);
  FitOptions options = drifting_options(0.01, FitOptions{}.step_share);
  std::size_t plain_steps = 0, steps = 0;
  FitOptions counted = plain_options;
  counted.on_step = [&](std::size_t, double) { ++plain_steps; };
  const FitResult plain = fit_greedy(field, counted);
  options.on_step = [&](std::size_t, double) { ++steps; };
  const FitResult fit = fit_greedy(field, options);
  ASSERT_TRUE(plain.within_tolerance);
  ASSERT_TRUE(fit.within_tolerance);
  // Every sample within the tolerance, checked apart from the fit's own measure.
  EXPECT_LE(largest_error(field, options, fit), 0.01 + 1e-9);
  EXPECT_NEAR(largest_error(field, options, fit), fit.max_error, 1e-9);
  // The plain fit measures after every keyframe (and once before); steps place many at once.
  EXPECT_EQ(plain_steps, plain.added.size() + 1);
  EXPECT_EQ(plain.steps, plain.added.size());
  EXPECT_EQ(fit.steps + 1, steps);
  EXPECT_LT(fit.steps * 3, fit.added.size());
  // About as few keyframes as the plain fit (within 10 %).
  EXPECT_LE(fit.added.size(), plain.added.size() * 11 / 10) << plain.added.size();
  EXPECT_GE(fit.added.size() * 11 / 10, plain.added.size());
}

TEST(SuggestFit, LargeStepsSolveAfreshAndTheBudgetIsMetExactly) {
  // A step share of 1 doubles the keyframes each step: steps of 64 and more solve all the
  // keyframes afresh instead of updating the solution one keyframe at a time.
  const TargetField field = drifting_field(800, 1);
  FitOptions options = drifting_options(0.005, 1.0);
  std::vector<std::size_t> added;
  options.on_step = [&](std::size_t n, double) { added.push_back(n); };
  const FitResult fit = fit_greedy(field, options);
  ASSERT_TRUE(fit.within_tolerance);
  EXPECT_GT(fit.added.size(), 128u);
  EXPECT_LE(largest_error(field, options, fit), 0.005 + 1e-9);
  EXPECT_EQ(added.front(), 0u);
  EXPECT_EQ(added.back(), fit.added.size());

  // A budget that ends inside a step: the step is cut to it.
  options.max_keyframes = 100;
  const FitResult cut = fit_greedy(field, options);
  EXPECT_EQ(cut.added.size(), 100u);
  EXPECT_FALSE(cut.within_tolerance);
  EXPECT_GT(cut.max_error, 0.005);
}

TEST(SuggestGuide, FollowsTheDocumentedFalloffAroundThePoint) {
  const auto dir = test_dir();
  SuggestRequest r;
  r.kind = Kind::Guide;
  r.video = write_window_panorama(dir);
  r.sidecar_out = dir / "out.vdfx.json";
  r.points = {parse_point_of_interest("-30,0")};
  r.guide_effect = GuideEffect::Both;
  const SuggestReport report = run_suggest(r);
  ASSERT_EQ(report.effects.size(), 2u);
  const Suggested s = read_suggestion(r.sidecar_out);
  ASSERT_TRUE(s.exposure && s.saturation);
  EXPECT_NEAR(s.at(*s.saturation, {-30, 0}), 1.0, kSaturationTolerance);
  EXPECT_NEAR(s.at(*s.exposure, {-30, 0}), 0.0, kExposureToleranceStops);
  EXPECT_NEAR(s.at(*s.saturation, {150, 0}), 1.0 - kGuideSaturationDepth, kSaturationTolerance);
  EXPECT_NEAR(s.at(*s.exposure, {150, 0}), -kGuideExposureStops, kExposureToleranceStops);
  // Halfway through the falloff (55 degrees from the point: smoothstep(0.5) = 0.5).
  EXPECT_NEAR(s.at(*s.saturation, {25, 0}), 1.0 - 0.5 * kGuideSaturationDepth,
              kSaturationTolerance + 0.02);
}

TEST(SuggestGuide, AMovingPointIsFollowedOverItsFrames) {
  const auto dir = test_dir();
  // A 3 s, 10 fps clip made from the panorama (the suggestion reads only its properties).
  const auto clip = dir / "clip.avi";
  const cv::Mat img = cv::imread(write_window_panorama(dir).string());
  cv::VideoWriter w(clip.string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 10, img.size());
  ASSERT_TRUE(w.isOpened());
  for (int i = 0; i < 30; ++i) w << img;
  w.release();
  SuggestRequest r;
  r.kind = Kind::Guide;
  r.video = clip;
  r.every = 5;
  r.sidecar_out = dir / "out.vdfx.json";
  r.points = {parse_point_of_interest("-90,0,0-14"), parse_point_of_interest("90,0,15-29")};
  run_suggest(r);
  const Suggested s = read_suggestion(r.sidecar_out);
  EXPECT_NEAR(s.at(*s.saturation, {-90, 0}, 5), 1.0, kSaturationTolerance);
  EXPECT_LT(s.at(*s.saturation, {90, 0}, 5), 0.3);
  EXPECT_NEAR(s.at(*s.saturation, {90, 0}, 25), 1.0, kSaturationTolerance);
  EXPECT_LT(s.at(*s.saturation, {-90, 0}, 25), 0.3);
}

/// A textured 720x360 equirect (smoothed noise, fixed seed: trackable everywhere), CV_8UC3.
cv::Mat textured_panorama() {
  cv::Mat noise(360, 720, CV_8UC3);
  cv::RNG rng(7);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 255);
  cv::Mat smooth;
  cv::GaussianBlur(noise, smooth, cv::Size(0, 0), 2.0);
  cv::normalize(smooth, smooth, 0, 255, cv::NORM_MINMAX);
  return smooth;
}

/// The panorama as the camera sees it after turning by `r` (a direction d of the world appears
/// at r d), resampled bilinearly.
cv::Mat rotated(const cv::Mat& pano, const Eigen::Matrix3d& r) {
  cv::Mat map_x(pano.size(), CV_32FC1), map_y(pano.size(), CV_32FC1);
  const Eigen::Matrix3d back = r.transpose();
  for (int y = 0; y < pano.rows; ++y)
    for (int x = 0; x < pano.cols; ++x) {
      const auto d = effects::from_equirect_uv({(x + 0.5) / pano.cols, (y + 0.5) / pano.rows});
      const Eigen::Vector2d uv =
          effects::to_equirect_uv(effects::from_unit(back * effects::to_unit(d)));
      map_x.at<float>(y, x) = static_cast<float>(uv.x() * pano.cols - 0.5);
      map_y.at<float>(y, x) = static_cast<float>(uv.y() * pano.rows - 0.5);
    }
  cv::Mat out;
  cv::remap(pano, out, map_x, map_y, cv::INTER_LINEAR, cv::BORDER_WRAP);
  return out;
}

Eigen::Matrix3d turn(double yaw_deg, double pitch_deg) {
  return (Eigen::AngleAxisd(yaw_deg * effects::kDegToRad, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(pitch_deg * effects::kDegToRad, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

TEST(SuggestMotion, RecoversAKnownRotationBetweenTwoFrames) {
  const cv::Mat pano = textured_panorama();
  cv::Mat a, b;
  pano.convertTo(a, CV_32FC3, 1.0 / 255);
  for (const auto& [yaw, pitch] : {std::pair{2.0, 0.0}, {-1.0, 1.5}, {0.0, 0.0}, {4.0, -2.0}}) {
    const Eigen::Matrix3d truth = turn(yaw, pitch);
    rotated(pano, truth).convertTo(b, CV_32FC3, 1.0 / 255);
    const MotionOptions o;
    const Rotation r = estimate_rotation(motion_frame(a, o), motion_frame(b, o), o);
    EXPECT_GT(r.tracked, 100);
    const double expected = Eigen::AngleAxisd(truth).angle() * effects::kRadToDeg;
    EXPECT_NEAR(r.angle_deg, expected, 0.1) << yaw << "," << pitch;
    // The same rotation, not only the same angle: it maps the view ahead where the truth does.
    const Eigen::Vector3d ahead = effects::to_unit({0, 0});
    EXPECT_LT(effects::angle_between(r.matrix * ahead, truth * ahead) * effects::kRadToDeg, 0.15)
        << yaw << "," << pitch;
  }
}

TEST(SuggestComfort, NarrowsTheViewWhileTheCameraTurnsFast) {
  // 4 s at 30 fps: still for 40 frames, then turning at 30 deg/s, then at 90 deg/s.
  const auto dir = test_dir();
  const auto clip = dir / "turning.avi";
  const cv::Mat pano = textured_panorama();
  cv::VideoWriter w(clip.string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 30, pano.size());
  ASSERT_TRUE(w.isOpened());
  double yaw = 0.0;
  for (int f = 0; f < 120; ++f) {
    yaw += f < 40 ? 0.0 : f < 80 ? 1.0 : 3.0;  // degrees per frame
    w << rotated(pano, turn(yaw, 0.0));
  }
  w.release();
  SuggestRequest r;
  r.kind = Kind::Comfort;
  r.video = clip;
  r.sidecar_out = dir / "out.vdfx.json";
  const SuggestReport report = run_suggest(r);
  ASSERT_EQ(report.speed_deg_per_s.size(), 120u);
  EXPECT_NEAR(report.speed_deg_per_s[20], 0.0, 2.0);
  EXPECT_NEAR(report.speed_deg_per_s[60], 30.0, 2.0);
  EXPECT_NEAR(report.speed_deg_per_s[100], 90.0, 3.0);
  ASSERT_EQ(report.effects.size(), 1u);
  EXPECT_TRUE(report.effects[0].fit.within_tolerance);

  const io::Sidecar s = io::read_sidecar(r.sidecar_out);
  ASSERT_EQ(s.effects.size(), 1u);
  ASSERT_EQ(s.effects[0].type, effects::EffectType::Vignette);
  const effects::RbfInterpolator f(
      s.effects[0].keyframes, 2, s.effects[0].interpolation.value_or(s.interpolation), s.video.fps,
      effects::effect_spec(effects::EffectType::Vignette).neutral());
  // Half a second away from each change the look-ahead window sees one speed only.
  for (const effects::Direction d : {effects::Direction{0, 0}, {120, 30}, {-90, -45}}) {
    EXPECT_NEAR(f.evaluate(d, 20)[0], comfort_radius_deg(0.0, 1.0), kVignetteToleranceDeg + 1);
    EXPECT_NEAR(f.evaluate(d, 60)[0], comfort_radius_deg(30.0, 1.0), kVignetteToleranceDeg + 1);
    EXPECT_NEAR(f.evaluate(d, 100)[0], comfort_radius_deg(90.0, 1.0), kVignetteToleranceDeg + 1);
    EXPECT_NEAR(f.evaluate(d, 100)[1], kComfortFalloffDeg, kVignetteToleranceDeg);
  }
  EXPECT_NEAR(comfort_radius_deg(30.0, 1.0), 78.0, 1e-9);  // the documented mapping
  EXPECT_NEAR(comfort_radius_deg(90.0, 1.0), kComfortMinRadiusDeg, 1e-9);
}

TEST(SuggestComfort, AStillHasNoMotionToMeasure) {
  const auto dir = test_dir();
  const auto r = run_vdfx_headless("suggest comfort " + write_window_panorama(dir).string() +
                                   " --sidecar-out " + (dir / "c.vdfx.json").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("cannot estimate the camera's motion"), std::string::npos) << r.output;
}

// ---- VR180 (docs/suggest.md, "VR180"): the left eye's half turn only

/// A VR180 eye, size x size (azimuth -90..90): a bright window (250) of 25 degrees radius at
/// (-50, 10) in a dim room (30), grey.
cv::Mat vr180_window_eye(int size) {
  cv::Mat img(size, size, CV_8UC3);
  const BruteMeter geometry{img, 180};
  const Eigen::Vector3d window = effects::to_unit({-50, 10});
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double a = effects::angle_between(effects::to_unit(geometry.direction(x, y)), window) *
                       effects::kRadToDeg;
      const uchar v = a < kWindowRadiusDeg ? 250 : 30;
      img.at<cv::Vec3b>(y, x) = {v, v, v};
    }
  return img;
}

TEST(SuggestVr180, MetersTheCoveredImageAndPlacesKeyframesInsideIt) {
  const auto dir = test_dir();
  // Left-right VR180: the left eye has the window, the right eye (never analysed) is all room.
  const cv::Mat left = vr180_window_eye(256), right(256, 256, CV_8UC3, cv::Scalar::all(30));
  cv::Mat frame;
  cv::hconcat(left, right, frame);
  const auto png = dir / "vr180.png";
  cv::imwrite(png.string(), frame);
  SuggestRequest r;
  r.video = png;
  r.sidecar_out = dir / "out.vdfx.json";
  r.layout = {effects::StereoMode::LeftRight, 180};
  const SuggestReport report = run_suggest(r);
  ASSERT_EQ(report.effects.size(), 1u);
  EXPECT_TRUE(report.effects[0].fit.within_tolerance);
  // The reference level is the covered hemisphere's: the half turn behind counts nowhere (read
  // as black it would pull the level down by stops, as the window's mirror it would push it up).
  const BruteMeter brute{left, 180};
  const double ref = brute.reference();
  EXPECT_NEAR(report.reference_level, ref, 0.05);

  const Suggested s = read_suggestion(r.sidecar_out);
  EXPECT_EQ(s.sidecar.video.stereo(), (effects::StereoLayout{effects::StereoMode::LeftRight, 180}));
  ASSERT_TRUE(s.exposure);
  ASSERT_FALSE(s.sidecar.effects[0].keyframes.empty());
  for (const auto& k : s.sidecar.effects[0].keyframes)  // where the editor places keyframes
    EXPECT_LT(std::abs(k.direction.azimuth_deg), 90.0) << k.direction.azimuth_deg;
  EXPECT_LT(s.at(*s.exposure, {-50, 10}), -1.0);
  EXPECT_GT(s.at(*s.exposure, {50, 0}), 0.3);
  // Within the tolerance of the target metered on the covered image alone, pixel by pixel (a
  // view near the edge meters what it shows, not the black beyond).
  for (const auto& d : sphere_directions(80)) {
    if (std::abs(d.azimuth_deg) > 85.0) continue;
    const double target = std::clamp(ref - brute.level(d), -8.0, 8.0);
    EXPECT_NEAR(s.at(*s.exposure, d), target, kExposureToleranceStops + 0.35)
        << d.azimuth_deg << "," << d.altitude_deg;
  }
}

TEST(SuggestVr180, ComfortMeasuresTheTurnOnTheHalfTurnImage) {
  // 40 frames at 30 fps, the left eye's half turn of a turning panorama: still for 20 frames,
  // then 2 degrees a frame (60 deg/s). Read as a whole turn, the turn would measure double.
  const auto dir = test_dir();
  const auto clip = dir / "vr180_turning.avi";
  const cv::Mat pano = textured_panorama();  // 720 x 360: the half turn is columns 180..540
  cv::VideoWriter w(clip.string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 30,
                    cv::Size(720, 360));
  ASSERT_TRUE(w.isOpened());
  double yaw = 0.0;
  for (int f = 0; f < 40; ++f) {
    yaw += f < 20 ? 0.0 : 2.0;
    const cv::Mat eye = rotated(pano, turn(yaw, 0.0)).colRange(180, 540);
    cv::Mat pair;
    cv::hconcat(eye, eye, pair);
    w << pair;
  }
  w.release();
  SuggestRequest r;
  r.kind = Kind::Comfort;
  r.video = clip;
  r.sidecar_out = dir / "out.vdfx.json";
  r.layout = {effects::StereoMode::LeftRight, 180};
  const SuggestReport report = run_suggest(r);
  ASSERT_EQ(report.speed_deg_per_s.size(), 40u);
  EXPECT_NEAR(report.speed_deg_per_s[10], 0.0, 2.0);
  EXPECT_NEAR(report.speed_deg_per_s[30], 60.0, 3.0);
  const io::Sidecar s = io::read_sidecar(r.sidecar_out);
  ASSERT_EQ(s.effects.size(), 1u);
  ASSERT_FALSE(s.effects[0].keyframes.empty());
  for (const auto& k : s.effects[0].keyframes)
    EXPECT_LT(std::abs(k.direction.azimuth_deg), 90.0) << k.direction.azimuth_deg;
}

TEST(SuggestVr180, APointOfInterestOutsideTheImageIsAnInputError) {
  const auto dir = test_dir();
  cv::Mat frame;
  cv::hconcat(vr180_window_eye(128), vr180_window_eye(128), frame);
  const auto png = dir / "vr180.png";
  cv::imwrite(png.string(), frame);
  const auto r =
      run_vdfx_headless("suggest guide " + png.string() + " --poi 120,0 --sidecar-out " +
                        (dir / "g.vdfx.json").string() + " --layout left-right --coverage 180");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find(png.string() + ": --poi 120,0: outside the video's image"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "g.vdfx.json"));
}

// ---- the editor's "Suggest" (docs/suggest.md, "In the editor")

/// An editor on `video` with a new sidecar, suggestions on a worker.
std::unique_ptr<Editor> editor_on(const std::filesystem::path& video, bool async = true) {
  auto decoder = io::open_frame_decoder(video, {});
  const auto& p = decoder->properties();
  EditorOptions eo;
  eo.video = video;
  eo.async_suggestions = async;
  eo.visuals.async = false;
  return std::make_unique<Editor>(
      io::new_sidecar(
          {video.string(), p.fps.value(), std::max<std::int64_t>(1, p.frames), p.width, p.height}),
      DocumentOptions{{.async = false}}, eo);
}

TEST(EditorSuggest, ExposureAddsTheCommandsKeyframesAsOneUndoStep) {
  const auto dir = test_dir();
  const auto pano = write_window_panorama(dir);
  auto ed = editor_on(pano);
  ed->select_effect(effects::EffectType::Exposure);
  EXPECT_EQ(ed->ui().suggest_button().label(), "Suggest exposure");
  ed->suggest();
  ASSERT_TRUE(ed->wait_for_suggestion(std::chrono::seconds(120)));
  EXPECT_FALSE(ed->suggestion_progress().has_value());
  const auto& added = ed->document().keyframes(effects::EffectType::Exposure);
  ASSERT_GT(added.size(), 1u);

  // The same keyframes as the command's on the same video.
  SuggestRequest r;
  r.video = pano;
  r.sidecar_out = dir / "cmd.vdfx.json";
  run_suggest(r);
  const Suggested cmd = read_suggestion(r.sidecar_out);
  ASSERT_EQ(cmd.sidecar.effects.at(0).keyframes.size(), added.size());
  for (std::size_t i = 0; i < added.size(); ++i) {
    EXPECT_NEAR(added[i].direction.azimuth_deg,
                cmd.sidecar.effects[0].keyframes[i].direction.azimuth_deg, 1e-9);
    EXPECT_NEAR(added[i].params[0], cmd.sidecar.effects[0].keyframes[i].params[0], 1e-9);
  }
  const auto f = ed->interpolant(effects::EffectType::Exposure);
  EXPECT_LT(f->evaluate(effects::Direction{kWindowAz, kWindowAlt}, 0)[0], -0.5);
  EXPECT_GT(f->evaluate(effects::Direction{kWindowAz + 180, -kWindowAlt}, 0)[0], 0.1);

  // One undo step removes them all; redo brings them back.
  EXPECT_TRUE(ed->undo());
  EXPECT_TRUE(ed->document().keyframes(effects::EffectType::Exposure).empty());
  EXPECT_FALSE(ed->document().undo_stack().can_undo());
  EXPECT_TRUE(ed->redo());
  EXPECT_EQ(ed->document().keyframes(effects::EffectType::Exposure).size(),
            cmd.sidecar.effects[0].keyframes.size());
}

TEST(EditorSuggest, TheStrengthSliderScalesItAndEffectsWithoutOneSaySo) {
  const auto dir = test_dir();
  auto ed = editor_on(write_window_panorama(dir), /*async=*/false);
  ed->select_effect(effects::EffectType::Exposure);
  ed->set_suggest_strength(0.0);
  ed->suggest();
  EXPECT_TRUE(ed->document().keyframes(effects::EffectType::Exposure).empty());
  EXPECT_NE(ed->hud_message().find("adds nothing"), std::string::npos) << ed->hud_message();

  ed->set_suggest_strength(0.5);
  ed->suggest();
  const auto half = ed->interpolant(effects::EffectType::Exposure);
  ASSERT_TRUE(half);
  ed->undo();
  ed->set_suggest_strength(1.0);
  ed->suggest();
  const auto full = ed->interpolant(effects::EffectType::Exposure);
  const double at_half = half->evaluate(effects::Direction{kWindowAz, kWindowAlt}, 0)[0];
  const double at_full = full->evaluate(effects::Direction{kWindowAz, kWindowAlt}, 0)[0];
  EXPECT_NEAR(at_half, 0.5 * at_full, kExposureToleranceStops * 1.5);
  EXPECT_LT(at_full, -0.5);

  // Blur has no suggestion: no button on the panel, a message, nothing changed.
  ed->select_effect(effects::EffectType::Blur);
  ed->update(xr::neutral_input_state(0), 1);
  EXPECT_EQ(ed->ui().suggest_button().rect().w, 0.0);
  ed->suggest();
  EXPECT_FALSE(ed->suggestion_progress().has_value());
  EXPECT_NE(ed->hud_message().find("has no suggestion"), std::string::npos) << ed->hud_message();
  // Saturation guides toward the view centre (the view is (0, 0) here).
  ed->select_effect(effects::EffectType::Saturation);
  ed->suggest();
  const auto sat = ed->interpolant(effects::EffectType::Saturation);
  ASSERT_TRUE(sat);
  EXPECT_GT(sat->evaluate(effects::Direction{0, 0}, 0)[0],
            sat->evaluate(effects::Direction{180, 0}, 0)[0] + 0.3);
}

TEST(EditorSuggest, CancellingLeavesTheDocumentAsItWas) {
  // The library: a suggestion asked to stop throws at its first step and changes nothing.
  const auto dir = test_dir();
  const auto pano = write_window_panorama(dir);
  io::Sidecar sidecar = io::new_sidecar({pano.string(), 30.0, 1, 512, 256});
  const std::string before = io::format_sidecar(sidecar);
  Progress progress;
  progress.cancel = true;
  SuggestRequest r;
  r.video = pano;
  EXPECT_THROW(suggest_into(r, sidecar, &progress), Cancelled);
  EXPECT_EQ(io::format_sidecar(sidecar), before);

  // The editor: a comfort suggestion over a 4 s clip, cancelled right after it started.
  const auto clip = dir / "turning.avi";
  const cv::Mat pano_img = textured_panorama();
  cv::VideoWriter w(clip.string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 30,
                    pano_img.size());
  for (int f = 0; f < 120; ++f) w << rotated(pano_img, turn(2.0 * f, 0.0));
  w.release();
  auto ed = editor_on(clip);
  ed->select_effect(effects::EffectType::Vignette);
  ed->suggest();
  ASSERT_TRUE(ed->suggestion_progress().has_value());
  ed->update(xr::neutral_input_state(0), 1);
  EXPECT_EQ(ed->ui().suggest_button().label().rfind("Cancel", 0), 0u)
      << ed->ui().suggest_button().label();
  ed->suggest();  // pressed again: cancel
  ASSERT_TRUE(ed->wait_for_suggestion(std::chrono::seconds(120)));
  EXPECT_TRUE(ed->document().keyframes(effects::EffectType::Vignette).empty());
  EXPECT_FALSE(ed->document().undo_stack().can_undo());
  EXPECT_NE(ed->hud_message().find("cancelled, nothing changed"), std::string::npos)
      << ed->hud_message();
}

TEST(SuggestCommand, ReportsAndWritesAValidSidecar) {
  const auto dir = test_dir();
  const auto pano = write_window_panorama(dir);
  const auto out = dir / "s.vdfx.json";
  const auto r =
      run_vdfx_headless("suggest exposure " + pano.string() + " --sidecar-out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("metered 1 frames as sRGB"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("exposure"), std::string::npos) << r.output;
  // Progress on stderr (a pipe here: lines), as export shows it: the frames metered, then the
  // keyframes placed with the largest error against the tolerance.
  EXPECT_NE(r.output.find("suggest: 1/1 frames (100%)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("suggest exposure: 0/256 keyframes"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("(tolerance 0.250)\n"), std::string::npos) << r.output;
  EXPECT_EQ(run_vdfx_headless("validate " + out.string()).exit_code, 0);
}

TEST(SuggestCommand, BadInputIsAMessageWithTheContractsExitCode) {
  const auto dir = test_dir();
  const auto pano = write_window_panorama(dir);
  const auto out = dir / "s.vdfx.json";
  const std::string base = "suggest exposure " + pano.string() + " --sidecar-out ";
  // Keyframes already there: only with --merge.
  ASSERT_EQ(run_vdfx_headless(base + out.string()).exit_code, 0);
  auto r = run_vdfx_headless(base + (dir / "again.vdfx.json").string() + " --sidecar-in " +
                             out.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("pass --merge"), std::string::npos) << r.output;
  r = run_vdfx_headless(base + (dir / "again.vdfx.json").string() + " --sidecar-in " +
                        out.string() + " --merge --tolerance 0.1");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  // The output is an input.
  r = run_vdfx_headless(base + pano.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  // An all-black panorama cannot be metered.
  const auto black = dir / "black.png";
  cv::imwrite(black.string(), cv::Mat(64, 128, CV_8UC3, cv::Scalar::all(0)));
  r = run_vdfx_headless("suggest exposure " + black.string() + " --sidecar-out " +
                        (dir / "b.vdfx.json").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("cannot be metered"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "b.vdfx.json"));
  // Options out of range are usage errors.
  EXPECT_EQ(run_vdfx_headless(base + out.string() + " --strength 2").exit_code, 2);
  EXPECT_EQ(run_vdfx_headless("suggest guide " + pano.string() + " --sidecar-out " + out.string() +
                              " --poi 10,100")
                .exit_code,
            2);
}

}  // namespace
}  // namespace vdfx::app::suggest
