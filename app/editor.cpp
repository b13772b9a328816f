/// @file
/// @brief Editor: actions -> edits, preview, playback, panels and visualizations.
#include "app/editor.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/visualizations.h"
#include "ui/colour_wheel.h"

namespace vdfx::app {

using effects::Direction;
using effects::EffectType;

namespace {
std::shared_ptr<const ui::FontSet> fonts_or_default(std::shared_ptr<const ui::FontSet> f) {
  return f ? f : std::make_shared<const ui::FontSet>(ui::FontSet::load());
}
double angle_deg(const Direction& a, const Direction& b) {
  return effects::angle_between(effects::to_unit(a), effects::to_unit(b)) * effects::kRadToDeg;
}
std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}
std::string title_case(std::string_view s) {
  std::string n(s);
  if (!n.empty()) n[0] = static_cast<char>(n[0] - 'a' + 'A');
  return n;
}
}  // namespace

Editor::Editor(io::Sidecar sidecar, DocumentOptions document_options, EditorOptions options)
    : doc_(std::move(sidecar), document_options),
      options_(options),
      panels_(fonts_or_default(options.fonts), doc_.video().frames, options.layout, options.viewport),
      fps_(io::fps_to_rational(doc_.video().fps)),
      input_(xr::neutral_input_state(0)),
      preview_(document_options.keyframes) {
  track_frames_ = track_sample_frames(doc_.video().frames, options_.track_samples);
  if (options_.async_visualizations) minimap_worker_ = std::make_unique<MinimapWorker>();
  if (options_.autosave_path) {
    autosave_ = std::make_unique<Autosave>(*options_.autosave_path);
    doc_.set_change_listener([this] { autosave_->save(doc_.sidecar()); });
  }
  select_effect(EffectType::Exposure);
}

void Editor::update(const xr::InputState& input, std::int64_t t_ns) {
  const double dt = last_t_ ? std::max<double>(0.0, static_cast<double>(t_ns - *last_t_) * 1e-9) : 0.0;
  last_t_ = t_ns;
  now_ = t_ns;
  input_ = input;
  if (!message_.empty() && t_ns - message_t_ > kMessageLifetimeNs) message_.clear();
  if (input.head_tracked) view_ = effects::from_unit([&] {
    const glm::dvec3 f = xr::forward(input.head);
    return Eigen::Vector3d(f.x, f.y, f.z);
  }());
  if (playing_) {
    // Frames elapsed since play was pressed, from the elapsed time itself (adding two rounded
    // frame start times could land a nanosecond short of a frame).
    const std::int64_t n = doc_.video().frames;
    const std::int64_t f = play_f0_ + io::frame_at_time(t_ns - play_t0_, fps_);
    frame_ = options_.loop ? ((f % n) + n) % n : std::clamp<std::int64_t>(f, 0, n - 1);
  }

  panels_.place(input);

  // Pointers: each hand's aim ray drives the panels not attached to it; the other hand's grip
  // held (Shift in the sim) makes a drag fine.
  auto pointer_input = [&](const xr::HandState& h, xr::Hand other) {
    ui::PointerInput p;
    if (!h.tracked) {
      p.ray.direction = glm::dvec3(0.0);  // parallel to everything: hits nothing
      return p;
    }
    p.ray = {h.aim.position, xr::forward(h.aim)};
    p.trigger = h.trigger;
    p.thumbstick = h.thumbstick;
    p.fine = input.edges.is_down(other, xr::Control::Squeeze);
    return p;
  };
  std::vector<ui::Event> events;
  {
    auto reach = panels_.reachable_by(xr::Hand::Left);
    auto ev = left_ptr_.update(reach, pointer_input(input.left, xr::Hand::Right), dt);
    events.insert(events.end(), ev.begin(), ev.end());
  }
  {
    auto reach = panels_.reachable_by(xr::Hand::Right);
    auto ev = right_ptr_.update(reach, pointer_input(input.right, xr::Hand::Left), dt);
    events.insert(events.end(), ev.begin(), ev.end());
  }
  validate_selection();  // the document may have been edited from outside (tests, tools)
  for (const auto& e : events) handle(e);

  // Buttons act on their edges (a tap between two frames is down in exactly one poll).
  using xr::Control;
  using xr::Hand;
  const xr::ActionEdges& edges = input.edges;
  // Grab: right squeeze selects the nearest keyframe and holds it; release commits the move.
  if (edges.was_pressed(Hand::Right, Control::Squeeze)) grab();
  if (!edges.is_down(Hand::Right, Control::Squeeze) && grabbing_) grab_release();
  if (edges.was_pressed(Hand::Right, Control::StickClick)) deselect();

  // Placement: a right-trigger press that did not land on a panel previews; release places. It
  // leaves a selection (the widget goes back to the chosen values that will be placed).
  const bool down = right_ptr_.trigger_down();
  if (down && !right_was_down_ && !grabbing_ && !right_ptr_.hit() && right_ptr_.pressed_widget().empty()) {
    deselect();
    previewing_ = true;
  }
  if (!down && previewing_) {
    previewing_ = false;
    place_keyframe();
  }
  right_was_down_ = down;

  unaltered_ = edges.is_down(Hand::Right, Control::Secondary);
  if (edges.was_pressed(Hand::Right, Control::Primary)) delete_nearest();
  if (edges.was_pressed(Hand::Left, Control::Primary)) undo();
  if (edges.was_pressed(Hand::Left, Control::Secondary)) redo();

  if (look_target_ && angle_deg(*look_target_, view_) < 5.0) look_target_.reset();
  if (!previewing_ && !grabbing_) preview_.reset();
  sync_widgets();
  refresh_visualizations();
}

