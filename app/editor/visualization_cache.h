/// @file
/// @brief What the editor shows about the current effect's keyframes, as data for its panels:
/// the track plot (the value over time at the view), the minimap (over the sphere at the playhead,
/// with the keyframes as dots and the view's footprint) and the timeline's markers. Keyframes
/// are stored in their effect's anchor's frame: the plot, the field and the markers turn the
/// view into it at each frame, and the dots are drawn where the keyframes are at the playhead.
/// Each is recomputed only when what it shows changed (the document's revision and solution, the
/// pending edit's version, the effect, the frame, the view by a degree), so a frame that changes
/// nothing costs nothing. While a keyframe is placed or held away from its place they show the
/// pending edit's interpolant, the one the view shows.
///
/// The minimap is the costly one (8192 evaluations, 30 ms at N = 1000): with `async` (live
/// `vdfx edit`) a MinimapWorker computes it and the newest finished field is shown a frame or two
/// later; without (replays, tests) it is computed here, so every run shows the same pictures.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <span>
#include <vector>

#include "app/editor/minimap_worker.h"
#include "effects/keyframe.h"

namespace vdfx::app {

class Document;

struct VisualizationOptions {
  double marker_cone_deg = 30.0;  //!< timeline markers highlighted within this angle of the view
  int track_samples = 240;        //!< frames sampled for the track plot
  int minimap_width = 128;
  int minimap_height = 64;
  //! true (`vdfx edit`): the minimap on a worker, shown a frame or two late; the frame thread
  //! never waits for it. false (replay, tests): computed in refresh().
  bool async = false;
};

/// What the visualizations are asked to show this frame.
struct VisualizationInput {
  EditTarget effect = effects::EffectType::Exposure;
  effects::Direction view{};
  std::int64_t frame = 0;
  std::optional<std::size_t> selected;
  /// The selected keyframe where a grab holds it now (else as it is); nullopt without selection.
  std::optional<effects::Keyframe> held;
  bool previewing = false;                            //!< a new keyframe is placed at the playhead
  double view_hfov_deg = 90.0, view_vfov_deg = 90.0;  //!< the footprint drawn on the minimap

  /// Keyframe i as the visualizations show it: the selected one where it is held.
  const effects::Keyframe& shown(std::span<const effects::Keyframe> keyframes,
                                 std::size_t i) const {
    return held && selected && i == *selected ? *held : keyframes[i];
  }
};

/// What the track plot, the minimap and the timeline's markers show: data, no widgets
/// (EditorPanels::show draws it). The costly parts carry versions that move when they were
/// recomputed, so the panels take them over only then.
struct Visualizations {
  // ---- the timeline strip's markers
  std::uint64_t markers_version = 0;
  std::vector<int> marker_frames;       //!< one per keyframe (the held one where it is held)
  std::vector<int> highlighted_frames;  //!< the keyframes near the view, and the held one
  // ---- the track plot: the display value over time at the view
  std::uint64_t track_version = 0;
  std::vector<double> track;  //!< at VisualizationCache::track_frames()
  double track_lo = 0.0, track_hi = 1.0;
  std::vector<int> track_marks;  //!< keyframes as indices into the sampled frames
  int track_playhead = 0;        //!< the playhead as an index into the sampled frames
  // ---- the minimap: the display value over the sphere at the playhead
  std::uint64_t field_version = 0;  //!< 0: no field yet
  cv::Mat field;
  double field_lo = 0.0, field_hi = 1.0;
  std::vector<effects::Direction> dots;  //!< the keyframes (the held one where it is held)
  int nearest = -1, selected = -1;       //!< dot indices, -1 for none
  effects::Direction view{};
  double view_hfov_deg = 90.0, view_vfov_deg = 90.0;
};

class VisualizationCache {
 public:
  VisualizationCache(VisualizationOptions options, std::int64_t frame_count);
  ~VisualizationCache();

  /// Brings the visualizations up to date and returns them.
  const Visualizations& refresh(const Document& doc, const VisualizationInput& in);
  /// The visualizations as the last refresh() or wait() left them.
  const Visualizations& data() const { return out_; }
  /// Waits for the minimap worker to finish and takes its field (frame thread; tests, replays).
  /// Returns minimap_current(). Immediate without async.
  bool wait(std::chrono::milliseconds timeout, EditTarget effect);

  const cv::Mat& minimap_field() const { return out_.field; }
  const std::vector<double>& track_values() const { return out_.track; }
  const std::vector<std::int64_t>& track_frames() const { return track_.frames; }
  /// Indices of the current effect's keyframes within marker_cone_deg of the view.
  const std::vector<std::size_t>& near_keyframes() const { return markers_.near; }
  /// How often the minimap was recomputed (with async: the fields taken over from the worker).
  int minimap_computations() const { return minimap_.computations; }
  /// Whether the minimap shown is the one for the current keyframes, effect and frame.
  bool minimap_current() const { return minimap_.shown == minimap_.requested; }

 private:
  void refresh_markers(const Document& doc, const VisualizationInput& in);
  void refresh_track(const VisualizationInput& in, std::span<const effects::Keyframe> ks,
                     const MinimapKey& key, const effects::RbfInterpolator* rbf,
                     const effects::AnchorFrames& anchor);
  void refresh_minimap(const Document& doc, const VisualizationInput& in, const MinimapKey& key,
                       const std::function<std::shared_ptr<const effects::RbfInterpolator>()>& rbf);
  void take_field(const MinimapKey& key, cv::Mat field, EditTarget effect);

  struct Markers {
    std::uint64_t revision = ~0ull;
    int effect = -1;
    effects::Direction view{};
    std::int64_t held_frame = -1;   //!< the selected keyframe's (held) frame at the last update
    std::int64_t anchor_frame = 0;  //!< the playhead then, for an anchored effect (else 0)
    std::vector<std::size_t> near;
  };
  struct Track {
    MinimapKey key;
    effects::Direction view{};
    std::vector<std::int64_t> frames;
  };
  struct Minimap {
    MinimapKey shown;                    //!< what the field shown was computed for
    MinimapKey requested;                //!< what it should show now
    std::optional<std::size_t> nearest;  //!< nearest keyframe at the last request
    int computations = 0;
  };
  VisualizationOptions options_;
  Markers markers_;
  Track track_;
  Minimap minimap_;
  Visualizations out_;
  std::unique_ptr<MinimapWorker> worker_;  //!< with async
};

}  // namespace vdfx::app
