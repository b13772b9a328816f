/// @file
/// @brief Pointer interaction: ray hit testing against panels and the hover / press / drag /
/// release / thumbstick state machine that turns controller input into widget events.
///
/// Time is passed in (dt); nothing here reads a clock. No GL: tests drive it with plain rays.
#pragma once

#include <glm/vec3.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "ui/panel.h"
#include "ui/widget.h"

namespace vdfx::ui {

struct Ray {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0, 0.0, -1.0};  //!< need not be unit length
};

/// Where a ray meets a panel's plane.
struct PlaneHit {
  glm::dvec2 pixel{0.0};  //!< panel pixels (may lie outside the panel)
  double distance = 0.0;  //!< along the ray, in units of |direction|
  bool front = false;     //!< the ray comes from the side the panel faces
  bool inside = false;    //!< within the panel's bounds
};

/// Ray-plane intersection in panel space; nullopt when parallel or behind the origin.
std::optional<PlaneHit> intersect_panel_plane(const Panel& panel, const Ray& ray);

struct PanelHit {
  Panel* panel = nullptr;
  glm::dvec2 pixel{0.0};
  double distance = 0.0;
};

/// The nearest visible panel hit from the front within its bounds.
std::optional<PanelHit> hit_panels(std::span<Panel* const> panels, const Ray& ray);

/// A button as the caller's edge detector sees it this frame (vdfx: xr::ActionEdges, whose
/// thresholds, hysteresis and taps kept between polls are the only ones; the pointer detects
/// nothing itself). A tap between two frames is pressed in one update and released in the next.
struct ButtonEdges {
  bool down = false;      //!< down in this update
  bool pressed = false;   //!< went down since the last update
  bool released = false;  //!< went up since the last update
};

/// One controller as the UI sees it.
struct PointerInput {
  Ray ray;
  ButtonEdges trigger;
  glm::dvec2 thumbstick{0.0};  //!< [-1, 1]^2, +x right, +y up
  /// Fine adjustment held (the other hand's grip; Shift in the sim): a drag moves the widget by
  /// PointerSettings::fine_factor of the pointer's motion, without a jump when it starts or ends.
  bool fine = false;
};

/// The thumbstick's dead zone and repeat, and the fine drag's gain.
struct PointerSettings {
  double stick_dead_zone = 0.2;
  double stick_repeat_delay_s = 0.35;  //!< a push steps once; held this long it moves on
  double fine_factor = 0.1;            //!< drag gain while PointerInput::fine is held
};

/// The interaction state of one pointer (one per hand). It refers to the widgets it hovers,
/// holds and focuses directly; a widget counts only while its panel is among those given to
/// update() (a hand's reach can change), and must live as long as it is referred to (panels
/// never remove widgets).
class Pointer {
 public:
  explicit Pointer(PointerSettings s = {}) : settings_(s) {}

  /// Advances by one frame: hit test, hover, trigger edges, drags, thumbstick (for dt seconds).
  /// Returns the events of this frame in the order they happened.
  std::vector<Event> update(std::span<Panel* const> panels, const PointerInput& in, double dt);

  /// Current hit (nullopt when the ray misses every panel).
  const std::optional<PanelHit>& hit() const { return hit_; }
  /// The widget under the pointer / held by its trigger / focused (null when none).
  const Widget* hovered() const { return hover_.widget; }
  const Widget* pressed() const { return press_.widget; }
  const Widget* focused() const { return focus_.widget; }
  /// Drops focus (e.g. when the editor closes a panel).
  void clear_focus();

 private:
  /// A widget and the panel holding it.
  struct Ref {
    Panel* panel = nullptr;
    Widget* widget = nullptr;
    bool empty() const { return widget == nullptr; }
    bool operator==(const Ref&) const = default;
  };
  /// One update's working set: the panels in reach and the events so far.
  struct Frame;
  static Widget* in_reach(std::span<Panel* const> panels, const Ref& r);
  void hover(Frame& f);
  void press(Frame& f);
  void drag(Frame& f);
  void release(Frame& f);
  void stick(Frame& f);

  PointerSettings settings_;
  std::optional<PanelHit> hit_;
  Ref hover_, press_, focus_;
  glm::dvec2 drag_start_value_{0.0};
  // Where the held widget is dragged to: the pointer's pixel, scaled about an anchor while fine.
  bool fine_ = false;
  glm::dvec2 drag_to_{0.0};      //!< the last position given to drag_to
  glm::dvec2 drag_anchor_{0.0};  //!< the pointer's pixel when the current mode began
  glm::dvec2 drag_offset_{0.0};  //!< drag_to_ - pointer pixel then (no jump between modes)
  bool stick_active_ = false;    //!< a thumbstick gesture is under way on stick_ref_
  Ref stick_ref_;                //!< the widget the gesture acts on (hovered, else focused)
  double stick_held_s_ = 0.0;
  glm::dvec2 stick_start_value_{0.0};
};

}  // namespace vdfx::ui
