/// @file
/// @brief The one binding table of the editor: which controller action runs which command, and
/// what it does (the help text of `vdfx edit --help` and docs/editor.md is generated from it,
/// bindings_help_text()). The thresholds that make analog controls buttons are xr's
/// (xr::kPressThreshold / kReleaseThreshold), and xr::ActionEdges is the one edge detector: the
/// commands and the UI pointers both act on its edges.
///
/// The right trigger is also the right pointer's (ui::Pointer): on a panel it is the UI; pressed
/// on nothing it previews a new keyframe, which its release places. The commands run in this
/// order every frame.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "xr/input/actions.h"

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
  std::string_view does;  //!< for the help text
};

inline constexpr std::array<Binding, 10> kBindings{{
    {xr::Hand::Right, xr::Control::Squeeze, When::Pressed, EditorCommand::Grab,
     "grab: hold the selected keyframe (without a selection, the one nearest the view); it "
     "follows the view and the playhead"},
    {xr::Hand::Right, xr::Control::Squeeze, When::Up, EditorCommand::GrabRelease,
     "let go: the held keyframe moves there (one undo step)"},
    {xr::Hand::Right, xr::Control::StickClick, When::Pressed, EditorCommand::Deselect,
     "deselect (a grab in progress is cancelled); so does the Deselect button"},
    {xr::Hand::Right, xr::Control::Trigger, When::Pressed, EditorCommand::Preview,
     "on no panel: preview the current effect's values at the view centre (the reticle)"},
    {xr::Hand::Right, xr::Control::Trigger, When::Up, EditorCommand::Place,
     "let go: a keyframe is placed there, at the current frame"},
    {xr::Hand::Right, xr::Control::Secondary, When::Down, EditorCommand::Unaltered,
     "the unaltered film (no effects) while held"},
    {xr::Hand::Right, xr::Control::Primary, When::Pressed, EditorCommand::Delete,
     "delete the selected keyframe, else the one nearest the view"},
    {xr::Hand::Left, xr::Control::Primary, When::Pressed, EditorCommand::Undo, "undo"},
    {xr::Hand::Left, xr::Control::Secondary, When::Pressed, EditorCommand::Redo, "redo"},
    {xr::Hand::Left, xr::Control::Squeeze, When::Down, EditorCommand::Fine,
     "while held, a drag moves the widget by a tenth of the pointer's motion"},
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

/// What the UI pointers do with a hand's controls (EditorControls::pointers): no command, the
/// panels' own events. Listed for the help text beside kBindings.
struct PointerUse {
  xr::Hand hand;
  xr::Control control;  //!< StickUp stands for the whole thumbstick
  std::string_view does;
};

inline constexpr std::array<PointerUse, 4> kPointerUses{{
    {xr::Hand::Right, xr::Control::Trigger,
     "on a panel: use it (menus, sliders, buttons, the timeline, minimap dots)"},
    {xr::Hand::Left, xr::Control::Trigger, "the same, on the panels not held by the left hand"},
    {xr::Hand::Right, xr::Control::StickUp,
     "one step of the slider, pad, menu or timeline under the pointer, else the focused one; "
     "held, it moves on"},
    {xr::Hand::Left, xr::Control::StickUp, "the same for the left hand's pointer"},
}};

/// What the desktop's mouse and keyboard (the sim, docs/input.md) do beyond the controllers'
/// actions: looking around and the keyboard's "place at the centre". Listed for the help text
/// after kBindings and kPointerUses; `input` is named as the sim names it
/// (EditorBindings.DesktopRowsNameTheSimsInputs checks).
struct DesktopUse {
  std::string_view input;
  std::string_view does;
};

inline constexpr std::array<DesktopUse, 3> kDesktopUses{{
    {"right mouse button drag",
     "look around: drags the image as desktop 360 players do (drag left, the view turns right); "
     "--look mouselook turns like a game's camera (drag left, turns left)"},
    {"I", "switch the right-button drag between drag and mouselook"},
    {"Space",
     "the right trigger aimed at the view centre: previews there and places on release, wherever "
     "the pointer rests (the left mouse button presses what is under the pointer)"},
}};

/// The editor's controls as text (`vdfx edit --help`, docs/editor.md), one row per binding,
/// pointer use and desktop use, generated from kBindings, kPointerUses and kDesktopUses, with the
/// sim's keys in brackets (for a pointer use only those that point through the cursor).
std::string bindings_help_text();

}  // namespace vdfx::app
