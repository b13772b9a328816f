/// @file
/// @brief Mirror geometry and its inverse (the pointer's ray through a window pixel).
#include "xr/render/mirror.h"

#include <algorithm>
#include <cmath>

#include "effects/coords.h"
#include "xr/headset/eye_views.h"
#include "xr/headset/session.h"

namespace vdfx::xr {

namespace {

using effects::kDegToRad;

effects::EyeLens eye_lens(const MirrorGeometry& g, int eye) {
  effects::EyeLens e;
  e.width = g.eye_w;
  e.height = g.eye_h;
  e.fov = g.eyes[static_cast<std::size_t>(eye)].tangents();
  e.lens = g.lens;
  return e;
}

/// The ray of an eye image pixel position (continuous, top-left origin) in the head frame.
ViewRay eye_pixel_ray(const MirrorGeometry& g, int eye, const Eigen::Vector2d& px) {
  const RenderView& v = g.eyes[static_cast<std::size_t>(eye)];
  const Eigen::Vector2d t = v.tangent_at(px.x(), px.y(), g.eye_w, g.eye_h);
  const Eigen::Vector3d n = (v.orientation * Eigen::Vector3d(t.x(), t.y(), -1.0)).normalized();
  return {{v.position.x(), v.position.y(), v.position.z()}, {n.x(), n.y(), n.z()}};
}

bool inside_image(const Eigen::Vector2d& px, int w, int h) {
  return px.x() >= 0.0 && px.y() >= 0.0 && px.x() <= w && px.y() <= h;
}

}  // namespace

std::string_view mirror_mode_name(MirrorMode mode) {
  switch (mode) {
    case MirrorMode::Desktop: return "desktop";
    case MirrorMode::PreDistorted: return "pre";
    case MirrorMode::ThroughTheLens: return "lens";
    case MirrorMode::SingleEye: return "eye";
  }
  return "desktop";
}

std::optional<MirrorMode> mirror_mode_from_name(std::string_view name) {
  for (const MirrorMode m : {MirrorMode::Desktop, MirrorMode::PreDistorted,
                             MirrorMode::ThroughTheLens, MirrorMode::SingleEye})
    if (mirror_mode_name(m) == name) return m;
  return std::nullopt;
}

WindowRect mirror_eye_rect(MirrorMode mode, int eye, int eye_w, int eye_h, int win_w, int win_h) {
  if (mode == MirrorMode::Desktop) return {0, 0, win_w, win_h};
  const int x0 = mode == MirrorMode::SingleEye ? 0 : eye * win_w / 2;
  const int x1 = mode == MirrorMode::SingleEye ? win_w : (eye + 1) * win_w / 2;
  const double s =
      std::min(static_cast<double>(x1 - x0) / eye_w, static_cast<double>(win_h) / eye_h);
  const int w = static_cast<int>(eye_w * s), h = static_cast<int>(eye_h * s);
  // Centred; the compositor's blit (GL, bottom-up) puts the bottom edge at (win_h - h) / 2.
  const int bottom = (win_h - h) / 2;
  return {x0 + (x1 - x0 - w) / 2, win_h - bottom - h, w, h};
}

RenderView desktop_view(const Pose& head, double hfov_deg, int width, int height) {
  RenderView v;
  v.orientation = rotation_of(head);
  v.position = position_of(head);
  const double t = std::tan(0.5 * hfov_deg * kDegToRad);
  const double tv = t * static_cast<double>(std::max(1, height)) / std::max(1, width);
  v.tan_left = -t;
  v.tan_right = t;
  v.tan_down = -tv;
  v.tan_up = tv;
  return v;
}

MirrorGeometry MirrorGeometry::from_profile(const HmdProfile& profile, MirrorMode mode, int eye_w,
                                            int eye_h, int window_w, int window_h,
                                            double desktop_hfov_deg) {
  MirrorGeometry g;
  g.mode = mode;
  g.window_w = window_w;
  g.window_h = window_h;
  g.desktop_hfov_deg = desktop_hfov_deg;
  g.eye_w = eye_w;
  g.eye_h = eye_h;
  const auto views = locate_eye_views(Pose{}, profile);  // head at the origin: the head frame
  for (int e = 0; e < 2; ++e)
    g.eyes[static_cast<std::size_t>(e)] = render_view(views[static_cast<std::size_t>(e)]);
  g.lens = effects::LensModel(profile.lens);
  return g;
}

std::optional<ViewRay> mirror_ray(const MirrorGeometry& g, double x, double y) {
  if (g.mode == MirrorMode::Desktop) {
    const RenderView v = desktop_view(Pose{}, g.desktop_hfov_deg, g.window_w, g.window_h);
    const Eigen::Vector2d t = v.tangent_at(x, y, g.window_w, g.window_h);
    const glm::dvec3 d = glm::normalize(glm::dvec3(t.x(), t.y(), -1.0));
    return ViewRay{{0.0, 0.0, 0.0}, d};
  }
  const int eyes = g.mode == MirrorMode::SingleEye ? 1 : 2;
  for (int e = 0; e < eyes; ++e) {
    const WindowRect r = mirror_eye_rect(g.mode, e, g.eye_w, g.eye_h, g.window_w, g.window_h);
    if (!r.contains(x, y)) continue;
    // The blit scales the eye image onto the rectangle: continuous positions map linearly.
    const Eigen::Vector2d shown((x - r.x) / r.w * g.eye_w, (y - r.y) / r.h * g.eye_h);
    const effects::EyeLens lens = eye_lens(g, e);
    Eigen::Vector2d panel = shown;
    if (g.mode == MirrorMode::SingleEye) return eye_pixel_ray(g, e, shown);
    if (g.mode == MirrorMode::ThroughTheLens) {
      // What the wearer sees at `shown` is the panel at the forward lens model (green channel).
      const auto p = effects::through_lens_panel_px(lens, shown, 1);
      if (!p) return std::nullopt;
      panel = *p;
      if (!inside_image(panel, g.eye_w, g.eye_h)) return std::nullopt;
    }
    // The panel pixel shows the eye image where the pre-distortion sampled it (green channel).
    const effects::ChannelSamples s = effects::panel_source_uv(lens, panel, g.lca_correction);
    if (!s.valid[1]) return std::nullopt;
    const Eigen::Vector2d src(s.uv[1].x() * g.eye_w, s.uv[1].y() * g.eye_h);
    if (!inside_image(src, g.eye_w, g.eye_h)) return std::nullopt;
    return eye_pixel_ray(g, e, src);
  }
  return std::nullopt;
}

std::optional<glm::dvec2> mirror_pixel_of(const MirrorGeometry& g, const glm::dvec3& head_point,
                                          int eye) {
  const auto pixel_in = [&](const RenderView& v, int w, int h) -> std::optional<Eigen::Vector2d> {
    const Eigen::Vector3d p =
        v.orientation.transpose() *
        (Eigen::Vector3d(head_point.x, head_point.y, head_point.z) - v.position);
    if (p.z() >= 0.0) return std::nullopt;  // behind
    return v.pixel_at({p.x() / -p.z(), p.y() / -p.z()}, w, h);
  };
  if (g.mode == MirrorMode::Desktop) {
    const auto px = pixel_in(desktop_view(Pose{}, g.desktop_hfov_deg, g.window_w, g.window_h),
                             g.window_w, g.window_h);
    if (!px) return std::nullopt;
    return glm::dvec2(px->x(), px->y());
  }
  if (g.mode == MirrorMode::SingleEye) eye = 0;
  const auto src = pixel_in(g.eyes[static_cast<std::size_t>(eye)], g.eye_w, g.eye_h);
  if (!src) return std::nullopt;
  Eigen::Vector2d shown = *src;
  if (g.mode != MirrorMode::SingleEye) {
    // Forward of the pre-distortion: the panel pixel that samples `src` is where the lens model
    // puts it (green channel, LCA scale included when corrected), found from the image point's
    // tangent; through the lens that panel point is seen at the image point itself.
    const effects::EyeLens lens = eye_lens(g, eye);
    if (g.mode == MirrorMode::PreDistorted) {
      effects::LensParams p = g.lens.params();
      if (!g.lca_correction) p.lca_scale = {1.0, 1.0, 1.0};  // all channels sampled alike
      const auto t_d = effects::LensModel(p).view_to_panel(lens.pixel_to_tan(*src), 1);
      if (!t_d) return std::nullopt;
      shown = lens.tan_to_pixel(*t_d);
    }
  }
  const WindowRect r = mirror_eye_rect(g.mode, eye, g.eye_w, g.eye_h, g.window_w, g.window_h);
  return glm::dvec2(r.x + shown.x() / g.eye_w * r.w, r.y + shown.y() / g.eye_h * r.h);
}

}  // namespace vdfx::xr
