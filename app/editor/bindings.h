/// @file
/// @brief The one binding table of the editor: which controller action runs which command. The
/// thresholds that make analog controls buttons are xr's (xr::kPressThreshold /
/// kReleaseThreshold), and xr::ActionEdges is the one edge detector: the commands and the UI
/// pointers both act on its edges. The sim's keys for each action are in docs/input.md.
///
/// The right trigger is also the right pointer's (ui::Pointer): on a panel it is the UI; pressed
/// on nothing it previews a new keyframe, which its release places. The commands run in this
/// order every frame.
#pragma once

#include <array>

#include "xr/actions.h"

namespace vdfx::app {

enum class EditorCommand {
  Preview,      //!< a new keyframe at the view centre follows the view (the trigger on nothing)
  Place,        //!< place the previewed keyframe
  Grab,         //!< hold the selected keyframe (else select the nearest and hold it)
  GrabRelease,  //!< commit the held keyframe's move
  Deselect,
  Unaltered,  //!< the plain film while held
  Delete,     //!< the selected keyframe, else the one nearest the view
  Undo,
  Redo,
  Fine,  //!< while held, drags move a tenth of the pointer's motion (UI pointers)
};

/// When a binding fires: on the press, on the release, every frame while down or while up.
enum class When { Pressed, Released, Down, Up };

struct Binding {
  xr::Hand hand;
  xr::Control control;
  When when;
  EditorCommand command;
};

inline constexpr std::array<Binding, 10> kBindings{{
    {xr::Hand::Right, xr::Control::Squeeze, When::Pressed, EditorCommand::Grab},
    {xr::Hand::Right, xr::Control::Squeeze, When::Up, EditorCommand::GrabRelease},
    {xr::Hand::Right, xr::Control::StickClick, When::Pressed, EditorCommand::Deselect},
    {xr::Hand::Right, xr::Control::Trigger, When::Pressed, EditorCommand::Preview},
    {xr::Hand::Right, xr::Control::Trigger, When::Up, EditorCommand::Place},
    {xr::Hand::Right, xr::Control::Secondary, When::Down, EditorCommand::Unaltered},
    {xr::Hand::Right, xr::Control::Primary, When::Pressed, EditorCommand::Delete},
    {xr::Hand::Left, xr::Control::Primary, When::Pressed, EditorCommand::Undo},
    {xr::Hand::Left, xr::Control::Secondary, When::Pressed, EditorCommand::Redo},
    {xr::Hand::Left, xr::Control::Squeeze, When::Down, EditorCommand::Fine},
}};

/// Whether a binding fires for these edges.
inline bool fires(const Binding& b, const xr::ActionEdges& e) {
  switch (b.when) {
    case When::Pressed: return e.was_pressed(b.hand, b.control);
    case When::Released: return e.was_released(b.hand, b.control);
    case When::Down: return e.is_down(b.hand, b.control);
    case When::Up: return !e.is_down(b.hand, b.control);
  }
  return false;
}

}  // namespace vdfx::app
