/// @file
/// @brief The shared benchmark inputs (seeded, built once).
#include "app/bench/inputs.h"

#include <cmath>
#include <cstdlib>
#include <glm/gtc/quaternion.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <random>

#include "effects/coords.h"
#include "xr/headset/eye_views.h"
#include "xr/headset/hmd_profile.h"

namespace vdfx::app::bench {

std::vector<effects::Keyframe> random_keyframes(int n, int dim, std::uint64_t seed,
                                                std::int64_t max_frame) {
  std::mt19937_64 rng(seed);
  // Uniform on the sphere: azimuth uniform, sin(altitude) uniform.
  std::uniform_real_distribution<double> az(-180, 180), h(-1, 1), v(0, 4);
  std::uniform_int_distribution<std::int64_t> f(0, max_frame);
  std::vector<effects::Keyframe> k(static_cast<std::size_t>(n));
  for (auto& kf : k) {
    kf.direction = {az(rng), std::asin(h(rng)) * effects::kRadToDeg};
    kf.frame = f(rng);
    for (int i = 0; i < dim; ++i) kf.params.push_back(v(rng));
  }
  return k;
}

const cv::Mat& synthetic_frame() {
  static const cv::Mat frame = [] {
    cv::Mat m(1920, 3840, CV_8UC3);
    m.forEach<cv::Vec3b>([](cv::Vec3b& p, const int* pos) {
      p = cv::Vec3b(static_cast<uchar>((pos[1] * 7) & 255), static_cast<uchar>((pos[0] * 3) & 255),
                    static_cast<uchar>(((pos[0] + pos[1]) / 4) & 255));
    });
    return m;
  }();
  return frame;
}

cv::Mat noise_image(int size) {
  cv::Mat m(size, size, CV_32FC3);
  cv::RNG rng(42);
  rng.fill(m, cv::RNG::UNIFORM, cv::Scalar::all(0.0), cv::Scalar::all(1.0));
  return m;
}

const cv::Mat& sunrise_rgb(bool* from_file) {
  static bool loaded = false;
  static const cv::Mat img = [] {
    setenv("OPENCV_IO_ENABLE_OPENEXR", "1", 1);
    cv::Mat bgr = cv::imread("/usr/share/blender/datafiles/studiolights/world/sunrise.exr",
                             cv::IMREAD_UNCHANGED);
    if (bgr.empty()) {
      cv::Mat noise(512, 1024, CV_32FC3);
      cv::RNG rng(42);
      rng.fill(noise, cv::RNG::UNIFORM, cv::Scalar::all(0.0), cv::Scalar::all(1.0));
      return noise;
    }
    loaded = true;
    if (bgr.channels() == 4) cv::cvtColor(bgr, bgr, cv::COLOR_BGRA2BGR);
    cv::Mat rgb;
    cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
    rgb.convertTo(rgb, CV_32FC3);
    return rgb;
  }();
  if (from_file) *from_file = loaded;
  return img;
}

xr::Pose head_at(const effects::Direction& look) {
  xr::Pose p;
  p.position = {0.0, 1.6, 0.0};
  p.orientation = glm::quat_cast(xr::camera_rotation(look, 0.0));
  return p;
}

const effects::EyeLens& generic90_left_lens() {
  static const effects::EyeLens e = xr::load_hmd_profile("generic90").eye_lens(xr::Eye::Left);
  return e;
}

const std::vector<cv::Point2d>& lens_grid_points() {
  static const std::vector<cv::Point2d> pts = [] {
    const effects::EyeLens& eye = generic90_left_lens();
    const double R = eye.lens.params().radius;
    std::vector<cv::Point2d> out;
    for (int j = 0; j < 64; ++j) {
      for (int i = 0; i < 64; ++i) {
        const Eigen::Vector2d t =
            eye.pixel_to_tan({(i + 0.5) / 64.0 * eye.width, (j + 0.5) / 64.0 * eye.height});
        out.emplace_back(t.x() / R, t.y() / R);
      }
    }
    return out;
  }();
  return pts;
}

double lens_px_per_unit() {
  const effects::EyeLens& e = generic90_left_lens();
  return e.lens.params().radius * e.width / (e.fov.right - e.fov.left);
}

cv::Point2d undistort_point(const cv::Point2d& p, effects::InverseMethod method) {
  const double r_d = std::hypot(p.x, p.y);
  const auto r_u = generic90_left_lens().lens.inverse(r_d, method);
  const double s = (r_u && r_d > 0.0) ? *r_u / r_d : 1.0;
  return {p.x * s, p.y * s};
}

void opencv_undistort_grid(std::vector<cv::Point2d>& out, int iterations) {
  const cv::Mat K = cv::Mat::eye(3, 3, CV_64F);
  const auto& p = generic90_left_lens().lens.params();
  const cv::Mat D = (cv::Mat_<double>(1, 4) << p.c1, p.c2, 0.0, 0.0);
  if (iterations == 0) {
    cv::undistortPoints(lens_grid_points(), out, K, D);
  } else {
    cv::undistortPoints(
        lens_grid_points(), out, K, D, cv::noArray(), cv::noArray(),
        cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, iterations, 1e-15));
  }
}

effects::StackParams colour_params() {
  effects::StackParams p;
  p.set(effects::EffectType::Tint, std::vector<double>{1.2, 1.0, 0.7});
  p.exposure_stops = 0.5;
  p.saturation = 1.3;
  p.contrast = 1.2;
  p.vignette_radius_deg = 30;
  p.vignette_falloff_deg = 20;
  return p;
}

}  // namespace vdfx::app::bench
