/// @file
/// @brief The retained widget base class and the events widgets produce.
///
/// A widget has a stable id, a layout rectangle in panel pixels and interaction state. Widgets
/// never emit events themselves: the interaction layer (interaction.h) calls press/drag/click/
/// thumbstick hooks and turns changes of value() into events, so every widget reports the same
/// way. Every visible change bumps revision(), which is how a panel knows to re-render.
#pragma once

#include <algorithm>
#include <cstdint>
#include <glm/ext/vector_int2.hpp>
#include <glm/vec2.hpp>
#include <optional>
#include <string>

#include "ui/rect.h"

namespace vdfx::ui {

class Canvas;
struct Theme;
struct FontSet;

enum class EventKind {
  Clicked,       //!< trigger pressed and released on the same widget
  ValueChanged,  //!< old_value -> new_value
  DragBegin,     //!< a drag or thumbstick gesture starts; new_value = value at the start
  DragEnd,       //!< it ends; old_value = value at the start, new_value = final value
};

/// Values are two numbers wide so one event type fits every widget: Slider1D (value, 0),
/// Pad2D (x, y), ColourWheel (hue_deg, sat), Toggle (0/1, 0), MenuList (index, 0),
/// TimelineStrip (frame, 0). A DragBegin/DragEnd pair brackets one undo step.
class Widget;

struct Event {
  std::string panel;
  std::string widget;
  EventKind kind = EventKind::Clicked;
  glm::dvec2 old_value{0.0};
  glm::dvec2 new_value{0.0};
  /// The widget itself: programs match events against the widgets they hold (typed), not ids.
  const Widget* source = nullptr;
};

struct DrawContext {
  Canvas& canvas;
  const Theme& theme;
  const FontSet& fonts;
};

class Widget {
 public:
  explicit Widget(std::string id) : id_(std::move(id)) {}
  virtual ~Widget() = default;
  Widget(const Widget&) = delete;
  Widget& operator=(const Widget&) = delete;

  const std::string& id() const { return id_; }
  const Rect& rect() const { return rect_; }
  void set_rect(const Rect& r) {
    if (rect_ == r) return;
    rect_ = r;
    touch();
    layout_changed();
  }

  bool hovered() const { return hovered_; }
  bool pressed() const { return pressed_; }
  bool focused() const { return focused_; }
  bool enabled() const { return enabled_; }
  void set_hovered(bool v) { set(hovered_, v); }
  void set_pressed(bool v) { set(pressed_, v); }
  void set_focused(bool v) { set(focused_, v); }
  void set_enabled(bool v) { set(enabled_, v); }

  /// Bumped by every change that alters the widget's pixels.
  std::uint64_t revision() const { return revision_; }

  /// Whether the pointer can press it at all (labels and plots cannot).
  virtual bool interactive() const { return enabled_; }
  /// Whether a press focuses it for thumbstick input.
  virtual bool focusable() const { return false; }
  /// Whether the thumbstick changes its value (step / thumbstick): then it takes the stick while
  /// the pointer is over it, without a click first.
  virtual bool steppable() const { return false; }
  /// Whether a press starts a drag whose value follows the pointer (drag_to) while held.
  virtual bool draggable() const { return false; }
  /// The value events report (see Event).
  virtual glm::dvec2 value() const { return glm::dvec2(0.0); }
  /// Hit test in panel pixels.
  virtual bool hit(glm::dvec2 p) const { return rect_.contains(p); }
  /// Everything draw() may touch: rect() grown by kPaintMargin, since focus rings, thumbs and
  /// markers reach a few pixels past it (the colour wheel's marker 8.5 px, the strip's focus
  /// ring 6.5 px). A widget drawing farther out must override this, or partial re-renders
  /// (Panel::dirty_rects) leave stale pixels behind.
  virtual Rect paint_bounds() const { return rect_.inset(-kPaintMargin); }
  static constexpr double kPaintMargin = 12.0;
  /// Whether every change since the panel last drew this widget was reported with an area
  /// (touch(area)); then damage() bounds them, else the whole paint_bounds() must be redrawn.
  bool damage_is_partial() const { return !damage_all_; }
  /// The union of the areas reported since the last draw (meaningful when damage_is_partial()).
  const Rect& damage() const { return damage_; }
  /// Called by the panel once it has drawn the widget.
  void reset_damage() {
    damage_all_ = false;
    damage_ = {};
  }

  /// Pointer position while hovering (for per-row highlights); not called when not hovered.
  virtual void hover_at(glm::dvec2 /*p*/) {}
  /// Pointer position while a drag is held (may lie outside the widget: clamp).
  virtual void drag_to(glm::dvec2 /*p*/) {}
  /// Where drag_to() would have to go to give the current value (a fine drag starts there);
  /// nullopt when the widget has no such point.
  virtual std::optional<glm::dvec2> drag_point() const { return std::nullopt; }
  /// Press and release on this widget.
  virtual void click(glm::dvec2 /*p*/) {}
  /// Deflection outside the dead zone (zero when released) for dt seconds while held past the
  /// repeat delay (PointerSettings::stick_repeat_delay_s) on the widget under the pointer (or
  /// the focused one).
  virtual void thumbstick(glm::dvec2 /*stick*/, double /*dt*/) {}
  /// One step per push of the thumbstick or tap of an arrow key: x -1 left / +1 right, y -1 down
  /// / +1 up (a slider's step, a menu row, a frame of the timeline).
  virtual void step(glm::ivec2 /*direction*/) {}

  virtual void draw(DrawContext& ctx) const = 0;

 protected:
  /// Called after the rectangle changed (widgets whose state depends on their size).
  virtual void layout_changed() {}
  void touch() {
    ++revision_;
    damage_all_ = true;
  }
  /// A change whose pixels all lie in area (panel pixels, anti-aliasing included): a panel
  /// redraws just that, e.g. two menu rows when the hovered row moves.
  void touch(const Rect& area) {
    ++revision_;
    if (damage_all_) return;
    if (damage_.empty()) {
      damage_ = area;
      return;
    }
    const double x0 = std::min(damage_.x, area.x), y0 = std::min(damage_.y, area.y);
    damage_ = {x0, y0, std::max(damage_.right(), area.right()) - x0,
               std::max(damage_.bottom(), area.bottom()) - y0};
  }
  template <class T>
  void set(T& field, const T& v) {
    if (!(field == v)) field = v, touch();
  }

 private:
  std::string id_;
  Rect rect_;
  bool hovered_ = false, pressed_ = false, focused_ = false, enabled_ = true;
  std::uint64_t revision_ = 1;
  bool damage_all_ = true;
  Rect damage_;
};

/// Draws the rounded widget background in the state's colour and the focus ring.
void draw_widget_frame(DrawContext& ctx, const Widget& w, const Rect& r);
/// Formats a number with a printf-style format ("%.1f"), for value texts.
std::string format_value(const char* fmt, double v);

}  // namespace vdfx::ui
