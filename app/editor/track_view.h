/// @file
/// @brief TrackView: what the tracking section, the timeline's track band and the track marker
/// show (docs/editor.md, "Tracking"), one value of EditorView built by Editor::track_view().
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "effects/coords.h"

namespace vdfx::app {

/// The track rename in progress (app/editor/rename_keyboard.h shows it).
struct RenameView {
  bool open = false;
  std::string from;         //!< the track being renamed
  std::string text;         //!< the name typed so far
  bool upper = false;       //!< Shift: letters upper case
  bool can_commit = false;  //!< the text is a track name, new and free
};

struct TrackView {
  bool available = false;  //!< a video to track
  /// The run in progress: which button it belongs to ("subject", "camera", "correct") and how far
  /// it is (0..1); the button then cancels it and the others wait.
  std::string running;
  double progress = 0.0;
  std::string anchor = "video";  //!< the current effect's anchor, as the sidecar writes it
  std::string track;             //!< the track shown and corrected ("" none)
  bool has_camera = false;
  std::string line;  //!< the section's status line
  /// The shown track over the timeline: its first and last frame (-1: none) and the frames where
  /// the subject was lost (its direction held there).
  int first = -1, last = -1;
  std::vector<int> held;
  /// The shown track at the current frame: where the marker is drawn, and whether it is held.
  std::optional<effects::Direction> marker;
  bool marker_held = false;
  RenameView rename;
};

}  // namespace vdfx::app
