/// @file
/// @brief TrackSection: the tracking buttons (docs/editor.md, "Tracking") as widgets of a panel
/// (Desktop: the views panel; Hands: the timeline panel): Track subject, Track camera, Correct
/// here, the current effect's anchor and Delete (the shown track). A running job's button shows
/// its progress and cancels it; the others wait.
#pragma once

#include "app/editor/track_view.h"
#include "ui/button.h"
#include "ui/panel.h"
#include "ui/rect.h"

namespace vdfx::app {

enum class PanelControl;

class TrackSection {
 public:
  /// Adds the buttons to `p`, taking their rows from `col`: two rows of two and Rename and
  /// Delete below (narrow panels), or one row of six.
  void build(ui::Panel& p, ui::Stack& col, bool two_rows);
  /// Writes the view onto the buttons (setters compare: an unchanged view redraws nothing).
  void show(const TrackView& view);
  /// What `w` is for (PanelControl::None when it is none of these buttons).
  PanelControl control_of(const ui::Widget* w) const;

  const ui::Button& subject_button() const { return *subject_; }
  const ui::Button& camera_button() const { return *camera_; }
  const ui::Button& correct_button() const { return *correct_; }
  const ui::Button& anchor_button() const { return *anchor_; }
  const ui::Button& delete_button() const { return *delete_; }
  const ui::Button& rename_button() const { return *rename_; }

 private:
  ui::Button* subject_ = nullptr;
  ui::Button* camera_ = nullptr;
  ui::Button* correct_ = nullptr;
  ui::Button* anchor_ = nullptr;  //!< "Anchor: video" / world / track:NAME; a press: the next
  ui::Button* delete_ = nullptr;  //!< "Delete NAME": the shown track
  ui::Button* rename_ = nullptr;  //!< "Rename NAME": the shown track (app/editor/rename_keyboard.h)
};

}  // namespace vdfx::app
