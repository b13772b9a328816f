/// @file
/// @brief Slider1D (one value in a range) and Pad2D (two values on a square, e.g. vignette
/// radius x falloff). Both follow the pointer while held and move with the thumbstick when
/// focused: full deflection sweeps the whole range in kStickSweepSeconds.
#pragma once

#include <string>

#include "ui/widget.h"

namespace vdfx::ui {

inline constexpr double kStickSweepSeconds = 3.0;

/// One axis of a slider or pad: range, snapping step (0 = continuous), display format.
struct Axis {
  double min = 0.0;
  double max = 1.0;
  double step = 0.0;
  const char* format = "%.2f";  //!< printf format of the value text
  std::string unit;             //!< appended to the value text ("°", " stops")
  std::string name;             //!< axis name shown by Pad2D ("radius")
  bool log = false;             //!< the track is logarithmic (min > 0); steps are 1/kLogSteps of it

  double clamp_snap(double v) const;
  std::string text(double v) const;
  /// Where v sits along the track, 0 at min, 1 at max (logarithmic when log).
  double fraction(double v) const;
  double at_fraction(double t) const;
  /// v moved by n steps: n * step, or n / kLogSteps of the track when log or continuous.
  double stepped(double v, int n) const;
  /// The step as shown next to the value ("step 0.1", "step x1.07").
  std::string step_text() const;
  static constexpr int kLogSteps = 100;
};

class Slider1D : public Widget {
 public:
  /// origin: where the accent fill starts (the effect's neutral value), clamped to the range.
  Slider1D(std::string id, std::string label, Axis axis, double value, double origin);
  double get() const { return value_; }
  /// Clamped and snapped.
  void set_value(double v);
  const Axis& axis() const { return axis_; }
  glm::dvec2 value() const override { return {value_, 0.0}; }
  bool focusable() const override { return true; }
  bool steppable() const override { return true; }
  bool draggable() const override { return true; }
  void drag_to(glm::dvec2 p) override;
  std::optional<glm::dvec2> drag_point() const override;
  void thumbstick(glm::dvec2 stick, double dt) override;
  void step(glm::ivec2 direction) override;
  void draw(DrawContext& ctx) const override;
  /// The track's horizontal extent in panel pixels (value min at x0, max at x1).
  double track_x0() const;
  double track_x1() const;

 private:
  std::string label_;
  Axis axis_;
  double value_;
  double origin_;
  double pending_ = 0.0;  //!< thumbstick motion not yet a whole step
};

class Pad2D : public Widget {
 public:
  Pad2D(std::string id, std::string label, Axis x, Axis y, glm::dvec2 value);
  glm::dvec2 get() const { return value_; }
  void set_value(glm::dvec2 v);
  glm::dvec2 value() const override { return value_; }
  bool focusable() const override { return true; }
  bool steppable() const override { return true; }
  bool draggable() const override { return true; }
  void drag_to(glm::dvec2 p) override;
  std::optional<glm::dvec2> drag_point() const override;
  void thumbstick(glm::dvec2 stick, double dt) override;
  void step(glm::ivec2 direction) override;
  void draw(DrawContext& ctx) const override;
  /// The square the value maps onto (x min at left, y min at the bottom).
  Rect area() const;

 private:
  std::string label_;
  Axis x_, y_;
  glm::dvec2 value_;
  glm::dvec2 pending_{0.0};
};

}  // namespace vdfx::ui
