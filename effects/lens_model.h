/// @file
/// @brief Radial lens distortion of a headset eyepiece: forward model, two inverses, the largest
/// radius where it can be inverted, and lateral chromatic aberration (LCA).
///
/// Units. All vectors here are in the eye's tangent plane: (x, y) = (tan of the angle to the
/// right of the optical axis, tan of the angle above it). The polynomial works on the normalised
/// radius r = |t| / R, where R (LensParams::radius, in tangent units) is the profile's
/// normalisation radius (R = 1 is plain tan-angles, as Cardboard uses).
///
/// Direction of the model (docs/lens.md): r_u is the radius of a point of the ideal, undistorted
/// eye image (what the user should perceive), r_d the radius on the panel where that point must
/// be drawn so the lens shows it at r_u:
///     r_d = f(r_u) = r_u + c1 r_u^3 + c2 r_u^5      (Cardboard's r (1 + K1 r^2 + K2 r^4)).
/// So f is the "through-the-lens" mapping (looking at r_u, the eye sees the panel at f(r_u)) and
/// the pre-distortion shader needs the inverse (panel pixel -> source point of the eye image).
///
/// Validity. f is monotonic up to the first root of f'(r) = 1 + 3 c1 r^2 + 5 c2 r^4. Beyond it the
/// panel would show the image folded; every function returns "invalid" there (the compositor
/// draws black) instead of folding.
///
/// LCA. Channel c (0 = R, 1 = G, 2 = B) of the panel is seen as if the panel were scaled by
/// lca_scale[c] about the lens centre: perceived r_u sees channel c at panel radius
/// lca_scale[c] * f(r_u). The inverse LCA correction samples channel c of panel radius r_d at
/// f^-1(r_d / lca_scale[c]), so the three channels of one image point land together.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>

#include "effects/view_camera.h"  // TanRect

namespace vdfx::effects {

struct LensParams {
  double c1 = 0.0;                           //!< coefficient of r^3
  double c2 = 0.0;                           //!< coefficient of r^5
  double radius = 1.0;                       //!< normalisation radius R, tangent units, > 0
  std::array<double, 3> lca_scale{1, 1, 1};  //!< per-channel (R, G, B) radial scale, > 0
};

/// Which inverse of f the caller wants: the iterative exact root, or the closed-form
/// approximation after Mallon and Whelan (ICPR 2004), cheaper and less accurate.
enum class InverseMethod { Newton, ClosedForm };

/// Outcome of the iterative inverse; iterations is how many Newton or bisection steps ran.
struct InverseResult {
  double r_u = 0.0;
  int iterations = 0;
  bool valid = false;  //!< false beyond the monotonic limit (or for a negative/NaN radius)
};

class LensModel {
 public:
  /// Iteration cap of the Newton solve. Cardboard's secant loop has none and can spin forever on
  /// a radius it cannot reach; with a bracket and bisection fallback 60 steps always suffice for
  /// double precision (each bisection halves the bracket).
  static constexpr int kMaxIterations = 60;

  LensModel() : LensModel(LensParams{}) {}
  /// Throws std::invalid_argument for a non-positive radius or LCA scale, or non-finite values.
  explicit LensModel(const LensParams& params);

  const LensParams& params() const { return params_; }

  // --- The radial polynomial, on normalised radii ---------------------------------------------
  double forward(double r_u) const;
  double derivative(double r_u) const;
  /// Largest r_u where f is monotonic (first root of f'); +infinity when f' never reaches 0.
  double max_undistorted_radius() const { return r_u_max_; }
  /// f(max_undistorted_radius()): panel radii at or beyond it have no inverse.
  double max_distorted_radius() const { return r_d_max_; }
  /// Exact inverse: Newton from the closed-form guess, bisection whenever a step leaves the
  /// bracket, at most kMaxIterations steps, converged to ~1 ulp.
  InverseResult inverse_newton(double r_d) const;
  /// Mallon-Whelan closed form; nullopt beyond the monotonic limit.
  std::optional<double> inverse_closed_form(double r_d) const;
  std::optional<double> inverse(double r_d, InverseMethod method) const;

  // --- Tangent-plane points (tangent units, not normalised) -----------------------------------
  /// Through the lens: the panel point where the eye, looking at image point t_u, sees channel c.
  /// nullopt beyond the monotonic limit.
  std::optional<Eigen::Vector2d> view_to_panel(const Eigen::Vector2d& t_u, int channel) const;
  /// The image point at which channel c of panel point t_d is perceived (inverse of the above).
  std::optional<Eigen::Vector2d> panel_to_view(const Eigen::Vector2d& t_d, int channel,
                                               InverseMethod method) const;
  /// What the pre-distortion samples for channel c of panel point t_d: panel_to_view with the
  /// channel's scale when lca_correction is on, with scale 1 (all channels alike) when off.
  std::optional<Eigen::Vector2d> source_for_panel(const Eigen::Vector2d& t_d, int channel,
                                                  bool lca_correction, InverseMethod method) const;

 private:
  std::optional<Eigen::Vector2d> scaled_inverse(const Eigen::Vector2d& t_d, double scale,
                                                InverseMethod method) const;
  LensParams params_;
  double r_u_max_;
  double r_d_max_;
};

/// One eye's panel viewport and lens. The panel viewport and the rendered eye image share one
/// linear pixel <-> tangent map (the FOV rectangle spread over width x height pixels), so the lens
/// centre sits on the panel where the optical axis is in the image. Pixel coordinates are
/// continuous, x right, y down, pixel (i, j) has its centre at (i + 0.5, j + 0.5); UVs are pixel
/// coordinates divided by (width, height).
struct EyeLens {
  int width = 1;
  int height = 1;
  TanRect fov;
  LensModel lens;

  Eigen::Vector2d pixel_to_tan(const Eigen::Vector2d& px) const;
  Eigen::Vector2d tan_to_pixel(const Eigen::Vector2d& t) const;
  Eigen::Vector2d tan_to_uv(const Eigen::Vector2d& t) const;
  /// The lens centre (optical axis) in pixels.
  Eigen::Vector2d centre_pixel() const { return tan_to_pixel({0.0, 0.0}); }
};

/// Per-channel sample positions for one panel pixel: UV in the undistorted eye image; a channel is
/// invalid beyond the monotonic limit (draw black). UVs outside [0, 1] are valid but off-image.
struct ChannelSamples {
  std::array<Eigen::Vector2d, 3> uv;
  std::array<bool, 3> valid{false, false, false};
};

/// What the pre-distortion shader samples for panel pixel position px (continuous pixels).
ChannelSamples panel_source_uv(const EyeLens& eye, const Eigen::Vector2d& px, bool lca_correction,
                               InverseMethod method = InverseMethod::Newton);

/// Through-the-lens simulation: the panel pixel position where the eye, looking at image pixel
/// position view_px, sees channel c; nullopt beyond the monotonic limit.
std::optional<Eigen::Vector2d> through_lens_panel_px(const EyeLens& eye,
                                                     const Eigen::Vector2d& view_px, int channel);

}  // namespace vdfx::effects
