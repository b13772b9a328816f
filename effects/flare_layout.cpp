/// @file
/// @brief Flare geometry: fade, the ring table, element profiles and the per-frame layout.
#include "effects/flare_layout.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace vdfx::effects {

namespace {

// A hand-designed "lens": positions along the light -> view-centre line (0 at the light, 1 at the
// view centre, beyond 1 past it), angular radii, tints and levels. Big ghosts are faint, small
// ones brighter, and the order is mixed so that any first n rows spread over the whole line.
constexpr std::array<RingSpec, kMaxFlareRings> kRings{{
    {0.45, 2.00, 1.00, 0.70, 0.40, 0.55},
    {0.72, 3.60, 0.50, 1.00, 0.60, 0.25},
    {1.22, 1.40, 0.60, 0.80, 1.00, 0.625},
    {1.48, 5.20, 0.80, 0.55, 1.00, 0.175},
    {1.78, 2.70, 1.00, 0.90, 0.55, 0.325},
    {2.10, 7.50, 0.45, 0.85, 1.00, 0.15},
    {0.30, 1.00, 1.00, 0.85, 0.60, 0.625},
    {0.95, 2.30, 0.70, 1.00, 0.80, 0.3},
    {1.10, 4.20, 1.00, 0.60, 0.80, 0.175},
    {1.62, 1.20, 0.55, 0.70, 1.00, 0.55},
    {0.58, 6.00, 0.90, 1.00, 0.70, 0.125},
    {1.95, 1.80, 1.00, 0.75, 0.50, 0.4},
    {0.85, 1.10, 0.60, 0.90, 1.00, 0.5},
    {1.35, 3.00, 1.00, 0.80, 0.70, 0.225},
    {2.30, 4.50, 0.70, 0.70, 1.00, 0.175},
    {0.18, 2.50, 1.00, 0.95, 0.85, 0.25},
}};

constexpr double kRingChroma = 0.06;
const Eigen::Vector3d kCoreColour(0.90, 0.84, 0.74);  // warm white, level 0.9
const Eigen::Vector3d kHaloColour(0.15, 0.13, 0.105);

double smoothstep(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// (1 - x^2)^2 on |x| < 1: C1 at its ends, so the sprites have no visible edge and the quads that
// bound them (element_support) lose nothing.
double bump(double x) {
  const double a = 1.0 - x * x;
  return a > 0.0 ? a * a : 0.0;
}

double ring_channel(double rho) {
  return bump((rho - 1.0) / kRingRimWidth) +
         kRingFill * (1.0 - smoothstep(1.0 - kRingRimWidth, 1.0, rho));
}

}  // namespace

std::span<const RingSpec> ring_table() {
  return kRings;
}

double flare_fade(double theta_deg, double fade_deg, double ramp_deg) {
  if (ramp_deg <= 0.0) return theta_deg <= fade_deg ? 1.0 : 0.0;
  return 1.0 - smoothstep(fade_deg - 0.5 * ramp_deg, fade_deg + 0.5 * ramp_deg, theta_deg);
}

double element_support(const FlareElement& e) {
  return e.shape == FlareShape::Glow ? 1.0 : (1.0 + kRingRimWidth) * (1.0 + std::abs(e.chroma));
}

Eigen::Vector3d element_profile(const FlareElement& e, double rho) {
  if (e.shape == FlareShape::Glow) {
    const double a = bump(rho);
    return e.colour * (a * a);
  }
  Eigen::Vector3d out;
  for (int c = 0; c < 3; ++c) {
    const double scale = 1.0 + e.chroma * static_cast<double>(1 - c);  // R +chroma, B -chroma
    out[c] = e.colour[c] * ring_channel(rho / scale);
  }
  return out;
}

std::optional<FlareLayout> layout_flare(FlareStyle style, const FlareSettings& settings,
                                        const HeadPose& head, const Eigen::Vector3d& light,
                                        double intensity) {
  FlareLayout out;
  out.style = style;
  out.head = head.position;
  out.gaze = head.forward().normalized();
  out.light = light.normalized();
  out.theta_deg = angle_between(out.gaze, out.light) * kRadToDeg;
  out.fade = flare_fade(out.theta_deg, settings.fade_deg, settings.ramp_deg);
  out.intensity = intensity;
  const double level = intensity * out.fade;
  const double gl = out.gaze.dot(out.light);
  if (!(level > 0.0) || !(gl > 0.0)) return std::nullopt;

  const Eigen::Vector3d& A = out.head;
  const double dist = settings.plane_m;
  out.plane_distance = dist;
  if (style == FlareStyle::Headset) {
    out.normal = out.gaze;
    out.view_point = A + dist * out.gaze;
    out.light_point = A + (dist / gl) * out.light;
  } else {
    out.normal = out.light;
    out.light_point = A + dist * out.light;
    out.view_point = A + (dist / gl) * out.gaze;
  }
  // In-plane axes from the head's right axis (Gram-Schmidt): never parallel to the normal, since
  // the normal is within 85 degrees of the gaze, which is perpendicular to the head's right.
  const Eigen::Vector3d right = head.orientation.col(0);
  out.axis_u = (right - right.dot(out.normal) * out.normal).normalized();
  out.axis_v = out.normal.cross(out.axis_u);

  const auto radius = [&](double deg) { return dist * std::tan(deg * kDegToRad); };
  out.elements.push_back(
      {FlareShape::Glow, out.light_point, radius(kGlareCoreDeg), level * kCoreColour, 0.0});
  out.elements.push_back(
      {FlareShape::Glow, out.light_point, radius(kGlareHaloDeg), level * kHaloColour, 0.0});
  const int rings = std::clamp(settings.rings, 0, kMaxFlareRings);
  for (int i = 0; i < rings; ++i) {
    const RingSpec& r = kRings[static_cast<std::size_t>(i)];
    const Eigen::Vector3d centre = out.light_point + r.s * (out.view_point - out.light_point);
    out.elements.push_back({FlareShape::Ring, centre, radius(r.angular_radius_deg),
                            level * r.level * Eigen::Vector3d(r.r, r.g, r.b), kRingChroma});
  }
  return out;
}

}  // namespace vdfx::effects