effects::StackParams Editor::params_for_view(const Direction& direction, std::int64_t frame) const {
  if (unaltered_) return {};
  effects::StackParams sp = doc_.interpolator().evaluate(direction, frame);
  if (!previewing_ && !grabbing_) return sp;
  const auto& chosen = doc_.params(effect_);
  // At the view centre the preview keyframe's values are exact; elsewhere interpolate with it.
  if (previewing_ && frame == frame_ && angle_deg(direction, view_) < 1e-9) {
    sp.set(effect_, chosen);
    return sp;
  }
  const auto target = shown_preview_target();  // a grab that has not moved yet changes nothing
  if (!target) return sp;
  const auto rbf = preview_.update(*target);
  const Eigen::VectorXd v = rbf->evaluate(direction, frame);
  sp.set(effect_, std::span<const double>(v.data(), static_cast<std::size_t>(v.size())));
  return sp;
}

std::optional<PreviewTarget> Editor::preview_target() const {
  PreviewTarget t;
  t.keyframes = &doc_.keyframes(effect_);
  t.revision = doc_.revision();
  t.effect = static_cast<int>(effect_);
  const auto& spec = effects::effect_spec(effect_);
  t.dimension = spec.dimension();
  t.neutral = spec.neutral();
  t.settings = doc_.interpolation(effect_);
  t.fps = doc_.video().fps;
  t.source = &doc_.keyframe_set(effect_);
  if (previewing_) {
    t.key = {view_, frame_, doc_.params(effect_)};
    return t;
  }
  if (grabbing_ && selected_ && *selected_ < t.keyframes->size()) {
    t.moved = selected_;
    t.key = *selected_preview();
    return t;
  }
  return std::nullopt;
}

std::optional<PreviewTarget> Editor::shown_preview_target() const {
  if (grabbing_) {
    const auto held = selected_preview();
    if (!held) return std::nullopt;
    const auto& k = doc_.keyframes(effect_)[*selected_];
    if (held->frame == k.frame && held->direction == k.direction) return std::nullopt;
  }
  return preview_target();
}

std::optional<effects::Keyframe> Editor::selected_preview() const {
  const auto& ks = doc_.keyframes(effect_);
  if (!selected_ || *selected_ >= ks.size()) return std::nullopt;
  effects::Keyframe k = ks[*selected_];
  if (!grabbing_) return k;
  // The keyframe keeps the offset from the view centre (in azimuth and altitude) and from the
  // playhead (in frames) that it had when grabbed, so grabbing alone moves nothing and a
  // keyframe grabbed while looking at it stays at the view centre.
  k.direction.azimuth_deg = effects::wrap_azimuth_deg(
      grab_key0_.direction.azimuth_deg + (view_.azimuth_deg - grab_view0_.azimuth_deg));
  k.direction.altitude_deg =
      std::clamp(grab_key0_.direction.altitude_deg + (view_.altitude_deg - grab_view0_.altitude_deg), -90.0, 90.0);
  k.frame = std::clamp<std::int64_t>(grab_key0_.frame + (frame_ - grab_frame0_), 0, doc_.video().frames - 1);
  return k;
}

