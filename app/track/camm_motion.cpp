/// @file
/// @brief camm_motion: CAMM records to one orientation per frame (camm_motion.h).
#include "app/track/camm_motion.h"

#include <algorithm>

#include "io/input_error.h"

namespace vdfx::app::track {
namespace {

Eigen::Vector3d vec(const io::CammRecord& r) {
  return {r.value[0], r.value[1], r.value[2]};
}

Eigen::Quaterniond from_angle_axis(const Eigen::Vector3d& v) {
  const double angle = v.norm();
  if (angle < 1e-15) return Eigen::Quaterniond::Identity();
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, v / angle));
}

struct Timed {
  double t;
  Eigen::Quaterniond q;
};

/// The orientation at time t: slerp between the samples around it, the ends held.
Eigen::Quaterniond at(const std::vector<Timed>& s, double t) {
  const auto next =
      std::upper_bound(s.begin(), s.end(), t, [](double x, const Timed& a) { return x < a.t; });
  if (next == s.begin()) return s.front().q;
  if (next == s.end()) return s.back().q;
  const Timed& a = *(next - 1);
  const Timed& b = *next;
  const double span = b.t - a.t;
  return span > 0 ? a.q.slerp((t - a.t) / span, b.q) : b.q;
}

std::vector<Timed> integrate_gyro(const std::vector<io::CammRecord>& gyro) {
  std::vector<Timed> out{{gyro.front().time_s, Eigen::Quaterniond::Identity()}};
  for (std::size_t k = 1; k < gyro.size(); ++k) {
    const double dt = gyro[k].time_s - gyro[k - 1].time_s;
    const Eigen::Vector3d w = 0.5 * (vec(gyro[k - 1]) + vec(gyro[k]));
    // Body rates: the turn is about the camera's own axes, so it multiplies on the right.
    Eigen::Quaterniond q = out.back().q * from_angle_axis(w * dt);
    q.normalize();
    out.push_back({gyro[k].time_s, q});
  }
  return out;
}

}  // namespace

const char* camm_kind_text(CammMotion::Kind kind) {
  return kind == CammMotion::Kind::AngleAxis ? "angle-axis orientations"
                                             : "gyroscope samples (integrated)";
}

CammMotion camm_motion(const io::CammTrack& track, const std::vector<double>& frame_times_s,
                       const std::string& file) {
  CammMotion out;
  std::vector<Timed> samples;
  if (!track.angle_axis.empty()) {
    out.kind = CammMotion::Kind::AngleAxis;
    out.records = track.angle_axis.size();
    for (const io::CammRecord& r : track.angle_axis)
      samples.push_back({r.time_s, from_angle_axis(vec(r))});
  } else if (!track.gyro.empty()) {
    out.kind = CammMotion::Kind::Gyro;
    out.records = track.gyro.size();
    samples = integrate_gyro(track.gyro);
  } else {
    throw io::InputError(file +
                         ": the CAMM track has neither orientations (type 0) nor gyroscope "
                         "samples (type 2)");
  }
  if (frame_times_s.empty()) return out;
  const Eigen::Quaterniond first_inverse = at(samples, frame_times_s.front()).conjugate();
  Eigen::Quaterniond last = Eigen::Quaterniond::Identity();
  for (const double t : frame_times_s) {
    Eigen::Quaterniond q = first_inverse * at(samples, t);
    q.normalize();
    if (q.dot(last) < 0) q.coeffs() *= -1.0;
    out.orientation.push_back(q);
    last = q;
  }
  return out;
}

}  // namespace vdfx::app::track
