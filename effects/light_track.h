/// @file
/// @brief The auto light's track over frames without the measurement (no OpenCV): per-frame
/// measurements in, the tracked and smoothed light at a frame out (the windowed straight-line fit
/// effects/auto_light.h describes). effects/auto_light.h measures video frames into it; the web
/// player's module (app/publish/wasm/) builds without OpenCV and takes the lights `vdfx publish`
/// tracked instead (effects::FlareSet::set_auto_lights).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <optional>

namespace vdfx::effects {

struct AutoLightOptions {
  int grid_width = 256;         //!< measurement grid (height = width / 2)
  double top_fraction = 0.001;  //!< of the sphere's solid angle
  double min_luma = 0.8;        //!< the region's brightest cell must reach this
  double min_contrast = 2.0;    //!< region mean luma / frame mean luma at least this
  double region_deg = 10.0;     //!< top-set cells beyond this from the peak are another light
  int window = 4;               //!< frames before f used by the fit at f
  double max_jump_deg = 15.0;   //!< measurements farther than this from f's are not f's light
};

class LightTrack {
 public:
  explicit LightTrack(AutoLightOptions options = {});

  /// Records frame's measurement (a unit direction, or none). A frame recorded before keeps its
  /// first measurement. Keeps the measurements of the most recent frames only (bounded memory).
  void record(std::int64_t frame, const std::optional<Eigen::Vector3d>& measured);
  bool observed(std::int64_t frame) const { return cache_.count(frame) != 0; }
  /// The tracked, smoothed light at `frame` from the measurements of frames frame - window ..
  /// frame recorded so far; nullopt when `frame` itself is unrecorded or has no light.
  std::optional<Eigen::Vector3d> light(std::int64_t frame) const;
  /// Frames before f that light(f) uses.
  int window() const { return options_.window; }
  const AutoLightOptions& options() const { return options_; }

 private:
  AutoLightOptions options_;
  std::map<std::int64_t, std::optional<Eigen::Vector3d>> cache_;
  std::int64_t latest_ = 0;
};

}  // namespace vdfx::effects
