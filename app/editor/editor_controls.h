/// @file
/// @brief The editor's input side: each hand's UI pointer on the panels it may use, turning the
/// frame's input into UI events, and the binding table's commands (app/editor/bindings.h) due
/// this frame. Both act on the input's edges (xr::ActionEdges, the one edge detector). Holds no
/// editing state: the Editor runs what it returns.
#pragma once

#include <vector>

#include "app/editor/bindings.h"
#include "app/editor/editor_panels.h"
#include "ui/interaction.h"
#include "xr/input/actions.h"

namespace vdfx::app {

class EditorControls {
 public:
  /// Both pointers for this frame (left, then right), each on the panels not held by its own
  /// hand, with its trigger's edges; the right one drags finely while EditorCommand::Fine's
  /// control is down. Returns the UI events in the order they happened.
  std::vector<ui::Event> pointers(const xr::InputState& input, EditorPanels& panels, double dt);
  /// The commands of the binding table that fire this frame (after pointers()), in table order;
  /// held ones (When::Down) are asked for with held(). Preview only when the trigger went down on
  /// no panel and no widget.
  std::vector<EditorCommand> commands(const xr::ActionEdges& edges) const;
  /// Whether a binding of `command` is down this frame (the unaltered film, fine drags).
  static bool held(const xr::ActionEdges& edges, EditorCommand command);
  const ui::Pointer& pointer(xr::Hand hand) const {
    return hand == xr::Hand::Left ? left_ : right_;
  }

 private:
  ui::Pointer left_, right_;
};

}  // namespace vdfx::app
