/// @file
/// @brief EditorClient: Editor -> FrameClient (playhead, parameters, panel quads).
#include "app/window/editor_client.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <opencv2/core.hpp>

#include "app/editor/bindings.h"
#include "app/window/flare_layouts.h"
#include "effects/effect_shaders.h"

namespace vdfx::app {

EditorClient::EditorClient(Editor& editor, std::unique_ptr<PanelTextures> textures,
                           bool follow_window)
    : editor_(editor), textures_(std::move(textures)), follow_window_(follow_window) {}

void EditorClient::on_desktop_event(const xr::DesktopEvent& event) {
  if (const auto* g = std::get_if<xr::ViewGeometryEvent>(&event);
      g && follow_window_ && g->width_px > 0)
    editor_.set_viewport({g->width_px, g->height_px, g->hfov_deg});
}

void EditorClient::update(const xr::InputState& input, std::int64_t t, FrameInfo& info) {
  // Frames per second of display time over about a second, for the heads-up line.
  if (fps_t0_ < 0) fps_t0_ = t;
  ++fps_frames_;
  if (t - fps_t0_ >= 1'000'000'000) {
    fps_ = fps_frames_ * 1e9 / static_cast<double>(t - fps_t0_);
    fps_t0_ = t;
    fps_frames_ = 0;
  }
  editor_.set_loop_status(fps_, info.shown_video_frame < 0);
  if (thumbnails_)
    if (auto thumbs = thumbnails_->take()) editor_.set_thumbnails(std::move(*thumbs));
  // A keyframe placed (the preview let go into the document): the controller's pulse.
  const bool was_previewing = editor_.previewing();
  const std::uint64_t revision_before = editor_.document().revision();
  editor_.update(input, t);
  if (was_previewing && !editor_.previewing() && editor_.document().revision() != revision_before)
    info.haptic_pulse = xr::Hand::Right;
  layers_.update(editor_);
  info.video_frame = editor_.frame();
  info.video_paused = !editor_.playing();
  info.video_loop = true;  // the editor's playhead wraps (or stops) itself; the decoder follows it

  // Compiled-in effects: those with keyframes, plus the one being placed.
  const Document& doc = editor_.document();
  unsigned mask = 0;
  for (const auto& spec : effects::all_effect_specs())
    if (!doc.keyframes(spec.type).empty()) mask |= effects::shader_bit(spec.type);
  const PendingEdit* pending = doc.pending();
  if (const auto type = pending ? pending->target().stack_effect() : std::nullopt)
    mask |= effects::shader_bit(*type);
  active_ = mask;
  // params() answers differently after an edit, a finished asynchronous solve, a move of the
  // pending keyframe, or the unaltered switch.
  const AnswersKey key{doc.revision(), doc.solutions_version(), pending ? pending->version() : 0,
                       pending != nullptr, editor_.unaltered()};
  if (!(key == answers_)) {
    answers_ = key;
    ++revision_;
  }
}

effects::StackParams EditorClient::params(const effects::Direction& direction,
                                          std::int64_t video_frame) {
  return editor_.params_for_view(direction, video_frame);
}

std::vector<effects::FlareLayout> EditorClient::flares(const xr::Pose& head,
                                                       std::int64_t video_frame,
                                                       const io::Picture* picture) {
  return flare_layouts(layers_.flares(), head, video_frame, picture);
}

std::vector<effects::GrainFrame> EditorClient::grains(const xr::Pose& head,
                                                      std::int64_t display_time_ns,
                                                      std::int64_t video_frame) {
  return layers_.grains().layout({xr::position_of(head), xr::rotation_of(head)}, display_time_ns,
                                 video_frame);
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
    const bool fresh = s.panel != &p || s.texture == 0 || s.width != p.texture_width() ||
                       s.height != p.texture_height();
    std::vector<cv::Rect> regions;  // in the texture's pixels
    if (!fresh) {
      for (const ui::Rect& r : p.dirty_rects())
        regions.emplace_back(static_cast<int>(r.x), static_cast<int>(r.y), static_cast<int>(r.w),
                             static_cast<int>(r.h));
    }
    // Someone else rendered it since our last upload: the damage is unknown, upload it all.
    const bool foreign = p.render_count() != s.render_count;
    const cv::Mat& tex = p.texture();  // renders when dirty
    if (fresh || foreign || p.render_count() != s.render_count) {
      // The panel's own pixels go up as they are: premultiplied, first row at the quad's top.
      const cv::Rect whole(0, 0, tex.cols, tex.rows);
      if (fresh || foreign) regions = {whole};
      std::vector<cv::Rect> inside;
      for (cv::Rect r : regions) {
        r &= whole;
        if (r.empty()) continue;
        inside.push_back(r);
      }
      s.texture = textures_->upload(i, tex, fresh ? std::vector<cv::Rect>{} : inside);
      s.panel = &p;
      s.width = tex.cols;
      s.height = tex.rows;
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
  add_pointer_quads(out);
  return out;
}

namespace {

/// A disc (ring_width 0) or a ring, white with a dark outline so it reads on any video;
/// premultiplied alpha, anti-aliased, size x size.
cv::Mat mark_image(int size, double ring_width) {
  cv::Mat img(size, size, CV_8UC4);
  const double c = 0.5 * size, outer = 0.5 * size - 1.0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double d = std::hypot(x + 0.5 - c, y + 0.5 - c);
      const double inner = ring_width > 0.0 ? outer - ring_width : -1.0;
      const double cover =
          std::clamp(outer - d + 0.5, 0.0, 1.0) * std::clamp(d - inner + 0.5, 0.0, 1.0);
      const double edge = 0.18 * size;  // dark outline on both edges
      const bool dark = outer - d < edge || (ring_width > 0.0 && d - inner < edge);
      const double v = (dark ? 20.0 : 250.0) * cover;  // premultiplied
      img.at<cv::Vec4b>(y, x) = {
          static_cast<uchar>(std::lround(v)), static_cast<uchar>(std::lround(v)),
          static_cast<uchar>(std::lround(v)), static_cast<uchar>(std::lround(255.0 * cover))};
    }
  return img;
}

/// A soft line seen across: alpha peaks in the middle column (premultiplied).
cv::Mat ray_image() {
  cv::Mat img(4, 16, CV_8UC4);
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x) {
      const double t = 1.0 - std::abs(x + 0.5 - 8.0) / 8.0, a = 200.0 / 255.0 * t * t;
      img.at<cv::Vec4b>(y, x) = {
          static_cast<uchar>(std::lround(120 * a)), static_cast<uchar>(std::lround(200 * a)),
          static_cast<uchar>(std::lround(255 * a)), static_cast<uchar>(std::lround(255 * a))};
    }
  return img;
}

/// A quad centred at `centre` whose +z is `facing` (towards the viewer), `up` giving its +y.
xr::QuadLayer billboard(const glm::dvec3& centre, const glm::dvec3& facing, glm::dvec3 up,
                        glm::dvec2 size, unsigned texture) {
  glm::dvec3 z = glm::normalize(facing);
  if (std::abs(glm::dot(z, glm::normalize(up))) > 0.999)
    up = std::abs(z.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  const glm::dvec3 x = glm::normalize(glm::cross(up, z));
  const glm::dvec3 y = glm::cross(z, x);
  xr::QuadLayer q;
  q.space = xr::ReferenceSpace::Local;
  q.pose = {centre, glm::normalize(glm::quat_cast(glm::dmat3(x, y, z)))};
  q.size_m = {size.x, size.y};
  q.texture = texture;
  return q;
}

}  // namespace

unsigned EditorClient::texture_of(std::size_t slot, const cv::Mat& image) {
  return textures_->upload(slot, image, {});
}

void EditorClient::add_pointer_quads(std::vector<xr::QuadLayer>& out) {
  pointer_quads_.clear();
  if (!textures_) return;
  const std::size_t base = 1000;  // texture slots after the panels'
  if (!pointer_textures_[0]) {
    const cv::Mat dot = mark_image(64, 0.0), ring = mark_image(64, 12.0), ray = ray_image();
    pointer_textures_ = {texture_of(base, dot), texture_of(base + 1, ring),
                         texture_of(base + 2, ray)};
  }
  const xr::InputState& in = editor_.input();
  const glm::dvec3 eye = in.head.position;
  // Marks lie parallel to the view plane, so they look round anywhere in a wide desktop view.
  const glm::dvec3 back = -xr::forward(in.head), up = in.head.rotate({0.0, 1.0, 0.0});
  const auto size_at = [&](double deg, const glm::dvec3& p) {
    return 2.0 * glm::length(p - eye) * std::tan(0.5 * glm::radians(deg));
  };
  for (const xr::Hand h : {xr::Hand::Left, xr::Hand::Right}) {
    const xr::HandState& hs = in.hand(h);
    if (!hs.tracked) continue;
    const ui::Pointer& ptr = editor_.pointer(h);
    const glm::dvec3 origin = hs.aim.position, dir = xr::forward(hs.aim);
    // The dot sits where the ray meets a panel, else far along it, over the video.
    const bool on_panel = ptr.hit().has_value();
    if (h == xr::Hand::Left && editor_.ui().layout() == PanelLayout::Desktop)
      continue;  // the sim's resting hand
    glm::dvec3 end = on_panel ? ptr.hit()->panel->world_of_pixel(ptr.hit()->pixel)
                              : origin + drawing_.far_m * dir;
    if (on_panel) end += 0.002 * ptr.hit()->panel->normal();  // just in front of the panel
    const double d = size_at(drawing_.dot_deg, end);
    pointer_quads_.push_back(billboard(end, back, up, {d, d}, pointer_textures_[0]));
    // The ray itself, from the controller to the dot; seen end-on (a point) when it starts at
    // the eye, as the sim's mouse ray does in the desktop view.
    const glm::dvec3 seg = end - origin;
    if (glm::length(origin - eye) > 0.02 && glm::length(seg) > 0.02)
      pointer_quads_.push_back(
          billboard(0.5 * (origin + end), eye - 0.5 * (origin + end), glm::normalize(seg),
                    {drawing_.ray_width_m, glm::length(seg)}, pointer_textures_[2]));
  }
  // The placement reticle at the view centre, head-locked.
  const glm::dvec3 centre = eye + 2.0 * xr::forward(in.head);
  const double r = size_at(drawing_.reticle_deg, centre);
  pointer_quads_.push_back(billboard(centre, back, up, {r, r}, pointer_textures_[1]));
  out.insert(out.end(), pointer_quads_.begin(), pointer_quads_.end());
}

void EditorClient::release_textures() {
  if (textures_) textures_->release();
  for (Slot& s : slots_) s = Slot{};
}

std::string EditorClient::status_line() const {
  return editor_.status_text();
}

std::string EditorClient::controls_text() {
  // The controls come from the binding table; what the panels hold is said once, here.
  return bindings_help_text() +
         "Panels: effects (menu, the effect's widget, undo / redo, delete, deselect, exponent, "
         "the\n"
         "time scale as degrees of view per second of video, autosave status), timeline (play,\n"
         "previous / next keyframe, time, thumbnails and keyframes on the strip), plot and "
         "minimap\n"
         "(with toggles and lock in world), and on the desktop a heads-up line (frame, time,\n"
         "heading, effect, selection, frame rate, the latest message; READ-ONLY first when\n"
         "another editor has the sidecar open).\n";
}

}  // namespace vdfx::app
