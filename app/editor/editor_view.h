/// @file
/// @brief EditorView: everything the editor's panels show, as one value built once per frame
/// from the Editor, its Document and PendingEdit and the visualizations (Editor::view()).
/// EditorPanels::show(view) is the only writer of widget state besides the UI pointers' own
/// interaction (hover, press, a drag's value while held); the panels' events go back to the
/// Editor as actions (app/editor/panel_binding.h). So the picture is always one frame's state.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "app/editor/edit_target.h"
#include "app/editor/track_view.h"
#include "app/editor/visualization_cache.h"
#include "effects/flare.h"
#include "effects/grain.h"

namespace vdfx::app {

struct EditorView {
  // ---- the effect panel
  EditTarget effect = effects::EffectType::Exposure;
  std::vector<double> values;  //!< the widget's: the selected keyframe's, else the chosen ones
  effects::FlareStyle flare_style = effects::FlareStyle::Directional;
  bool auto_light = true;
  effects::GrainStyle grain_style = effects::GrainStyle::Headset;
  double exponent = 1.0;
  double time_scale_deg_per_s = 1.0;  //!< degrees of view one second of video weighs like
  bool can_undo = false, can_redo = false;
  std::optional<std::size_t> selected;  //!< the selected keyframe of the effect
  std::size_t keyframe_count = 0;       //!< the effect's keyframes
  bool grabbing = false;                //!< the selected keyframe is held
  std::string autosave;                 //!< the autosave line ("" without autosave)
  /// "Suggest" for the effect ("" when it has none: no button), its strength, and how far a
  /// running suggestion is (nullopt: none runs; the button then cancels it).
  std::string suggest_title;
  bool suggest_available = false;  //!< a video to suggest from
  double suggest_strength = 1.0;
  std::optional<double> suggest_progress;
  // ---- the timeline
  bool playing = false;
  std::int64_t frame = 0;
  double fps = 30.0;
  /// Video thumbnails for the strip and their version (0: none yet); they are taken over when
  /// the version moves.
  const std::vector<cv::Mat>* thumbnails = nullptr;
  std::uint64_t thumbnails_version = 0;
  // ---- the status lines
  std::string status;                 //!< the one-line status (the Hands layout's hint)
  std::string hud_line, hud_message;  //!< the Desktop layout's heads-up line and message
  // ---- the views: what is shown, and where the timeline is
  bool show_track_plot = true, show_minimap = true, timeline_locked = false;
  /// Degrees of azimuth the video covers (360, or 180 for VR180: the minimap dims the rest).
  int coverage_deg = 360;
  /// The plot, the minimap and the strip's markers (VisualizationCache's latest); null: none
  /// yet. Lives as long as the editor.
  const Visualizations* visuals = nullptr;
  // ---- tracking: the section's buttons, the strip's track band, the marker in the view
  TrackView track;
};

}  // namespace vdfx::app