const std::vector<double>& Editor::widget_values() const {
  const auto& ks = doc_.keyframes(effect_);
  return selected_ && *selected_ < ks.size() ? ks[*selected_].params : doc_.params(effect_);
}

void Editor::validate_selection() {
  if (selected_ && *selected_ >= doc_.keyframes(effect_).size()) {
    selected_.reset();
    grabbing_ = false;
  }
}

std::vector<ui::Panel*> Editor::panels() { return panels_.all(); }

std::string Editor::status_text() const {
  const auto& chosen = widget_values();
  std::string s = title_case(effects::effect_name(effect_)) + " ";
  switch (effect_) {
    case EffectType::Tint: s += fmt("gain %.2f", chosen[0]) + fmt(" %.2f", chosen[1]) + fmt(" %.2f", chosen[2]); break;
    case EffectType::Vignette: s += fmt("radius %.0f", chosen[0]) + fmt(" falloff %.0f deg", chosen[1]); break;
    case EffectType::Exposure: s += fmt("%+.1f stops", chosen[0]); break;
    case EffectType::Blur: s += fmt("%.1f deg", chosen[0]); break;
    default: s += fmt("%.2f", chosen[0]); break;
  }
  s += " | frame " + std::to_string(frame_) + "/" + std::to_string(doc_.video().frames);
  s += " | " + std::to_string(doc_.keyframes(effect_).size()) + " keyframes";
  if (playing_) s += " | playing";
  if (previewing_) s += " | PREVIEW: release to place";
  if (const auto k = selected_preview()) {
    const std::string where = fmt("az %.0f", k->direction.azimuth_deg) + fmt(" alt %.0f", k->direction.altitude_deg) +
                              " frame " + std::to_string(k->frame);
    const std::string which = std::to_string(*selected_ + 1) + "/" + std::to_string(doc_.keyframes(effect_).size());
    s += grabbing_ ? " | GRAB keyframe " + which + " -> " + where + ": release to move"
                   : " | SELECTED keyframe " + which + " (" + where + "): widget edits it";
  }
  if (unaltered_) s += " | UNALTERED";
  if (look_target_) {
    const double daz = effects::wrap_azimuth_deg(look_target_->azimuth_deg - view_.azimuth_deg);
    const double dalt = look_target_->altitude_deg - view_.altitude_deg;
    s += " | look " + fmt("%.0f deg ", std::abs(daz)) + (daz >= 0 ? "right" : "left") + ", " +
         fmt("%.0f deg ", std::abs(dalt)) + (dalt >= 0 ? "up" : "down");
  }
  if (!message_.empty()) s += " | " + message_;
  return s;
}

void Editor::say(std::string message) {
  message_ = std::move(message);
  message_t_ = now_;
}

void Editor::set_viewport(const DesktopViewport& v) {
  if (v == panels_.viewport()) return;
  panels_.set_viewport(v);
  sync_widgets();
}

void Editor::set_loop_status(double frames_per_second, bool video_loading) {
  loop_fps_ = frames_per_second;
  video_loading_ = video_loading;
}

std::string Editor::hud_text() const {
  const double fps = doc_.video().fps;
  const double t = static_cast<double>(frame_) / fps;
  const int minutes = static_cast<int>(t / 60.0);
  std::string s = "frame " + std::to_string(frame_) + " / " + std::to_string(doc_.video().frames) + "   " +
                  std::to_string(minutes) + ":" + fmt("%05.2f", t - 60.0 * minutes) + "   az " +
                  fmt("%.0f\u00b0", view_.azimuth_deg) + " alt " + fmt("%.0f\u00b0", view_.altitude_deg) +
                  "   " + title_case(effects::effect_name(effect_)) + " (" +
                  std::to_string(doc_.keyframes(effect_).size()) + " keyframes)";
  if (selected_) s += (grabbing_ ? "   moving " : "   selected ") + std::to_string(*selected_ + 1);
  if (playing_) s += "   \u25b6";
  if (loop_fps_ > 0.0) s += "   " + fmt("%.0f fps", loop_fps_);
  return s;
}

