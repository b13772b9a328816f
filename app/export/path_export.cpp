/// @file
/// @brief Head path resampling and the viewer's-path frame render.
#include "app/export/path_export.h"

#include <algorithm>

#include "effects/equirect_sampler.h"
#include "effects/view_renderer.h"
#include "io/input_error.h"
#include "xr/headset/eye_views.h"
#include "xr/headset/hmd_profile.h"
#include "xr/headset/render_view.h"

namespace vdfx::app {

std::vector<HeadSample> head_path(const io::Recording& recording) {
  std::vector<HeadSample> path;
  for (const io::RecordingLine& line : recording.lines) {
    const auto* s = std::get_if<io::RecordedSample>(&line.value);
    if (!s) continue;
    const auto& q = s->head.q;  // [w, x, y, z]
    path.push_back({s->t_ns, glm::normalize(glm::dquat(q[0], q[1], q[2], q[3]))});
  }
  if (path.empty()) throw io::InputError(recording.name + ": holds no head pose (only HID lines)");
  const std::int64_t t0 = path.front().t_ns;
  for (HeadSample& h : path) h.t_ns -= t0;
  return path;
}

glm::dquat head_at(const std::vector<HeadSample>& path, std::int64_t t_ns) {
  if (t_ns <= path.front().t_ns) return path.front().q;
  if (t_ns >= path.back().t_ns) return path.back().q;
  const auto it = std::upper_bound(path.begin(), path.end(), t_ns,
                                   [](std::int64_t t, const HeadSample& h) { return t < h.t_ns; });
  const HeadSample& b = *it;
  const HeadSample& a = *(it - 1);
  const double f = static_cast<double>(t_ns - a.t_ns) / static_cast<double>(b.t_ns - a.t_ns);
  return glm::slerp(a.q, b.q, f);
}

PathView path_view(const std::vector<HeadSample>& path, std::int64_t frame, io::Rational fps) {
  xr::Pose head;
  head.orientation = head_at(path, io::frame_start_ns(frame, fps));
  // The head's look and roll (eye_camera's; the profile's FOV is not used here).
  const xr::EyeCamera cam = xr::eye_camera(head, xr::HmdProfile{}, xr::Eye::Left);
  return {cam.look, cam.roll_deg};
}

std::int64_t path_last_frame(const std::vector<HeadSample>& path, io::Rational fps) {
  return std::max<std::int64_t>(0, io::frame_at_time(path.back().t_ns, fps));
}

cv::Mat render_path_frame(const cv::Mat& equirect, const effects::StackInterpolator& stack,
                          const PathView& view, std::int64_t frame, const PathRenderSettings& s) {
  const xr::RenderView rv =
      xr::RenderView::look_at(view.look, view.roll_deg, s.hfov_deg, s.width, s.height);
  const effects::ViewCamera camera = rv.camera(s.width, s.height);
  const cv::Mat eye = effects::eye_image(equirect, s.layout, s.eye);
  const effects::EquirectSampler sampler(eye, effects::sampler_options_for(s.layout));
  cv::Mat rgb = effects::render_view(sampler, camera, stack.evaluate(view.look, frame));
  if (s.view_layers) s.view_layers(rgb, eye, rv, frame);
  return rgb;
}

}  // namespace vdfx::app
