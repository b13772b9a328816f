/// @file
/// @brief Plot: values over frames ("effect tracks") with axes, keyframe dots and a playhead.
#pragma once

#include <string>
#include <vector>

#include "ui/colour.h"
#include "ui/widget.h"

namespace vdfx::ui {

class Plot : public Widget {
 public:
  Plot(std::string id, std::string title, double y_min, double y_max,
       const char* y_format = "%.1f");
  /// One value per frame (frame i at index i).
  void set_values(std::vector<double> values);
  void set_range(double y_min, double y_max);
  void set_keyframes(std::vector<int> frames);
  /// Moves the playhead; only its old and new columns (line and a keyframe dot under it) are
  /// damaged.
  void set_playhead(int frame);
  bool interactive() const override { return false; }
  void draw(DrawContext& ctx) const override;
  /// The plotting area inside the axes.
  Rect plot_area() const;
  /// The pixels the playhead draws at a frame (empty when it draws none there).
  Rect playhead_area(int frame) const;

 private:
  std::string title_;
  double y_min_, y_max_;
  const char* y_format_;
  std::vector<double> values_;
  std::vector<int> keyframes_;
  int playhead_ = -1;
};

}  // namespace vdfx::ui
