/// @file
/// @brief Exact pointing in every mirror mode: where the GL compositor actually draws each widget
/// of the editor's panels (found in the rendered mirror, each widget painted in a colour of its
/// own), the mouse's ray (xr::mirror_ray, as the frame loop computes it) hits that same widget.
///
/// The drawn centre comes from the GPU path (quad projection, the lens pre-distortion shader,
/// the through-the-lens pass, the mirror blit); the ray from the CPU inverse. A mismatch between
/// the two is exactly the bug users met: clicks landing 100-200 px away from what is drawn.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <opencv2/imgproc.hpp>

#include "app/editor/editor.h"
#include "editor_test_util.h"
#include "tests/support/test_paths.h"
#include "xr/headset/eye_views.h"
#include "xr/headset/hmd_profile.h"
#include "xr/input/input_backend.h"
#include "xr/render/compositor.h"
#include "xr/render/gl_context.h"
#include "xr/render/gl_texture.h"
#include "xr/render/mirror.h"

namespace vdfx::app {
namespace {

constexpr int kW = 1280, kH = 720;

struct Target {
  std::string panel, widget;
  cv::Vec3b colour;  //!< BGR
};

/// The widgets the mouse can press, each painted in a colour of its own on a copy of its panel.
std::vector<Target> paint_ids(const std::vector<ui::Panel*>& panels, std::vector<cv::Mat>& images) {
  std::vector<Target> out;
  for (const ui::Panel* p : panels) {
    cv::Mat img(p->height_px(), p->width_px(), CV_8UC4, cv::Scalar(0, 0, 0, 0));
    for (const auto& w : p->widgets()) {
      if (w->rect().empty() || !w->interactive() || p->id() == kHudPanelId) continue;
      const int i = static_cast<int>(out.size());
      const cv::Vec3b c(static_cast<uchar>(40 + 6 * i), 200, static_cast<uchar>(235 - 6 * i));
      const ui::Rect r = w->rect();
      cv::rectangle(img,
                    cv::Rect(static_cast<int>(r.x), static_cast<int>(r.y), static_cast<int>(r.w),
                             static_cast<int>(r.h)),
                    cv::Scalar(c[0], c[1], c[2], 255), cv::FILLED);
      out.push_back({p->id(), w->id(), c});
    }
    images.push_back(img);
  }
  return out;
}

/// Centroid of the pixels of `colour` (within 2 per channel) inside a window rectangle.
std::optional<glm::dvec2> drawn_centre(const cv::Mat& bgr, const cv::Vec3b& colour,
                                       const xr::WindowRect& r) {
  double sx = 0, sy = 0;
  int n = 0;
  for (int y = r.y; y < r.y + r.h; ++y)
    for (int x = r.x; x < r.x + r.w; ++x) {
      const cv::Vec3b p = bgr.at<cv::Vec3b>(y, x);
      if (std::abs(p[0] - colour[0]) <= 2 && std::abs(p[1] - colour[1]) <= 2 &&
          std::abs(p[2] - colour[2]) <= 2) {
        sx += x + 0.5;
        sy += y + 0.5;
        ++n;
      }
    }
  if (n < 12) return std::nullopt;  // not (usefully) visible there
  return glm::dvec2(sx / n, sy / n);
}

/// The id of the widget under the mouse's ray ("" for none).
std::string hovered_id(const Editor& ed) {
  const ui::Widget* w = ed.pointer(xr::Hand::Right).hovered();
  return w ? w->id() : std::string();
}

TEST(PointingGl, APressAtTheDrawnCentreOfEveryWidgetHitsItInEveryMirrorMode) {
  xr::GlContextOptions go;
  go.width = 64;
  go.height = 64;
  const auto gl = xr::GlContext::create(go);
  const xr::HmdProfile profile = xr::load_hmd_profile("generic90");

  EditorOptions eo;
  eo.layout = PanelLayout::Desktop;
  eo.viewport = {kW, kH, 100.0};
  io::Sidecar sc = test::empty_sidecar(90);
  sc.effects.push_back({effects::EffectType::Exposure, std::nullopt, {{{-50.0, 10.0}, 0, {1.0}}}});
  Editor ed(sc, DocumentOptions{{.async = false}}, eo);
  xr::SimConfig sim_cfg;
  sim_cfg.window_width = kW;
  sim_cfg.window_height = kH;
  auto sim = xr::create_sim_backend(sim_cfg);
  std::int64_t t = 0;
  ed.update(sim->poll(t), t);  // panels placed for the head at rest

  const std::vector<ui::Panel*> panels = ed.panels();
  std::vector<cv::Mat> images;
  const std::vector<Target> targets = paint_ids(panels, images);
  ASSERT_GE(targets.size(), 12u);  // disabled buttons (nothing to redo yet) take no press
  std::vector<xr::GlTexture> textures;
  std::vector<xr::QuadLayer> quads;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    textures.emplace_back(images[i].cols, images[i].rows, xr::TexFormat::RGBA8);
    // Quads take their texture's first row as their top; GlTexture::upload puts an image's last
    // row first (GL's image convention), so the image goes up flipped.
    cv::Mat first_row_first;
    cv::flip(images[i], first_row_first, 0);
    textures.back().upload(first_row_first);
    textures.back().set_sampling(false, false);  // exact colours: no blending between ids
    xr::QuadLayer q;
    q.pose = panels[i]->pose();
    q.size_m = {panels[i]->size_m().x, panels[i]->size_m().y};
    q.texture = textures.back().id();
    quads.push_back(q);
  }

