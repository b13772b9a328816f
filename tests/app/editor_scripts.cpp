/// @file
/// @brief Scripted editor sessions behind recordings/editor_*.vdrec.jsonl and demo.vdrec.jsonl.
#include "editor_scripts.h"

#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>

#include "app/editor/editor_panels.h"
#include "effects/effect_types.h"
#include "ui/colour_wheel.h"
#include "xr/input/input_backend.h"
#include "xr/render/mirror.h"

namespace vdfx::app::test {

namespace {

xr::SimConfig script_sim() {
  xr::SimConfig c;
  c.window_width = kScriptViewport.width;
  c.window_height = kScriptViewport.height;
  c.hfov_deg = kScriptViewport.hfov_deg;
  c.look = xr::LookMode::Mouselook;  // the scripts' look() turns the way the mouse moves
  c.look_deg_per_px = 0.2;           // the fixed rate look() drags at (not the cursor's)
  return c;
}

std::shared_ptr<const ui::FontSet> fonts() {
  static const auto f = std::make_shared<const ui::FontSet>(ui::FontSet::load());
  return f;
}

// The panels as the editor lays them out for the sim at its first frame.
EditorPanels& panels_for(int frames) {
  static std::map<int, std::unique_ptr<EditorPanels>> cache;
  auto& p = cache[frames];
  if (!p) {
    p = std::make_unique<EditorPanels>(fonts(), frames, PanelLayout::Desktop, kScriptViewport);
    p->place(xr::create_sim_backend(script_sim())->poll(0));
  }
  return *p;
}

// The window position where the desktop view draws a world point (the head at rest).
glm::dvec2 project(const glm::dvec3& world) {
  const xr::InputState in = xr::create_sim_backend(script_sim())->poll(0);
  const auto g = xr::MirrorGeometry::from_profile(
      xr::load_hmd_profile("generic90"), xr::MirrorMode::Desktop, 1, 1, kScriptViewport.width,
      kScriptViewport.height, kScriptViewport.hfov_deg);
  return *xr::mirror_pixel_of(g, in.head.inverse().transform(world));
}

ui::Panel& panel_of(EditorPanels& p, const std::string& id) {
  return *p.panel(id);
}

// Lays out the panels as the editor shows `target` (its widgets have rectangles only then).
EditorPanels& panels_showing(EditTarget target) {
  auto& p = panels_for(1);
  EditorView v;
  v.effect = target;
  v.values = target.neutral();
  p.show(v);
  return p;
}

// Pixel of a value on the effect panel's widgets.
glm::dvec2 slider_cursor(const std::string& id, double v) {
  auto& p = panels_for(1);
  auto* s = panel_of(p, kEffectPanelId).find_as<ui::Slider1D>(id);
  if (s->rect().w == 0)  // per-effect sliders are laid out only while shown
    panels_showing(*effects::effect_type_from_name(id));
  const double t = (v - s->axis().min) / (s->axis().max - s->axis().min);
  const glm::dvec2 px{s->track_x0() + t * (s->track_x1() - s->track_x0()),
                      s->rect().y + s->rect().h * 0.5};
  return cursor_for(kEffectPanelId, px);
}

glm::dvec2 pad_cursor(double x, double y) {
  auto& p = panels_showing(effects::EffectType::Vignette);
  auto* pad = panel_of(p, kEffectPanelId).find_as<ui::Pad2D>("vignette");
  const ui::Rect a = pad->area();
  return cursor_for(kEffectPanelId,
                    {a.x + a.w * (x / 180.0), a.y + a.h - a.h * ((y - 0.01) / (180.0 - 0.01))});
}

glm::dvec2 wheel_cursor(double hue_deg, double sat) {
  auto& p = panels_showing(effects::EffectType::Tint);
  auto* w = panel_of(p, kEffectPanelId).find_as<ui::ColourWheel>("tint");
  const double a = hue_deg * 3.14159265358979323846 / 180.0;
  const glm::dvec2 px =
      w->disc_centre() + sat * w->disc_radius() * glm::dvec2(std::cos(a), -std::sin(a));
  return cursor_for(kEffectPanelId, px);
}

glm::dvec2 menu_cursor(int item) {
  const ui::Rect r = panels_for(1).menu().cell(item);
  return cursor_for(kEffectPanelId, {r.x + r.w * 0.5, r.y + r.h * 0.5});
}

glm::dvec2 strip_cursor(int frame, int frames) {
  auto& p = panels_for(frames);
  const ui::Rect r = p.strip().rect();
  return cursor_for(kTimelinePanelId, {p.strip().x_of(frame), r.y + r.h * 0.5}, frames);
}

// A sim session being recorded, one poll per 30 Hz frame.
class Session {
 public:
  Session(const std::filesystem::path& file, const std::string& note,
          std::optional<std::string> video)
      : rec_(xr::create_recording_backend(
            xr::create_sim_backend(script_sim()), file,
            {"sim", std::move(video), note,
             io::RecordedDesktopView{kScriptViewport.width, kScriptViewport.height,
                                     kScriptViewport.hfov_deg}})) {}
  void frames(int n) {
    for (int i = 0; i < n; ++i) rec_->poll(f_++ * kFrameNs);
  }
  void cursor(glm::dvec2 p) {
    rec_->push_event(xr::MouseMoveEvent{p.x, p.y});
    mouse_ = p;
    frames(1);
  }
  // Turn the head by right-dragging (0.2 deg per pixel; drag down looks down).
  void look(double daz_deg, double dalt_deg, int steps = 10) {
    rec_->push_event(xr::MouseButtonEvent{xr::MouseButton::Right, true});
    frames(1);
    const glm::dvec2 start = mouse_;
    for (int i = 1; i <= steps; ++i) {
      const double a = static_cast<double>(i) / steps;
      mouse_ = start + a * glm::dvec2(daz_deg / 0.2, -dalt_deg / 0.2);
      rec_->push_event(xr::MouseMoveEvent{mouse_.x, mouse_.y});
      frames(1);
    }
    rec_->push_event(xr::MouseButtonEvent{xr::MouseButton::Right, false});
    frames(2);
  }
  void click(glm::dvec2 p) {
    cursor(p);
    rec_->push_event(xr::MouseButtonEvent{xr::MouseButton::Left, true});
    frames(3);
    rec_->push_event(xr::MouseButtonEvent{xr::MouseButton::Left, false});
    frames(3);
  }
  void drag(glm::dvec2 a, glm::dvec2 b, int steps = 8) {
    cursor(a);
    rec_->push_event(xr::MouseButtonEvent{xr::MouseButton::Left, true});
    frames(1);
    for (int i = 1; i <= steps; ++i) {
      const glm::dvec2 p = a + (b - a) * (static_cast<double>(i) / steps);
      rec_->push_event(xr::MouseMoveEvent{p.x, p.y});
      mouse_ = p;
      frames(1);
    }
    rec_->push_event(xr::MouseButtonEvent{xr::MouseButton::Left, false});
    frames(3);
  }
  // Hold the trigger (Space) with the cursor off the panels: preview, then place.
  void place(int hold = 8) {
    cursor({640.0, 200.0});
    key_down(xr::Key::Space);
    frames(hold);
    key_up(xr::Key::Space);
    frames(3);
  }
  void key(xr::Key k, int hold = 3) {
    key_down(k);
    frames(hold);
    key_up(k);
    frames(3);
  }
  // Press and hold a key across other actions (a grab), then let go.
  void hold(xr::Key k) {
    key_down(k);
    frames(2);
  }
  void release(xr::Key k) {
    key_up(k);
    frames(3);
  }

