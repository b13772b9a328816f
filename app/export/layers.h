/// @file
/// @brief Flare and grain on the viewer's-path export (docs/export.md): drawn into each rendered
/// view after the view-dependent effects, as `vdfx render` draws them on the CPU, for a cyclopean
/// head at the origin looking along the path. The shader grain styles (headset, surface) have a
/// CPU reference; the volumetric ones are GPU only and left out (named at the start).
#pragma once

#include <cstdint>
#include <mutex>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "effects/flare_set.h"
#include "effects/grain_layout.h"
#include "io/sidecar.h"
#include "xr/headset/render_view.h"

namespace vdfx::app {

class PathLayers {
 public:
  /// Throws io::InputError when the sidecar's flares cannot be interpolated.
  explicit PathLayers(const io::Sidecar& sidecar);
  bool empty() const { return flares_.empty() && grains_.empty(); }
  /// An auto light tracks the light over consecutive frames: frames must then be drawn in order
  /// (one render thread), so the export shows what `vdfx play` shows.
  bool needs_frame_order() const { return flares_.uses_auto_light(); }
  /// What the export leaves out ("grain style object_cloud (GPU only)"), for the start message.
  std::vector<std::string> left_out() const;
  /// Draws the flares and shader grain for this view of video frame `frame` into `rgb` (RGB
  /// float, unclamped); `equirect` is the decoded frame (RGB float), observed for an auto light.
  /// Safe to call from several render threads.
  void draw(cv::Mat& rgb, const cv::Mat& equirect, const xr::RenderView& view, std::int64_t frame);

 private:
  std::mutex mutex_;  //!< the auto-light tracker and the grain set's particle cache
  effects::FlareSet flares_;
  effects::GrainSet grains_;
  double fps_;  //!< the sidecar's, for the grain's display times (as `vdfx render` has them)
};

}  // namespace vdfx::app