std::string Editor::hud_message() const {
  if (!message_.empty()) return message_;
  if (video_loading_) return "loading the video\u2026";
  if (previewing_) return "release to place the keyframe at the centre of the view";
  if (grabbing_) return "turn or scrub to move the keyframe; release to drop it";
  if (unaltered_) return "showing the unaltered film";
  if (selected_) return "the widget edits the selected keyframe; G (hold) moves it, L deselects";
  return "click the view or Space: keyframe at the centre   right-drag: look   arrows: step   Shift: fine";
}

bool Editor::finish() { return autosave_ ? autosave_->finish(doc_.sidecar()) : true; }

void Editor::select_effect(EffectType type) {
  if (type != effect_) {
    selected_.reset();
    grabbing_ = false;
  }
  effect_ = type;
  panels_.show_effect(type);
  previewing_ = false;
  sync_widgets();
}

void Editor::set_chosen_params(std::vector<double> params) { doc_.set_params(effect_, std::move(params)); }

void Editor::set_playing(bool on) {
  playing_ = on;
  play_t0_ = now_;
  play_f0_ = frame_;
}

void Editor::seek(std::int64_t frame) {
  frame_ = std::clamp<std::int64_t>(frame, 0, doc_.video().frames - 1);
  play_t0_ = now_;
  play_f0_ = frame_;
}

std::optional<Direction> Editor::jump_to_keyframe(int step) {
  const auto& ks = doc_.keyframes(effect_);
  const auto i = adjacent_keyframe(ks, view_, frame_, step);
  if (!i) {
    say(step > 0 ? "no keyframe after this frame" : "no keyframe before this frame");
    return std::nullopt;
  }
  seek(ks[*i].frame);
  look_target_ = ks[*i].direction;
  say({});
  // The keyframe jumped to becomes the selection (its values in the widget, ready to grab); a
  // grab in progress keeps its keyframe, which follows the playhead instead.
  if (!grabbing_) select_keyframe(*i);
  return look_target_;
}

bool Editor::delete_nearest() {
  if (selected_) {
    const std::size_t i = *selected_;
    selected_.reset();
    grabbing_ = false;
    doc_.remove_keyframe(effect_, i);
    say("deleted the selected keyframe");
    return true;
  }
  const auto& ks = doc_.keyframes(effect_);
  const auto i = nearest_keyframe(ks, view_, frame_, doc_.interpolation(effect_).time_scale, doc_.video().fps);
  if (!i) {
    say("no keyframe to delete");
    return false;
  }
  doc_.remove_keyframe(effect_, *i);
  say("deleted a keyframe");
  return true;
}

void Editor::place_keyframe() {
  const auto edit = doc_.add_keyframe(effect_, {view_, frame_, doc_.params(effect_)});
  say(edit.replaced ? "replaced a keyframe" : "placed a keyframe");
}

bool Editor::select_nearest() {
  const auto& ks = doc_.keyframes(effect_);
  const auto i = nearest_keyframe(ks, view_, frame_, doc_.interpolation(effect_).time_scale, doc_.video().fps);
  if (!i) {
    say("no keyframe to select");
    return false;
  }
  selected_ = *i;
  grabbing_ = false;
  previewing_ = false;
  say("selected keyframe " + std::to_string(*i + 1));
  return true;
}

bool Editor::select_keyframe(std::size_t index) {
  if (grabbing_ || index >= doc_.keyframes(effect_).size()) return false;
  selected_ = index;
  previewing_ = false;
  say("selected keyframe " + std::to_string(index + 1));
  return true;
}

void Editor::keep_selection_if_stable(std::size_t count_before) {
  // An undone or redone step that added or removed keyframes (a place, a delete, a move that
  // replaced another) renumbers them: the index would then name another keyframe.
  if (doc_.keyframes(effect_).size() != count_before) selected_.reset();
  validate_selection();
}

void Editor::deselect() {
  if (!selected_) return;
  selected_.reset();
  grabbing_ = false;  // a grab in progress is cancelled, not committed
  say("deselected");
}

bool Editor::grab() {
  validate_selection();
  if (!selected_ && !select_nearest()) return false;
  previewing_ = false;
  grabbing_ = true;
  grab_view0_ = view_;
  grab_frame0_ = frame_;
  grab_key0_ = doc_.keyframes(effect_)[*selected_];
  say("holding keyframe " + std::to_string(*selected_ + 1));
  return true;
}

