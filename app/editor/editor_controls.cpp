/// @file
/// @brief EditorControls: pointers and the binding table.
#include "app/editor/editor_controls.h"

namespace vdfx::app {

namespace {

/// A hand as the UI sees it; an untracked hand's ray points nowhere (hits nothing).
ui::PointerInput pointer_input(const xr::InputState& in, xr::Hand hand, bool fine) {
  const xr::HandState& h = in.hand(hand);
  ui::PointerInput p;
  if (!h.tracked) {
    p.ray.direction = glm::dvec3(0.0);  // parallel to everything: hits nothing
    return p;
  }
  p.ray = {h.aim.position, xr::forward(h.aim)};
  // An untracked hand has nothing down (xr::controls_down), so its edges are empty too.
  p.trigger = {in.edges.is_down(hand, xr::Control::Trigger),
               in.edges.was_pressed(hand, xr::Control::Trigger),
               in.edges.was_released(hand, xr::Control::Trigger)};
  p.thumbstick = h.thumbstick;
  p.fine = fine;
  return p;
}

}  // namespace

std::vector<ui::Event> EditorControls::pointers(const xr::InputState& in, EditorPanels& panels,
                                                double dt) {
  auto events = left_.update(panels.reachable_by(xr::Hand::Left),
                             pointer_input(in, xr::Hand::Left, false), dt);
  const auto right =
      right_.update(panels.reachable_by(xr::Hand::Right),
                    pointer_input(in, xr::Hand::Right, held(in.edges, EditorCommand::Fine)), dt);
  events.insert(events.end(), right.begin(), right.end());
  return events;
}

std::vector<EditorCommand> EditorControls::commands(const xr::ActionEdges& edges) const {
  std::vector<EditorCommand> out;
  for (const Binding& b : kBindings) {
    if (b.when == When::Down || !fires(b, edges)) continue;
    // A trigger press on a panel (or on a widget the pointer holds) is the UI's.
    if (b.command == EditorCommand::Preview && (right_.hit() || right_.pressed())) continue;
    out.push_back(b.command);
  }
  return out;
}

bool EditorControls::held(const xr::ActionEdges& edges, EditorCommand command) {
  for (const Binding& b : kBindings)
    if (b.command == command && b.when == When::Down && fires(b, edges)) return true;
  return false;
}

}  // namespace vdfx::app
