/// @file
/// @brief Known camera and subject paths over a real panorama (track_clips.h).
#include "app/bench/track_clips.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "effects/coords.h"
#include "effects/view_camera.h"
#include "io/image_source.h"

namespace vdfx::app::bench {

namespace fs = std::filesystem;
using effects::kDegToRad;

fs::path studio_light(const std::string& name) {
  return fs::path("/usr/share/blender/datafiles/studiolights/world") / (name + ".exr");
}

cv::Mat world_panorama(const std::string& name, int width) {
  const cv::Mat rgb = io::load_image(studio_light(name)).rgb;
  cv::Mat small, out;
  cv::resize(rgb, small, cv::Size(width, width / 2), 0, 0,
             width < rgb.cols ? cv::INTER_AREA : cv::INTER_CUBIC);
  small.convertTo(out, CV_8UC3, 255.0);
  return out;
}

cv::Mat camera_view(const cv::Mat& world, const Eigen::Quaterniond& q, int w, int h,
                    int coverage_deg) {
  // One row across each pole (the row next to it, half a turn round), so that bilinear samples
  // there blend the right neighbours; columns wrap through remap's border.
  cv::Mat padded(world.rows + 2, world.cols, world.type());
  world.copyTo(padded(cv::Rect(0, 1, world.cols, world.rows)));
  const int half = world.cols / 2;
  for (int edge = 0; edge < 2; ++edge) {
    const cv::Mat src = world.row(edge == 0 ? 0 : world.rows - 1);
    cv::Mat dst = padded.row(edge == 0 ? 0 : padded.rows - 1);
    src.colRange(half, world.cols).copyTo(dst.colRange(0, world.cols - half));
    src.colRange(0, half).copyTo(dst.colRange(world.cols - half, world.cols));
  }
  const Eigen::Matrix3d r = q.normalized().toRotationMatrix();
  cv::Mat map_x(h, w, CV_32F), map_y(h, w, CV_32F);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const effects::Direction d{((x + 0.5) / w - 0.5) * coverage_deg,
                                 90.0 - (y + 0.5) * 180.0 / h};
      const Eigen::Vector3d n = r * effects::to_unit(d);
      const double az = std::atan2(n.x(), -n.z()), alt = std::asin(std::clamp(n.y(), -1.0, 1.0));
      map_x.at<float>(y, x) =
          static_cast<float>((0.5 + az / (2 * effects::kPi)) * world.cols - 0.5);
      map_y.at<float>(y, x) = static_cast<float>((0.5 - alt / effects::kPi) * world.rows + 0.5);
    }
  cv::Mat out;
  cv::remap(padded, out, map_x, map_y, cv::INTER_LINEAR, cv::BORDER_WRAP);
  return out;
}

namespace {

Eigen::Quaterniond yaw_pitch_roll(double yaw_deg, double pitch_deg, double roll_deg) {
  // Yaw to the right turns the forward direction towards +x: a negative turn about +y.
  return Eigen::Quaterniond(Eigen::AngleAxisd(-yaw_deg * kDegToRad, Eigen::Vector3d::UnitY()) *
                            Eigen::AngleAxisd(pitch_deg * kDegToRad, Eigen::Vector3d::UnitX()) *
                            Eigen::AngleAxisd(roll_deg * kDegToRad, Eigen::Vector3d::UnitZ()));
}

/// A sum of sines that starts at 0: amplitude a (degrees), frequencies f (Hz), phases p.
double wobble(double t, const double (&a)[3], const double (&f)[3], const double (&p)[3]) {
  double v = 0.0;
  for (int k = 0; k < 3; ++k)
    v += a[k] * (std::sin(2 * effects::kPi * f[k] * t + p[k]) - std::sin(p[k]));
  return v;
}

}  // namespace

std::vector<Eigen::Quaterniond> camera_path(CameraPath path, int frames, double fps) {
  std::vector<Eigen::Quaterniond> out;
  for (int i = 0; i < frames; ++i) {
    const double t = i / fps, s = frames > 1 ? static_cast<double>(i) / (frames - 1) : 0.0;
    switch (path) {
      case CameraPath::Turn:
        out.push_back(yaw_pitch_roll(36.0 * t, 8.0 * std::sin(2 * effects::kPi * t / 7.0),
                                     5.0 * std::sin(2 * effects::kPi * t / 5.0)));
        break;
      case CameraPath::Shake:
        out.push_back(yaw_pitch_roll(wobble(t, {2.2, 1.6, 1.1}, {3.1, 4.3, 5.9}, {0.3, 1.9, 4.0}),
                                     wobble(t, {2.0, 1.4, 1.0}, {3.7, 4.9, 6.1}, {2.2, 0.7, 5.1}),
                                     wobble(t, {1.6, 1.2, 0.8}, {2.9, 4.1, 5.3}, {1.1, 3.3, 0.2})));
        break;
      case CameraPath::Pan:
        out.push_back(yaw_pitch_roll(120.0 * s, 10.0 * std::sin(effects::kPi * s),
                                     3.0 * std::sin(2 * effects::kPi * s)));
        break;
    }
  }
  return out;
}