void Editor::grab_release() {
  if (!grabbing_) return;
  const auto k = selected_preview();
  grabbing_ = false;
  if (!k) return;
  const std::uint64_t revision = doc_.revision();
  const auto edit = doc_.move_keyframe(effect_, *selected_, k->direction, k->frame);
  if (doc_.revision() == revision) {  // released where it was: no edit
    say("selected keyframe " + std::to_string(*selected_ + 1));
    return;
  }
  selected_ = edit.index;
  say(edit.replaced ? "moved a keyframe onto another (replaced it)" : "moved a keyframe");
}

void Editor::set_selected_params(std::vector<double> params) {
  if (selected_) doc_.set_keyframe_params(effect_, *selected_, std::move(params));
}

bool Editor::undo() {
  grabbing_ = false;  // undo during a grab cancels it
  const std::size_t count = doc_.keyframes(effect_).size();
  const bool ok = doc_.undo();
  keep_selection_if_stable(count);
  say(ok ? "undone" : "nothing to undo");
  return ok;
}

bool Editor::redo() {
  grabbing_ = false;
  const std::size_t count = doc_.keyframes(effect_).size();
  const bool ok = doc_.redo();
  keep_selection_if_stable(count);
  say(ok ? "redone" : "nothing to redo");
  return ok;
}

std::vector<double> Editor::widget_params(const ui::Event& e) const {
  switch (effect_) {
    case EffectType::Tint: {
      const Eigen::Vector3d g = ui::tint_gain_from_hue_sat(e.new_value.x, e.new_value.y);
      return {g[0], g[1], g[2]};
    }
    case EffectType::Vignette: return {e.new_value.x, e.new_value.y};
    default: return {e.new_value.x};
  }
}

void Editor::handle(const ui::Event& e) {
  // Widget ids are unique across the panels; which panel holds a widget depends on the layout.
  using ui::EventKind;
  const bool drag_begin = e.kind == EventKind::DragBegin, drag_end = e.kind == EventKind::DragEnd;
  const bool changed = e.kind == EventKind::ValueChanged, clicked = e.kind == EventKind::Clicked;
  const std::string& w = e.widget;
  if (w == "effect_menu" && changed) {
    select_effect(static_cast<EffectType>(std::clamp(static_cast<int>(e.new_value.x), 0, effects::kEffectCount - 1)));
  } else if (w == effect_widget_id(effect_) || w == "exponent" || w == "time_scale") {
    if (drag_begin) doc_.begin_group(w);
    if (drag_end) doc_.end_group();
    if (!changed) return;
    if (w == "exponent" || w == "time_scale") {
      auto s = doc_.interpolation(effect_);
      if (w == "exponent") s.exponent = e.new_value.x;
      else s.time_scale = effects::time_scale_from_deg_per_s(e.new_value.x);
      doc_.set_interpolation(effect_, s);
    } else if (selected_) {
      set_selected_params(widget_params(e));
    } else {
      set_chosen_params(widget_params(e));
    }
  } else if (clicked && w == "undo") {
    undo();
  } else if (clicked && w == "redo") {
    redo();
  } else if (clicked && w == "delete_nearest") {
    delete_nearest();
  } else if (clicked && w == "deselect") {
    deselect();
  } else if (w == "minimap" && changed) {
    if (e.new_value.x >= 0.0) select_keyframe(static_cast<std::size_t>(e.new_value.x));
  } else if (clicked && w == "play") {
    set_playing(!playing_);
  } else if (clicked && w == "prev_key") {
    jump_to_keyframe(-1);
  } else if (clicked && w == "next_key") {
    jump_to_keyframe(+1);
  } else if (w == "strip" && drag_begin) {
    set_playing(false);
  } else if (w == "strip" && changed) {
    seek(static_cast<std::int64_t>(e.new_value.x));
  } else if (w == "lock" && changed) {
    panels_.lock_timeline(e.new_value.x > 0.5);
  }
}

