/// @file
/// @brief MenuList: a list of items with one selection and scrolling, in one column or a grid of
/// several (items row by row: the effect menu's two columns, a style switch's cells).
#pragma once

#include <string>
#include <vector>

#include "ui/widget.h"

namespace vdfx::ui {

class MenuList : public Widget {
 public:
  /// row_height in pixels (the theme's row_height suits the pointer).
  MenuList(std::string id, std::vector<std::string> items, int selected = 0,
           double row_height = 76.0, int columns = 1);
  const std::vector<std::string>& items() const { return items_; }
  void set_items(std::vector<std::string> items);
  int selected() const { return selected_; }
  /// Clamped to the items; scrolls it into view.
  void select(int index);
  int columns() const { return columns_; }
  /// Rows the items fill (ceil(items / columns)).
  int rows() const;
  /// First visible row.
  int scroll() const { return scroll_; }
  void set_scroll(int first);
  int visible_rows() const;
  /// Item under a panel pixel, or -1.
  int row_at(glm::dvec2 p) const;
  /// Where item `index` is drawn, in panel pixels (its row need not be visible).
  Rect cell(int index) const;

  glm::dvec2 value() const override { return {static_cast<double>(selected_), 0.0}; }
  bool focusable() const override { return true; }
  bool steppable() const override { return true; }
  void hover_at(glm::dvec2 p) override;
  void click(glm::dvec2 p) override;
  /// A push moves the selection one row (up = the item above; in a grid left / right = the
  /// neighbouring item); held on (past the pointer's repeat delay, past half deflection) it moves
  /// a row every kRepeatSeconds.
  void step(glm::ivec2 direction) override;
  void thumbstick(glm::dvec2 stick, double dt) override;
  void draw(DrawContext& ctx) const override;

  static constexpr double kRepeatSeconds = 0.2;

 private:
  void layout_changed() override { select(selected_); }
  double bar_width() const;
  std::vector<std::string> items_;
  int selected_;
  double row_h_;
  int columns_;
  int scroll_ = 0;
  int hover_row_ = -1;
  double held_ = 0.0;  //!< seconds held past half deflection not yet turned into rows
};

}  // namespace vdfx::ui
