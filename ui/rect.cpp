/// @file
/// @brief Layout helpers of rect.h.
#include "ui/rect.h"

namespace vdfx::ui {

Rect Stack::next(double extent) {
  Rect r = axis_ == Axis::Vertical ? Rect{area_.x, area_.y + used_, area_.w, extent}
                                   : Rect{area_.x + used_, area_.y, extent, area_.h};
  used_ += extent + gap_;
  return r;
}

Rect Stack::rest() const {
  if (axis_ == Axis::Vertical)
    return {area_.x, area_.y + used_, area_.w, std::max(0.0, area_.h - used_)};
  return {area_.x + used_, area_.y, std::max(0.0, area_.w - used_), area_.h};
}

Rect split_cols(const Rect& r, int n, int index, double gap) {
  const double w = (r.w - gap * (n - 1)) / n;
  return {r.x + index * (w + gap), r.y, w, r.h};
}

Rect split_rows(const Rect& r, int n, int index, double gap) {
  const double h = (r.h - gap * (n - 1)) / n;
  return {r.x, r.y + index * (h + gap), r.w, h};
}

}  // namespace vdfx::ui
