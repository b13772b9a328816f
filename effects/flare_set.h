/// @file
/// @brief The flares of a sidecar, evaluated per frame: each flare's intensity (RBF over gaze
/// direction and frame), its light direction (fixed, track or auto) and its world-space layout
/// for the head pose. One call per frame; both eyes draw the same layouts.
///
/// No OpenCV here (the web player's module compiles it): an auto light's measurements come in
/// through record_light (effects/flare_set_cv.h's observe_frame measures a video frame), or
/// whole, already tracked, through set_auto_lights (the lights `vdfx publish` found).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "effects/anchor_sources.h"
#include "effects/flare.h"
#include "effects/flare_layout.h"
#include "effects/light_track.h"
#include "effects/rbf_interpolator.h"

namespace vdfx::effects {

class FlareSet {
 public:
  /// Solves each flare's intensity keyframes (its own interpolation settings, else `defaults`)
  /// and resolves its anchor against `anchors`. Throws std::invalid_argument like
  /// RbfInterpolator, or when an anchor names what `anchors` lack.
  FlareSet(std::vector<FlareEffect> flares, const InterpolationSettings& defaults, double fps,
           const AnchorSources& anchors = {}, AutoLightOptions auto_options = {});

  bool empty() const { return flares_.empty(); }
  std::size_t size() const { return flares_.size(); }
  const std::vector<FlareEffect>& flares() const { return flares_; }

  /// True when some flare finds its light in the video frames (observe_frame() them).
  bool uses_auto_light() const { return uses_auto_; }
  /// Frames before f whose images the auto light at f uses (observe them too for a lone frame).
  int auto_light_window() const { return tracker_.window(); }
  const AutoLightOptions& auto_light_options() const { return tracker_.options(); }
  /// Gives the auto-light tracker frame's measurement (find_brightest_region of the frame);
  /// nothing without auto lights.
  void record_light(std::int64_t frame, const std::optional<Eigen::Vector3d>& measured);
  /// Whether the tracker has measured `frame` (observe it before asking for its light).
  bool observed(std::int64_t frame) const { return tracker_.observed(frame); }
  /// The auto light of every frame, tracked elsewhere (entry f: frame f's light or none; none
  /// beyond the list): from now on light() reads these instead of the tracker.
  void set_auto_lights(std::vector<std::optional<Eigen::Vector3d>> lights);

  /// New flares (an editor's edit), solved like the constructor's. The auto-light tracker keeps
  /// what it measured: it is about the video, not the flares.
  void replace_flares(std::vector<FlareEffect> flares, const InterpolationSettings& defaults,
                      double fps, const AnchorSources& anchors = {});
  /// Flare k's intensity from another solution of its keyframes (an editor's pending edit);
  /// dimension 1, keyframes in the flare's anchor's frame.
  void set_intensity(std::size_t k, std::shared_ptr<const RbfInterpolator> intensity);

  /// Flare k's intensity at a gaze direction (unit, of the video frame) and frame, clamped to
  /// 0..4.
  double intensity(std::size_t k, const Eigen::Vector3d& gaze, std::int64_t frame) const;
  /// Flare k's anchor.
  const AnchorFrames& anchor(std::size_t k) const { return anchors_.at(k); }
  /// Flare k's light direction (unit, of the video frame) at a frame; nullopt when an auto light
  /// finds none.
  std::optional<Eigen::Vector3d> light(std::size_t k, std::int64_t frame) const;
  /// The layouts of every flare that adds light for this head pose at this frame.
  std::vector<FlareLayout> layouts(const HeadPose& head, std::int64_t frame) const;

 private:
  std::vector<FlareEffect> flares_;
  std::vector<std::shared_ptr<const RbfInterpolator>> intensity_;
  std::vector<AnchorFrames> anchors_;  //!< one per flare
  LightTrack tracker_;
  std::optional<std::vector<std::optional<Eigen::Vector3d>>> given_lights_;
  bool uses_auto_ = false;
};

}  // namespace vdfx::effects
