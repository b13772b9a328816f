/// @file
/// @brief Minimap: an equirect image of one parameter over the sphere, keyframe dots and the
/// outline of the current view's footprint. A press on a dot picks that keyframe.
///
/// Picking: while it shows keyframes the widget is interactive; a click (trigger pressed and
/// released on it) at a panel pixel within kPickRadius of a dot picks the nearest such dot.
/// value() is (picked index or -1, clicks so far), so every click reports a ValueChanged whose
/// new_value.x is the keyframe picked (-1: none under the ray), even the same one twice.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "effects/coords.h"
#include "ui/canvas.h"
#include "ui/widget.h"

namespace vdfx::ui {

class Minimap : public Widget {
 public:
  Minimap(std::string id, std::string title);
  /// A scalar field (CV_32FC1, equirect, row 0 = altitude +90) shown through the viridis colour
  /// map with lo..hi mapped to its ends. A field that maps to the image already shown changes
  /// nothing (playback of a frame-independent field redraws no map).
  void set_field(const cv::Mat& field, double lo, double hi);
  /// A ready-made colour image (BGR, equirect) instead of a field.
  void set_image(const cv::Mat& bgr);
  /// Keyframe dots; `highlighted` drawn larger (the nearest), `selected` ringed (the one being
  /// edited). Setting what is already shown changes nothing (no re-render).
  void set_keyframes(std::vector<effects::Direction> dirs, int highlighted = -1, int selected = -1);
  int selected() const { return selected_; }
  const std::vector<effects::Direction>& keyframes() const { return keyframes_; }
  /// The viewer's forward direction and field of view (degrees, full angles); unchanged values
  /// change nothing.
  void set_view(effects::Direction forward, double hfov_deg, double vfov_deg);
  /// Degrees of azimuth the video covers, centred on azimuth 0 (360, or 180 for VR180): the
  /// rest of the map is dimmed and hatched as "no picture there".
  void set_coverage(int coverage_deg);
  int coverage() const { return coverage_deg_; }
  bool interactive() const override { return enabled() && !keyframes_.empty(); }
  glm::dvec2 value() const override {
    return {static_cast<double>(picked_), static_cast<double>(clicks_)};
  }
  void click(glm::dvec2 p) override;
  /// The keyframe whose dot is nearest panel pixel p within kPickRadius (inside the map), or -1.
  int keyframe_at(glm::dvec2 p) const;
  /// Panel pixels around a dot's centre that pick it (a dot is 10-13 px; a ray held in a hand
  /// wobbles by more).
  static constexpr double kPickRadius = 28.0;
  void draw(DrawContext& ctx) const override;
  /// The equirect image's rectangle (2:1) inside the widget.
  Rect map_area() const;
  /// Panel pixel of a direction on the map.
  glm::dvec2 to_pixel(const effects::Direction& d) const;
  /// The footprint outline as map polylines in panel pixels, split where it wraps at +-180 deg.
  std::vector<std::vector<glm::dvec2>> footprint() const;

 private:
  std::string title_;
  cv::Mat image_;               //!< BGR
  mutable ScaledImage scaled_;  //!< image_ scaled to map_area()
  std::vector<effects::Direction> keyframes_;
  int highlighted_ = -1;
  int selected_ = -1;
  int picked_ = -1;  //!< the last click's keyframe
  int clicks_ = 0;
  effects::Direction view_{};
  double hfov_ = 90.0, vfov_ = 90.0;
  int coverage_deg_ = 360;
};

}  // namespace vdfx::ui