void Editor::sync_widgets() {
  // Widgets show the document; a widget being dragged already shows its own value (setters
  // compare, so re-setting equal values costs nothing), and the wheel is left alone while held
  // because tint normalisation would nudge it.
  const auto& chosen = widget_values();
  ui::Widget* w = panels_.effect_widgets[static_cast<std::size_t>(effect_)];
  if (!w->pressed()) {
    if (auto* s = dynamic_cast<ui::Slider1D*>(w)) s->set_value(chosen[0]);
    if (auto* p = dynamic_cast<ui::Pad2D*>(w)) p->set_value({chosen[0], chosen[1]});
    if (auto* c = dynamic_cast<ui::ColourWheel*>(w)) {
      const glm::dvec2 hs = ui::hue_sat_from_tint_gain({chosen[0], chosen[1], chosen[2]});
      if (glm::length(hs - glm::dvec2(c->hue(), c->sat())) > 1e-6) c->set_hue_sat(hs.x, hs.y);
    }
  }
  const auto s = doc_.interpolation(effect_);
  if (!panels_.exponent->pressed()) panels_.exponent->set_value(s.exponent);
  if (!panels_.time_scale->pressed()) panels_.time_scale->set_value(effects::deg_per_s_from_time_scale(s.time_scale));
  panels_.undo->set_enabled(doc_.undo_stack().can_undo());
  panels_.redo->set_enabled(doc_.undo_stack().can_redo());
  const std::string name = title_case(effects::effect_name(effect_));
  if (selected_) {
    const std::string which = std::to_string(*selected_ + 1) + " of " + std::to_string(doc_.keyframes(effect_).size());
    panels_.title->set_text(name + (grabbing_ ? " \u2014 moving keyframe " : " \u2014 keyframe ") + which);
  } else {
    panels_.title->set_text("Effects \u2014 " + name);
  }
  panels_.delete_nearest->set_label(selected_ ? "Delete selected" : "Delete nearest");
  panels_.deselect->set_enabled(selected_.has_value());
  panels_.play->set_icon(playing_ ? ui::Icon::Pause : ui::Icon::Play);
  panels_.strip->set_playhead(static_cast<int>(frame_));
  const double fps = doc_.video().fps;
  panels_.time->set_text(fmt("frame %.0f", static_cast<double>(frame_)) + fmt("  %.2f s", static_cast<double>(frame_) / fps));
  panels_.status->set_text(autosave_ ? autosave_->status() : std::string());
  if (panels_.hint) panels_.hint->set_text(status_text());
  if (panels_.hud_line) {
    panels_.hud_line->set_text(hud_text());
    panels_.hud_message->set_text(hud_message());
  }
}