 private:
  void key_down(xr::Key k) { rec_->push_event(xr::KeyEvent{k, true}); }
  void key_up(xr::Key k) { rec_->push_event(xr::KeyEvent{k, false}); }
  std::unique_ptr<xr::InputBackend> rec_;
  int f_ = 0;
  glm::dvec2 mouse_{640.0, 360.0};
};

void editor_place_exposure(const std::filesystem::path& file) {
  Session s(
      file,
      "editor: exposure +2 at az -40, -1.5 at az 40 alt 10 (B held once), undo (button), redo (Y)",
      "/usr/share/blender/datafiles/studiolights/world/sunrise.exr");
  s.frames(5);
  s.click(slider_cursor("exposure", 2.0));
  s.look(-40.0, 0.0);
  s.place();
  s.click(slider_cursor("exposure", -1.5));
  s.look(80.0, 10.0);
  s.place();
  s.key(xr::Key::K, 6);  // B: the unaltered film
  s.click(widget_cursor(kEffectPanelId, "undo"));
  s.key(xr::Key::Y);  // left y: redo
  s.frames(5);
}

void editor_all_widgets(const std::filesystem::path& file) {
  Session s(file,
            "editor: every effect and widget on a 90-frame 30 fps clip (see recordings/README.md)",
            std::nullopt);
  const int n = kClipFrames;
  s.frames(5);
  s.click(menu_cursor(0));  // blur: drag the slider 0 -> 2, place at (0, 0) frame 0
  s.drag(slider_cursor("blur", 0.0), slider_cursor("blur", 2.0));
  s.place();
  s.click(menu_cursor(1));  // tint: wheel hue 120 sat 0.6, place at (30, 0) frame 0
  s.click(wheel_cursor(120.0, 0.6));
  s.look(30.0, 0.0);
  s.place();
  s.click(menu_cursor(2));  // exposure: scrub to 45, +1 at (30, 0)
  s.drag(strip_cursor(0, n), strip_cursor(45, n));
  s.click(slider_cursor("exposure", 1.0));
  s.place();
  s.click(menu_cursor(3));  // saturation 0.5 at (-30, 0) frame 45
  s.click(slider_cursor("saturation", 0.5));
  s.look(-60.0, 0.0);
  s.place();
  s.click(menu_cursor(4));  // contrast 1.5 then 2.0 at the same place: replaced
  s.click(slider_cursor("contrast", 1.5));
  s.place();
  s.click(slider_cursor("contrast", 2.0));
  s.place();
  s.click(menu_cursor(5));  // vignette: pad radius 60 falloff 40; exponent 1.5
  s.click(pad_cursor(60.0, 40.0));
  s.place();
  s.drag(slider_cursor("exponent", 1.0), slider_cursor("exponent", 1.5));
  s.click(menu_cursor(2));  // exposure: -1 at (-30, 0) frame 45, then delete the one at (30, 0)
  s.click(slider_cursor("exposure", -1.0));
  s.place();
  s.look(60.0, 0.0);
  s.key(xr::Key::J);  // right a: delete nearest
  s.key(xr::Key::X);  // left x: undo
  s.key(xr::Key::Y);  // left y: redo
  s.click(widget_cursor(kEffectPanelId, "undo"));
  s.click(widget_cursor(kEffectPanelId, "redo"));
  s.click(widget_cursor(kTimelinePanelId, "play", n));  // play half a second, pause
  s.frames(15);
  s.click(widget_cursor(kTimelinePanelId, "play", n));
  s.click(widget_cursor(kTimelinePanelId, "prev_key", n));
  s.click(widget_cursor(kViewsPanelId, "show_minimap", n));
  s.click(widget_cursor(kViewsPanelId, "show_minimap", n));
  s.click(widget_cursor(kViewsPanelId, "lock", n));
  s.click(widget_cursor(kViewsPanelId, "lock", n));
  s.frames(5);
}

void editor_move_keyframe(const std::filesystem::path& file) {
  Session s(
      file,
      "editor: two exposure keyframes; grab (G) the one at az 40, carry it 15 right, 10 up and 30 "
      "frames "
      "later, set its value to +2.5; deselect (L); chosen value 0.5 (see recordings/README.md)",
      std::nullopt);
  const int n = kClipFrames;
  s.frames(5);
  s.click(slider_cursor("exposure", 1.0));  // A: +1 at (-20, 0) frame 0
  s.look(-20.0, 0.0);
  s.place();
  s.click(slider_cursor("exposure", -1.0));  // B: -1 at (40, 0) frame 0
  s.look(60.0, 0.0);
  s.place();
  s.hold(xr::Key::G);  // right squeeze: grab B (nearest the view), hold it
  s.look(15.0, 10.0);  // it follows the view ...
  s.drag(strip_cursor(0, n), strip_cursor(30, n));  // ... and the playhead
  s.release(xr::Key::G);  // release: one move to (55, 10) frame 30; B stays selected
  s.click(slider_cursor("exposure", 2.5));  // edits B's value, not the chosen one
  s.key(xr::Key::L);                        // right thumbstick click: deselect
  s.click(slider_cursor("exposure", 0.5));  // the chosen value again
  s.frames(5);
}

void demo(const std::filesystem::path& file) {
  Session s(file,
            "demo on sunrise.exr: calm the sun, lift the shadows, warm the sunrise, focus with a "
            "vignette",
            "/usr/share/blender/datafiles/studiolights/world/sunrise.exr");
  s.frames(15);
  s.look(36.0, 8.0, 30);  // the sun
  s.frames(10);
  s.click(slider_cursor("exposure", -1.0));
  s.place(15);
  s.click(menu_cursor(3));
  s.click(slider_cursor("saturation", 1.4));
  s.place(15);
  s.click(menu_cursor(1));
  s.click(wheel_cursor(30.0, 0.35));
  s.place(15);
  s.click(menu_cursor(5));
  s.click(pad_cursor(35.0, 45.0));
  s.place(15);
  s.look(180.0, -8.0, 45);  // away from the sun: brighter, desaturated, no vignette
  s.frames(10);
  s.click(menu_cursor(2));
  s.click(slider_cursor("exposure", 1.0));
  s.place(15);
  s.click(menu_cursor(3));
  s.click(slider_cursor("saturation", 0.6));
  s.place(15);
  s.click(menu_cursor(5));
  s.click(pad_cursor(90.0, 90.0));
  s.place(15);
  s.look(-180.0, 0.0, 60);  // back towards the sun to see the blend
  s.frames(30);
}

}  // namespace

glm::dvec2 cursor_for(const std::string& panel, glm::dvec2 pixel, int frames) {
  return project(panel_of(panels_for(frames), panel).world_of_pixel(pixel));
}

glm::dvec2 widget_cursor(const std::string& panel, const std::string& widget, int frames) {
  const ui::Widget* w = panel_of(panels_for(frames), panel).find(widget);
  if (!w) throw std::invalid_argument("widget_cursor: no widget " + widget + " on panel " + panel);
  const ui::Rect r = w->rect();
  return cursor_for(panel, {r.x + r.w * 0.5, r.y + r.h * 0.5}, frames);
}

const std::vector<EditorScript>& editor_scripts() {
  static const std::vector<EditorScript> scripts = {
      {"editor_place_exposure.vdrec.jsonl", editor_place_exposure},
      {"editor_all_widgets.vdrec.jsonl", editor_all_widgets},
      {"editor_move_keyframe.vdrec.jsonl", editor_move_keyframe},
      {"demo.vdrec.jsonl", demo},
  };
  return scripts;
}

}  // namespace vdfx::app::test
