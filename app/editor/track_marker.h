/// @file
/// @brief TrackMarker: the shown subject track drawn in the view (docs/editor.md, "Tracking"): a
/// small quad (a ui::Panel with a ring and the track's name on a tag, no backdrop) placed in the
/// direction where the track has its subject at the current frame, facing the head; hidden when the
/// track has no point there. The ring is dashed where the subject was lost (its direction held).
#pragma once

#include <memory>
#include <optional>

#include "app/editor/track_view.h"
#include "ui/button.h"
#include "ui/panel.h"

namespace vdfx::app {

inline constexpr const char* kTrackMarkerPanelId = "track_marker";

class TrackMarker {
 public:
  explicit TrackMarker(std::shared_ptr<const ui::FontSet> fonts);
  ui::Panel& panel() { return *panel_; }
  const ui::Panel& panel() const { return *panel_; }
  /// Where the head is (EditorPanels::place, once a frame).
  void set_head(const ui::Pose& head);
  /// Shows the view's marker (or hides the panel) and puts it in its direction.
  void show(const TrackView& view);
  /// The direction the marker is drawn in; nullopt while hidden.
  const std::optional<effects::Direction>& direction() const { return at_; }

  static constexpr double kDistanceM = 2.0;  //!< from the head (the video is at infinity)

 private:
  void put();

  std::unique_ptr<ui::Panel> panel_;
  ui::Widget* ring_ = nullptr;
  ui::Widget* name_ = nullptr;
  ui::Pose head_;
  std::optional<effects::Direction> at_;
};

}  // namespace vdfx::app
