/// @file
/// @brief The world-space layout of one flare for one frame, computed once from the head
/// (cyclopean) pose and drawn into each eye from that eye's own pose (shared/guide/flare-grain.md,
/// stereo rules 1 and 2; docs/flare.md, "Geometry").
///
/// A = head position, g = gaze (head forward), l = light direction, theta = angle(g, l).
/// - headset:     plane perpendicular to g at distance d;  B = A + d g, C = A + (d / g.l) l.
/// - directional: plane perpendicular to l at distance D;  C = A + D l, B = A + (D / g.l) g.
/// C is where the light's ray meets the plane, B where the gaze does. The glare (a bright core and
/// a wide faint halo) sits at C; ring i sits at C + s_i (B - C) with a fixed s_i, so the rings
/// splay from the light through the view centre and beyond, further apart as theta grows. Every
/// element's radius is its angular radius times the plane distance (constant angular size).
/// The whole flare is scaled by intensity x fade(theta).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <span>
#include <vector>

#include "effects/flare.h"
#include "effects/head_pose.h"

namespace vdfx::effects {

/// Radial profiles of the elements (docs/flare.md, "Elements"); the GLSL in flare_shaders.cpp is
/// the same function.
enum class FlareShape {
  Glow = 0,  //!< (1 - rho^2)^4 for rho < 1: glare core and halo
  Ring = 1,  //!< a soft rim at rho = 1 over a faint disc, per channel at its own radius
};

/// Ring profile constants: rim half-width and the interior fill's level (rho units).
inline constexpr double kRingRimWidth = 0.15;
inline constexpr double kRingFill = 0.4;

/// One element: a radially symmetric sprite in the flare plane.
struct FlareElement {
  FlareShape shape = FlareShape::Glow;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  //!< world (LOCAL), metres
  double radius = 0.0;                               //!< metres: the profile's rho = 1
  Eigen::Vector3d colour = Eigen::Vector3d::Zero();  //!< added RGB at the profile's peak (1)
  /// Ring chromatic scattering: channel c is drawn at radius (1 + chroma * (1, 0, -1)_c) * radius,
  /// red outermost, as analogue lens ghosts separate their colours.
  double chroma = 0.0;
};

/// rho (in units of the element's radius) beyond which the element adds exactly nothing.
double element_support(const FlareElement& e);

/// The element's added colour at rho = (distance from its centre in the plane) / radius.
Eigen::Vector3d element_profile(const FlareElement& e, double rho);

struct FlareLayout {
  FlareStyle style = FlareStyle::Directional;
  Eigen::Vector3d head = Eigen::Vector3d::Zero();    //!< A
  Eigen::Vector3d gaze = Eigen::Vector3d::Zero();    //!< g (unit)
  Eigen::Vector3d light = Eigen::Vector3d::Zero();   //!< l (unit)
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  //!< plane normal (g or l), unit
  Eigen::Vector3d axis_u = Eigen::Vector3d::Zero();  //!< in-plane orthonormal basis
  Eigen::Vector3d axis_v = Eigen::Vector3d::Zero();
  Eigen::Vector3d light_point = Eigen::Vector3d::Zero();  //!< C
  Eigen::Vector3d view_point = Eigen::Vector3d::Zero();   //!< B
  double plane_distance = 0.0;  //!< from A to the plane along its normal (d or D)
  double theta_deg = 0.0;
  double fade = 0.0;                   //!< fade(theta) in [0, 1]
  double intensity = 0.0;              //!< the keyframed intensity (0..4)
  std::vector<FlareElement> elements;  //!< glare core, glare halo, then the rings
};

/// The fade factor: 1 for theta <= fade - ramp/2, 0 for theta >= fade + ramp/2, smoothstep
/// (3t^2 - 2t^3) between; ramp 0 is a hard edge at fade (1 up to and including it).
double flare_fade(double theta_deg, double fade_deg, double ramp_deg);

/// Ring i's place s_i on the line C + s (B - C), angular radius (degrees), colour and peak
/// level: a fixed table (rings use its first `rings` rows).
struct RingSpec {
  double s;
  double angular_radius_deg;
  double r, g, b;
  double level;
};
std::span<const RingSpec> ring_table();  //!< kMaxFlareRings rows

/// Glare core and halo: angular radii and levels.
inline constexpr double kGlareCoreDeg = 4.0;
inline constexpr double kGlareHaloDeg = 18.0;

/// The layout of one flare, or nullopt when it adds nothing (intensity x fade is 0, or the light
/// is not in front of the gaze). `light` need not be normalised (non-zero).
std::optional<FlareLayout> layout_flare(FlareStyle style, const FlareSettings& settings,
                                        const HeadPose& head, const Eigen::Vector3d& light,
                                        double intensity);

}  // namespace vdfx::effects
