/// @file
/// @brief The turning clip: the panorama turned column by column, its camera, its sidecar.
#include "app/bench/turning_clip.h"

#include <Eigen/Geometry>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "io/image_source.h"
#include "io/video_encoder.h"
#include "io/ycbcr.h"

namespace vdfx::app::bench {

effects::Quat camera_yaw(double deg) {
  return effects::from_eigen(
      Eigen::Quaterniond(Eigen::AngleAxisd(-deg * effects::kDegToRad, Eigen::Vector3d::UnitY())));
}

double turning_yaw_deg(int f, int frames, double turn_deg) {
  return turn_deg * f / frames;
}

effects::CameraMotion turning_camera(int frames, double turn_deg) {
  effects::CameraMotion c;
  c.source = effects::CameraMotion::Source::Given;
  for (int f = 0; f < frames; ++f)
    c.orientation.push_back(camera_yaw(turning_yaw_deg(f, frames, turn_deg)));
  return c;
}

effects::Direction video_direction(const effects::Direction& world, double yaw_deg) {
  return {effects::wrap_azimuth_deg(world.azimuth_deg - yaw_deg), world.altitude_deg};
}

cv::Mat interior_panorama(int width) {
  const cv::Mat rgb = io::load_image(kInteriorExr).rgb;
  cv::Mat out;
  cv::resize(rgb, out, cv::Size(width, width / 2), 0, 0, cv::INTER_AREA);
  return out;
}

cv::Mat turned_panorama(const cv::Mat& world, double yaw_deg) {
  // Video column x (centre at u = (x + 0.5) / w) shows world u + yaw / 360: world column x + s.
  const int w = world.cols;
  const double s = yaw_deg / 360.0 * w;
  const double fs = std::floor(s), t = s - fs;
  const int shift = static_cast<int>(fs);
  cv::Mat out(world.size(), world.type());
  for (int x = 0; x < w; ++x) {
    const int a = ((x + shift) % w + w) % w, b = (a + 1) % w;
    if (t == 0.0)
      world.col(a).copyTo(out.col(x));
    else
      cv::addWeighted(world.col(a), 1.0 - t, world.col(b), t, 0.0, out.col(x));
  }
  return out;
}

void write_turning_clip(const std::filesystem::path& path, const cv::Mat& world, int frames,
                        double turn_deg, int fps) {
  io::EncoderSettings s;
  s.codec = "libx264";
  s.width = world.cols;
  s.height = world.rows;
  s.frame_rate = {fps, 1};
  s.crf = 16;
  s.preset = "veryfast";
  auto enc = io::VideoEncoder::create(path, s);
  for (int f = 0; f < frames; ++f) {
    cv::Mat rgb8;
    turned_panorama(world, turning_yaw_deg(f, frames, turn_deg)).convertTo(rgb8, CV_8UC3, 255.0);
    enc->write(io::rgb_to_ycbcr(rgb8, s.ycbcr), f);
  }
  enc->finish();
}

io::Sidecar turning_sidecar(const io::VideoInfo& video, const effects::CameraMotion& camera,
                            const effects::Anchor& anchor) {
  io::Sidecar s = io::new_sidecar(video);
  const effects::Direction behind{effects::wrap_azimuth_deg(kRoomWindow.azimuth_deg + 180.0),
                                  -kRoomWindow.altitude_deg};
  effects::EffectTrack exposure;
  exposure.type = effects::EffectType::Exposure;
  exposure.anchor = anchor;
  exposure.keyframes = {{kRoomWindow, 0, {kWindowStops}}, {behind, 0, {0.0}}};
  s.effects.push_back(exposure);
  s.camera = camera;
  return s;
}

}  // namespace vdfx::app::bench
