/// @file
/// @brief EditorClient: Editor -> FrameClient (playhead, parameters, panel quads).
#include "app/editor_client.h"

#include <algorithm>

#include "effects/effect_shaders.h"

namespace vdfx::app {

void unpremultiply_flipped(const cv::Mat& src, const cv::Rect& r, cv::Mat& out) {
  const int h = src.rows;
  for (int y = r.y; y < r.y + r.height; ++y) {
    const auto* s = src.ptr<cv::Vec4b>(y);
    auto* d = out.ptr<cv::Vec4b>(h - 1 - y);
    for (int x = r.x; x < r.x + r.width; ++x) {
      const cv::Vec4b p = s[x];
      const int a = p[3];
      if (a == 255 || a == 0) {
        d[x] = p;  // opaque: already straight; transparent: colour irrelevant (premultiplied 0)
        continue;
      }
      // Round to nearest; premultiplied colour never exceeds alpha, so the result is <= 255.
      for (int c = 0; c < 3; ++c) d[x][c] = static_cast<uchar>(std::min(255, (p[c] * 255 + a / 2) / a));
      d[x][3] = p[3];
    }
  }
}

EditorClient::EditorClient(Editor& editor, std::unique_ptr<PanelTextures> textures)
    : editor_(editor), textures_(std::move(textures)) {}

void EditorClient::update(const xr::InputState& input, std::int64_t t, FrameInfo& info) {
  editor_.update(input, t);
  info.video_frame = editor_.frame();
  info.video_paused = !editor_.playing();
  info.video_loop = true;  // the editor's playhead wraps (or stops) itself; the decoder follows it

  // Compiled-in effects: those with keyframes, plus the one being previewed.
  const Document& doc = editor_.document();
  unsigned mask = 0;
  std::vector<double> key = {static_cast<double>(doc.revision()), editor_.previewing() ? 1.0 : 0.0,
                             editor_.unaltered() ? 1.0 : 0.0};
  for (const auto& spec : effects::all_effect_specs()) {
    if (!doc.keyframes(spec.type).empty()) mask |= effects::shader_bit(spec.type);
    // A finished asynchronous solve changes the answers without an edit.
    key.push_back(static_cast<double>(doc.keyframe_set(spec.type).solution_version()));
  }
  if (editor_.previewing()) {
    const effects::EffectType e = editor_.current_effect();
    mask |= effects::shader_bit(e);
    // The preview follows the view centre, the frame and the chosen values.
    key.insert(key.end(), {editor_.view_direction().azimuth_deg, editor_.view_direction().altitude_deg,
                           static_cast<double>(editor_.frame()), static_cast<double>(e)});
    const auto& chosen = doc.params(e);
    key.insert(key.end(), chosen.begin(), chosen.end());
  }
  if (editor_.grabbing()) {
    // The held keyframe follows the view and the playhead before the move is committed.
    key.push_back(2.0);
    if (const auto k = editor_.selected_preview())
      key.insert(key.end(), {k->direction.azimuth_deg, k->direction.altitude_deg, static_cast<double>(k->frame),
                             static_cast<double>(*editor_.selected_keyframe())});
  }
  active_ = mask;
  if (key != revision_key_) {
    revision_key_ = std::move(key);
    ++revision_;
  }
}

effects::StackParams EditorClient::params(const effects::Direction& direction, std::int64_t video_frame) {
  return editor_.params_for_view(direction, video_frame);
}

std::vector<xr::QuadLayer> EditorClient::quads() {
  std::vector<xr::QuadLayer> out;
  if (!textures_) return out;
  const std::vector<ui::Panel*> panels = editor_.panels();
  if (slots_.size() < panels.size()) slots_.resize(panels.size());
  for (std::size_t i = 0; i < panels.size(); ++i) {
    ui::Panel& p = *panels[i];
    if (!p.visible()) continue;
    Slot& s = slots_[i];
    const bool fresh = s.panel != &p || s.texture == 0 || s.straight.cols != p.width_px() ||
                       s.straight.rows != p.height_px();
    std::vector<cv::Rect> regions;  // in the panel's pixels (top-down)
    if (!fresh) {
      for (const ui::Rect& r : p.dirty_rects())
        regions.emplace_back(static_cast<int>(r.x), static_cast<int>(r.y), static_cast<int>(r.w),
                             static_cast<int>(r.h));
    }
    // Someone else rendered it since our last upload: the damage is unknown, upload it all.
    const bool foreign = p.render_count() != s.render_count;
    const cv::Mat& tex = p.texture();  // renders when dirty
    if (fresh || foreign || p.render_count() != s.render_count) {
      const cv::Rect whole(0, 0, tex.cols, tex.rows);
      if (fresh) s.straight.create(tex.rows, tex.cols, CV_8UC4);
      if (fresh || foreign) regions = {whole};
      std::vector<cv::Rect> flipped;
      for (cv::Rect r : regions) {
        r &= whole;
        if (r.empty()) continue;
        unpremultiply_flipped(tex, r, s.straight);
        flipped.emplace_back(r.x, tex.rows - r.y - r.height, r.width, r.height);
        uploaded_pixels_ += r.area();
      }
      s.texture = textures_->upload(i, s.straight, fresh ? std::vector<cv::Rect>{} : flipped);
      s.panel = &p;
      s.render_count = p.render_count();
      ++uploads_;
    }
    xr::QuadLayer q;
    q.space = xr::ReferenceSpace::Local;
    q.pose = p.pose();
    q.size_m = {p.size_m().x, p.size_m().y};
    q.texture = s.texture;
    out.push_back(q);
  }
  return out;
}

void EditorClient::release_textures() {
  if (textures_) textures_->release();
  for (Slot& s : slots_) s = Slot{};
}

std::string EditorClient::status_line() const { return editor_.status_text(); }

std::string EditorClient::controls_text() {
  return "  right trigger (on no panel) preview the current effect's values at the view centre;\n"
         "                            release places a keyframe there at the current frame\n"
         "  right trigger (on a panel) use the panel (menus, sliders, buttons, timeline)\n"
         "  left trigger + left aim   use the panels not held by the left hand\n"
         "  right a                   delete the selected keyframe, else the one nearest the view\n"
         "  right squeeze (held)      grab the keyframe nearest the view and select it: it follows\n"
         "                            the view and the playhead while held; release moves it there\n"
         "                            (one undo step); while selected the effect widget edits its values\n"
         "  right thumbstick click    deselect (so does the Deselect button or a trigger placement)\n"
         "  right b (held)            unaltered film (no effects) while held\n"
         "  left x / left y           undo / redo\n"
         "  thumbstick                adjust the widget that hand's pointer focused last\n"
         "Panels: effects (effect menu, the effect's widget, undo / redo, delete, deselect,\n"
         "exponent and time scale, autosave status) and timeline (play, previous / next keyframe, strip,\n"
         "track plot, minimap, lock in world). --input sim: both panels in front of the head, the\n"
         "mouse-driven right aim ray reaches both; a headset: on the left and right grips.\n";
}

}  // namespace vdfx::app