  xr::CompositorConfig cc;
  cc.eye_width = 360;  // generic90 at a quarter of its resolution, as the window uses it
  cc.eye_height = 400;
  cc.lens = effects::LensModel(profile.lens);
  xr::Compositor comp(cc);
  comp.set_video_frame(cv::Mat(32, 64, CV_8UC3, cv::Scalar::all(0)));
  const xr::Pose head = ed.input().head;

  std::ostringstream table;
  table << "| widget |";
  for (const xr::MirrorMode m : {xr::MirrorMode::Desktop, xr::MirrorMode::PreDistorted,
                                 xr::MirrorMode::ThroughTheLens, xr::MirrorMode::SingleEye})
    table << " " << xr::mirror_mode_name(m) << " |";
  table << "\n|---|---|---|---|---|\n";
  std::map<std::string, std::string> rows;
  for (const xr::MirrorMode mode : {xr::MirrorMode::Desktop, xr::MirrorMode::PreDistorted,
                                    xr::MirrorMode::ThroughTheLens, xr::MirrorMode::SingleEye}) {
    if (mode == xr::MirrorMode::Desktop) {
      comp.render_desktop({xr::desktop_view(head, 100.0, kW, kH), {}, 0u, false}, kW, kH, 0.5,
                          quads, head);
    } else {
      const auto views = xr::locate_eye_views(head, profile);
      for (int e = 0; e < 2; ++e)
        comp.render_eye(e, {xr::render_view(views[static_cast<std::size_t>(e)]), {}, 0u, false},
                        quads, head);
    }
    xr::GlTarget mirror(kW, kH, xr::TexFormat::RGBA8);
    comp.draw_mirror(mode, &mirror, kW, kH);
    const cv::Mat bgr = xr::to_bgr8(mirror.read_float());
    const auto g =
        xr::MirrorGeometry::from_profile(profile, mode, cc.eye_width, cc.eye_height, kW, kH, 100.0);
    const int eyes =
        mode == xr::MirrorMode::PreDistorted || mode == xr::MirrorMode::ThroughTheLens ? 2 : 1;
    int visible = 0, hit = 0, pinhole_hits = 0;
    for (const Target& tg : targets) {
      std::string cell;
      for (int e = 0; e < eyes; ++e) {
        const xr::WindowRect r = xr::mirror_eye_rect(mode, e, cc.eye_width, cc.eye_height, kW, kH);
        const auto c = drawn_centre(bgr, tg.colour, r);
        if (!c) continue;
        ++visible;
        // The mouse there: the ray through what the mirror draws under it (as the frame loop).
        xr::MouseMoveEvent m{c->x, c->y};
        m.ray = xr::mirror_ray(g, c->x, c->y);
        m.over_view = m.ray.has_value();
        sim->push_event(m);
        t += 33'333'333;
        ed.update(sim->poll(t), t);
        const std::string got = hovered_id(ed);
        const bool ok = got == tg.widget;
        hit += ok;
        EXPECT_TRUE(ok) << xr::mirror_mode_name(mode) << " eye " << e << ": " << tg.panel << "/"
                        << tg.widget << " drawn at (" << c->x << ", " << c->y
                        << ") but the ray hits \"" << got << "\"";
        // Control: the window taken as a plain pinhole (what the sim did before, whatever the
        // mirror showed) misses in the headset mirrors, so this test can fail.
        sim->push_event(xr::MouseMoveEvent{c->x, c->y});
        t += 33'333'333;
        ed.update(sim->poll(t), t);
        pinhole_hits += hovered_id(ed) == tg.widget;
        char buf[64];
        std::snprintf(buf, sizeof buf, "%s(%.0f, %.0f) %s", cell.empty() ? "" : "; ", c->x, c->y,
                      ok ? "hit" : "MISS");
        cell += buf;
      }
      rows[tg.panel + "/" + tg.widget] +=
          " " + (cell.empty() ? std::string("not in view") : cell) + " |";
    }
    EXPECT_EQ(hit, visible) << xr::mirror_mode_name(mode);
    if (mode == xr::MirrorMode::Desktop)
      EXPECT_EQ(pinhole_hits, visible) << "the desktop view is that pinhole";
    else
      EXPECT_LT(pinhole_hits, visible / 2)
          << xr::mirror_mode_name(mode) << ": the control should miss";
    // The desktop view shows every widget; the headset mirrors most (the eyes see less).
    if (mode == xr::MirrorMode::Desktop)
      EXPECT_EQ(visible, static_cast<int>(targets.size()));
    else
      EXPECT_GE(visible, static_cast<int>(targets.size()) / 2) << xr::mirror_mode_name(mode);
  }
  for (const auto& [name, row] : rows) table << "| " << name << " |" << row << "\n";
  std::ofstream(std::string(VDFX_TEST_OUTPUT_DIR) + "/pointing_table.md") << table.str();
}

}  // namespace
}  // namespace vdfx::app
