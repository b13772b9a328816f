/// @file
/// @brief PathLayers: the sidecar's flares and shader grain drawn into the viewer's-path views.
#include "app/export/layers.h"

#include "effects/flare_render.h"
#include "effects/flare_set_cv.h"
#include "effects/grain_render.h"
#include "io/sidecar_sets.h"

namespace vdfx::app {

PathLayers::PathLayers(const io::Sidecar& sidecar)
    : flares_(io::flare_set_of(sidecar)),
      grains_(io::grain_set_of(sidecar)),
      fps_(sidecar.video.fps) {}

std::vector<std::string> PathLayers::left_out() const {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < grains_.size(); ++i)
    if (effects::is_volumetric(grains_.effect(i).style))
      out.push_back("grain style " +
                    std::string(effects::grain_style_name(grains_.effect(i).style)) +
                    " (GPU only)");
  return out;
}

void PathLayers::draw(cv::Mat& rgb, const cv::Mat& equirect, const xr::RenderView& view,
                      std::int64_t frame) {
  // The video is a sphere at infinity seen from the origin; the head sits there, looking along
  // the view (its roll included), as in `vdfx render --view`.
  const effects::HeadPose head{Eigen::Vector3d::Zero(), view.orientation};
  std::vector<effects::FlareLayout> flares;
  std::vector<effects::GrainFrame> grains;
  {
    const std::lock_guard lock(mutex_);
    if (flares_.uses_auto_light() && !flares_.observed(frame))
      effects::observe_frame(flares_, frame, equirect);
    flares = flares_.layouts(head, frame);
    grains = grains_.layout(head, effects::frame_display_time_ns(frame, fps_), frame);
  }
  const effects::ViewCamera camera = view.camera(rgb.cols, rgb.rows);
  effects::add_flares(rgb, camera, head.position, flares);
  for (const effects::GrainFrame& g : grains)
    if (!effects::is_volumetric(g.style))
      effects::composite_shader_grain(rgb, g, view.orientation, head.position, view.tangents());
}

}  // namespace vdfx::app