void Editor::refresh_visualizations() {
  const auto& ks = doc_.keyframes(effect_);
  const int eff = static_cast<int>(effect_);
  const auto held = selected_preview();  // the selected keyframe, where a grab puts it now
  const std::int64_t held_frame = held ? held->frame : -1;
  // Markers follow the view: recomputed when it moved by a degree, or the keyframes changed.
  if (marker_revision_ != doc_.revision() || marker_effect_ != eff || angle_deg(marker_view_, view_) > 1.0 ||
      marker_selected_ != held_frame) {
    near_ = keyframes_near_view(ks, view_, options_.marker_cone_deg);
    std::vector<int> frames, highlighted;
    for (std::size_t i = 0; i < ks.size(); ++i)
      frames.push_back(static_cast<int>(held && i == *selected_ ? held->frame : ks[i].frame));
    for (const auto i : near_) highlighted.push_back(static_cast<int>(ks[i].frame));
    if (held) highlighted.push_back(static_cast<int>(held->frame));
    marker_selected_ = held_frame;
    panels_.strip->set_keyframes(frames);
    panels_.strip->set_highlighted(highlighted);
    marker_revision_ = doc_.revision();
    marker_effect_ = eff;
    marker_view_ = view_;
    ++marker_count_;
  }
  // While a keyframe is previewed (placed, or held away from its place) the track and the field
  // are the live preview's interpolant, the one params_for_view answers with (at most one
  // incremental move here); each new place of the preview keyframe is a new MinimapKey::preview.
  const auto target = shown_preview_target();
  if (!target) {
    shown_preview_.reset();
  } else if (!shown_preview_ || shown_preview_->moved != target->moved || !(shown_preview_->key == target->key)) {
    shown_preview_ = ShownPreview{target->moved, target->key};
    ++preview_serial_;
  }
  const auto doc_rbf = doc_.keyframe_set(effect_).solution();
  std::shared_ptr<const effects::RbfInterpolator> preview_rbf;
  auto interpolant = [&] {
    if (!target) return doc_rbf;
    if (!preview_rbf) preview_rbf = preview_.update(*target);
    return preview_rbf;
  };
  const MinimapKey base{doc_.revision(), doc_.keyframe_set(effect_).solution_version(), eff, -1,
                        target ? preview_serial_ : 0};
  const auto [lo, hi] = display_range(effect_);
  if (!(track_key_ == base) || angle_deg(track_view_, view_) > 1.0) {
    track_ = effect_track(interpolant().get(), effect_, view_, track_frames_);
    panels_.plot->set_values(track_);
    panels_.plot->set_range(lo, hi);
    std::vector<std::int64_t> key_frames;  // the held keyframe where it is held, a placed one at the playhead
    for (std::size_t i = 0; i < ks.size(); ++i) key_frames.push_back(held && i == *selected_ ? held->frame : ks[i].frame);
    if (previewing_) key_frames.push_back(frame_);
    std::vector<int> marks;  // keyframe frames as sample indices
    for (const auto f : key_frames) {
      const auto it = std::lower_bound(track_frames_.begin(), track_frames_.end(), f);
      if (it != track_frames_.end()) marks.push_back(static_cast<int>(it - track_frames_.begin()));
    }
    panels_.plot->set_keyframes(marks);
    track_key_ = base;
    track_view_ = view_;
  }
  {
    const auto it = std::lower_bound(track_frames_.begin(), track_frames_.end(), frame_);
    panels_.plot->set_playhead(static_cast<int>(std::min<std::ptrdiff_t>(it - track_frames_.begin(),
                                                                          static_cast<std::ptrdiff_t>(track_frames_.size()) - 1)));
  }
  MinimapKey mk = base;
  mk.frame = frame_;
  if (!(minimap_requested_ == mk)) {
    nearest_ = nearest_keyframe(ks, view_, frame_, doc_.interpolation(effect_).time_scale, doc_.video().fps);
    minimap_requested_ = mk;
    if (minimap_worker_)
      minimap_worker_->request({mk, interpolant(), effect_, frame_, options_.minimap_width, options_.minimap_height});
    else
      show_minimap(mk, effect_minimap(interpolant().get(), effect_, frame_, options_.minimap_width, options_.minimap_height));
  }
  // A field finished for an earlier frame or edit is shown until the current one is ready (a
  // frame or two while playing large sets); one for another effect is dropped.
  if (minimap_worker_)
    if (auto r = minimap_worker_->take(); r && r->key.effect == eff) show_minimap(r->key, std::move(r->field));
  {
    // Keyframe dots: the selected one ringed (and carried along while grabbed). Setters compare,
    // so an unchanged set costs no redraw.
    std::vector<Direction> dirs;
    for (std::size_t i = 0; i < ks.size(); ++i) dirs.push_back(held && i == *selected_ ? held->direction : ks[i].direction);
    panels_.minimap->set_keyframes(std::move(dirs), nearest_ ? static_cast<int>(*nearest_) : -1,
                                   selected_ ? static_cast<int>(*selected_) : -1);
  }
  if (options_.layout == PanelLayout::Desktop) {
    const DesktopViewport& v = panels_.viewport();
    const double vfov = 2.0 * std::atan(std::tan(0.5 * v.hfov_deg * effects::kDegToRad) * v.height / v.width);
    panels_.minimap->set_view(view_, v.hfov_deg, vfov * effects::kRadToDeg);
  } else {
    panels_.minimap->set_view(view_, options_.view_hfov_deg, options_.view_vfov_deg);
  }
}

void Editor::show_minimap(const MinimapKey& key, cv::Mat field) {
  const auto [lo, hi] = display_range(effect_);
  minimap_ = std::move(field);
  panels_.minimap->set_field(minimap_, lo, hi);
  minimap_key_ = key;
  ++minimap_count_;
}

bool Editor::wait_for_visualizations(std::chrono::milliseconds timeout) {
  if (minimap_worker_ && minimap_worker_->wait_idle(timeout))
    if (auto r = minimap_worker_->take(); r && r->key.effect == static_cast<int>(effect_))
      show_minimap(r->key, std::move(r->field));
  return minimap_current();
}

}  // namespace vdfx::app
