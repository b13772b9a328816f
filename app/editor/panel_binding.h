/// @file
/// @brief The editor's panels bound to the editor, one way: each UI event becomes a call of one
/// Editor action (matched by what its widget is for, EditorPanels::control_of, not by ids). The
/// panels are written back only by EditorPanels::show, from the editor's view.
#pragma once

#include "ui/widget.h"

namespace vdfx::app {

class Editor;
class EditorPanels;

/// Runs what one UI event asks of the editor (a menu row, a slider drag as one undo group, a
/// button, the strip, a minimap dot, a toggle).
void handle_panel_event(Editor& editor, const EditorPanels& panels, const ui::Event& event);

}  // namespace vdfx::app