double rotation_error_deg(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return a.normalized().angularDistance(b.normalized()) / kDegToRad;
}

OrientationErrors orientation_errors(const std::vector<Eigen::Quaterniond>& estimated,
                                     const std::vector<Eigen::Quaterniond>& truth) {
  OrientationErrors e;
  const std::size_t n = std::min(estimated.size(), truth.size());
  for (std::size_t i = 0; i < n; ++i) {
    const double a = rotation_error_deg(estimated[i], truth[i]);
    e.rms += a * a;
    e.max = std::max(e.max, a);
    e.last = a;
  }
  e.rms = n > 0 ? std::sqrt(e.rms / static_cast<double>(n)) : 0.0;
  return e;
}

SubjectErrors subject_errors(const std::vector<Eigen::Vector3d>& directions,
                             const std::vector<bool>& seen, const std::vector<SubjectPose>& truth) {
  SubjectErrors e;
  const std::size_t n = std::min({directions.size(), seen.size(), truth.size()});
  for (std::size_t f = 0; f < n; ++f) {
    if (!truth[f].visible) {
      if (seen[f]) e.hidden_seen.push_back(static_cast<std::int64_t>(f));
      continue;
    }
    if (!seen[f]) e.visible_lost.push_back(static_cast<std::int64_t>(f));
    const double a = effects::angle_between(directions[f], truth[f].centre()) / kDegToRad;
    e.rms += a * a;
    e.max = std::max(e.max, a);
    ++e.visible;
  }
  e.rms = e.visible > 0 ? std::sqrt(e.rms / e.visible) : 0.0;
  return e;
}

std::vector<SubjectPose> subject_path(SubjectMotion motion, int frames) {
  std::vector<SubjectPose> out;
  for (int i = 0; i < frames; ++i) {
    const double s = frames > 1 ? static_cast<double>(i) / (frames - 1) : 0.0;
    SubjectPose p;
    if (motion == SubjectMotion::Seam) {
      p.axes = effects::pose_rotation({{effects::wrap_azimuth_deg(150.0 + 60.0 * s), 10.0}, 0.0});
    } else if (motion == SubjectMotion::Pole) {
      p.axes = Eigen::AngleAxisd((55.0 + 70.0 * s) * kDegToRad, Eigen::Vector3d::UnitX())
                   .toRotationMatrix();
    } else if (motion == SubjectMotion::Turn) {
      p.axes = effects::pose_rotation({{-30.0 + 60.0 * s, 0.0}, 90.0 * s});
    } else {
      p.axes = effects::pose_rotation({{-20.0 + 30.0 * s, -5.0 + 10.0 * s}, 0.0});
      // Seen from a distance falling from 3.3 to 1 (in units where it is 20 degrees at 1).
      const double distance = 3.3 - 2.3 * s;
      p.size_deg = 2.0 * std::atan(std::tan(10.0 * kDegToRad) / distance) / kDegToRad;
      p.visible = s < 0.4 || s >= 0.6;
    }
    out.push_back(p);
  }
  return out;
}

cv::Mat subject_texture() {
  cv::RNG rng(20240531);
  cv::Mat blocks(8, 8, CV_8UC3), big, noise(64, 64, CV_8UC3), out;
  rng.fill(blocks, cv::RNG::UNIFORM, 0, 256);
  cv::resize(blocks, big, cv::Size(64, 64), 0, 0, cv::INTER_NEAREST);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 60);
  cv::add(big, noise, big);
  cv::GaussianBlur(big, out, cv::Size(0, 0), 0.8);
  return out;
}

cv::Mat draw_subject(const cv::Mat& background, const SubjectPose& pose, const cv::Mat& texture) {
  cv::Mat out = background.clone();
  if (!pose.visible) return out;
  const Eigen::Vector3d e1 = pose.axes.col(0), e2 = pose.axes.col(1), c = pose.centre();
  const double half = std::tan(0.5 * pose.size_deg * kDegToRad);
  const double reach = std::cos(std::atan(std::sqrt(2.0) * half));  // the corners' angle
  const int w = out.cols, h = out.rows;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Eigen::Vector3d n =
          effects::to_unit(effects::from_equirect_uv({(x + 0.5) / w, (y + 0.5) / h}));
      const double along = n.dot(c);
      if (along < reach - 1e-9) continue;
      const double px = n.dot(e1) / along / half, py = n.dot(e2) / along / half;
      if (std::abs(px) >= 1.0 || std::abs(py) >= 1.0) continue;
      cv::Mat sample;
      cv::getRectSubPix(texture, cv::Size(1, 1),
                        cv::Point2f(static_cast<float>((px + 1) / 2 * texture.cols - 0.5),
                                    static_cast<float>((1 - py) / 2 * texture.rows - 0.5)),
                        sample);
      out.at<cv::Vec3b>(y, x) = sample.at<cv::Vec3b>(0, 0);
    }
  return out;
}

}  // namespace vdfx::app::bench
