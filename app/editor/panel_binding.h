/// @file
/// @brief The editor's panels bound to the editor: UI events run editor actions (matched against
/// the widgets EditorPanels holds, not by ids), and the document and the editor's state are shown
/// on the widgets and the status lines.
#pragma once

#include "ui/widget.h"

namespace vdfx::app {

class Editor;
class EditorPanels;

/// Runs what one UI event asks of the editor (a menu row, a slider drag as one undo group, a
/// button, the strip, a minimap dot, a toggle).
void handle_panel_event(Editor& editor, EditorPanels& panels, const ui::Event& event);

/// Shows the editor's state on the panels: the effect widget's values (the selected keyframe's,
/// else the chosen ones), interpolation settings, button states, title, time, status lines and
/// the heads-up line. Setters compare, so an unchanged state costs no redraw.
void show_editor_state(const Editor& editor, EditorPanels& panels);

}  // namespace vdfx::app
