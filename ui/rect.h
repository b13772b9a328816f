/// @file
/// @brief Axis-aligned rectangles in panel pixels (origin top-left, +y down) and layout helpers.
#pragma once

#include <algorithm>
#include <glm/vec2.hpp>

namespace vdfx::ui {

struct Rect {
  double x = 0.0;  //!< left edge, pixels
  double y = 0.0;  //!< top edge, pixels
  double w = 0.0;
  double h = 0.0;

  double right() const { return x + w; }
  double bottom() const { return y + h; }
  glm::dvec2 centre() const { return {x + 0.5 * w, y + 0.5 * h}; }
  bool contains(glm::dvec2 p) const { return p.x >= x && p.x < x + w && p.y >= y && p.y < y + h; }
  bool empty() const { return w <= 0.0 || h <= 0.0; }
  /// Shrinks by d on every side (never below zero size).
  Rect inset(double d) const { return inset(d, d); }
  Rect inset(double dx, double dy) const {
    return {x + dx, y + dy, std::max(0.0, w - 2 * dx), std::max(0.0, h - 2 * dy)};
  }
  Rect intersect(const Rect& o) const {
    const double l = std::max(x, o.x), t = std::max(y, o.y);
    const double r = std::min(right(), o.right()), b = std::min(bottom(), o.bottom());
    return {l, t, std::max(0.0, r - l), std::max(0.0, b - t)};
  }
  bool operator==(const Rect&) const = default;
};

/// Hands out consecutive rows (or columns) of a rectangle, top to bottom (left to right), with a
/// fixed gap: enough layout for panels of stacked widgets.
class Stack {
 public:
  enum class Axis { Vertical, Horizontal };
  Stack(Rect area, double gap, Axis axis = Axis::Vertical) : area_(area), gap_(gap), axis_(axis) {}
  /// The next slot of the given extent (height for vertical stacks, width for horizontal).
  Rect next(double extent);
  /// Everything not yet handed out.
  Rect rest() const;

 private:
  Rect area_;
  double gap_;
  Axis axis_;
  double used_ = 0.0;
};

/// Splits a rectangle into n equal columns (or rows) separated by gap.
Rect split_cols(const Rect& r, int n, int index, double gap);
Rect split_rows(const Rect& r, int n, int index, double gap);

}  // namespace vdfx::ui
