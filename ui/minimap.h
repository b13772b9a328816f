/// @file
/// @brief Minimap: an equirect image of one parameter over the sphere, keyframe dots and the
/// outline of the current view's footprint.
#pragma once

#include "effects/coords.h"
#include "ui/canvas.h"
#include "ui/widget.h"

#include <opencv2/core.hpp>

#include <string>
#include <vector>

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
  bool interactive() const override { return false; }
  void draw(DrawContext& ctx) const override;
  /// The equirect image's rectangle (2:1) inside the widget.
  Rect map_area() const;
  /// Panel pixel of a direction on the map.
  glm::dvec2 to_pixel(const effects::Direction& d) const;
  /// The footprint outline as map polylines in panel pixels, split where it wraps at +-180 deg.
  std::vector<std::vector<glm::dvec2>> footprint() const;

 private:
  std::string title_;
  cv::Mat image_;  //!< BGR
  mutable ScaledImage scaled_;  //!< image_ scaled to map_area()
  std::vector<effects::Direction> keyframes_;
  int highlighted_ = -1;
  int selected_ = -1;
  effects::Direction view_{};
  double hfov_ = 90.0, vfov_ = 90.0;
};

}  // namespace vdfx::ui
