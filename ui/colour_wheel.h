/// @file
/// @brief ColourWheel: a hue x saturation disc for the tint effect, and the conversions between
/// (hue, saturation) and the contract's normalised tint gain.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <string>

#include "ui/widget.h"

namespace vdfx::ui {

/// Tint gain of a hue (degrees) and saturation: the HSV colour at value 1, scaled by
/// effects::normalize_tint so that 0.25 r + 0.5 g + 0.25 b = 1. Saturation 0 gives (1, 1, 1).
Eigen::Vector3d tint_gain_from_hue_sat(double hue_deg, double sat);
/// The inverse for positive gains: (hue_deg in [0, 360), sat in [0, 1]); scale-invariant.
glm::dvec2 hue_sat_from_tint_gain(const Eigen::Vector3d& gain);

class ColourWheel : public Widget {
 public:
  ColourWheel(std::string id, std::string label, double hue_deg = 0.0, double sat = 0.0);
  double hue() const { return hue_; }
  double sat() const { return sat_; }
  /// hue wraps into [0, 360), sat clamps to [0, 1].
  void set_hue_sat(double hue_deg, double sat);
  Eigen::Vector3d tint_gain() const { return tint_gain_from_hue_sat(hue_, sat_); }
  glm::dvec2 value() const override { return {hue_, sat_}; }
  bool focusable() const override { return true; }
  bool steppable() const override { return true; }
  bool draggable() const override { return true; }
  /// The disc follows the pointer: angle (0 deg = right, counter-clockwise) is hue, distance
  /// from the centre over the radius is saturation.
  void drag_to(glm::dvec2 p) override;
  /// x turns the hue (120 deg/s at full deflection), y changes saturation (0.5/s).
  void thumbstick(glm::dvec2 stick, double dt) override;
  /// A push turns the hue by kHueStepDeg (x) or changes saturation by kSatStep (y).
  void step(glm::ivec2 direction) override;
  static constexpr double kHueStepDeg = 5.0;
  static constexpr double kSatStep = 0.05;
  void draw(DrawContext& ctx) const override;
  glm::dvec2 disc_centre() const;
  double disc_radius() const;

 private:
  std::string label_;
  double hue_, sat_;
  /// The disc image depends only on its radius: built once per size, not per draw.
  mutable cv::Mat wheel_;
  mutable double wheel_radius_ = -1.0;
};

}  // namespace vdfx::ui
