/// @file
/// @brief Editor: the frame's conductor (input -> commands and panel events -> actions -> the
/// document and the pending edit -> visualizations -> one view on the panels), the playhead and
/// the actions.
#include "app/editor/editor.h"

#include <algorithm>
#include <cmath>

#include "app/editor/panel_binding.h"
#include "app/editor/visualizations.h"
#include "effects/direction_angle.h"
#include "effects/stereo_layout.h"

namespace vdfx::app {

using effects::Direction;
using effects::EffectType;

namespace {
std::shared_ptr<const ui::FontSet> fonts_or_default(std::shared_ptr<const ui::FontSet> f) {
  return f ? f : std::make_shared<const ui::FontSet>(ui::FontSet::load());
}
}  // namespace

Editor::Editor(io::Sidecar sidecar, DocumentOptions document_options, EditorOptions options)
    : doc_(std::move(sidecar), document_options),
      options_(options),
      panels_(fonts_or_default(options.fonts), doc_.video().frames, options.layout,
              options.viewport),
      visuals_(options.visuals, doc_.video().frames),
      fps_(io::fps_to_rational(doc_.video().fps)),
      input_(xr::neutral_input_state(0)) {
  if (options_.autosave_path) {
    autosave_ = std::make_unique<Autosave>(*options_.autosave_path,
                                           options_.read_only_note.empty()
                                               ? Autosave::Target::Sidecar
                                               : Autosave::Target::CopyWhenChanged);
    doc_.set_change_listener([this] { autosave_->save(doc_.sidecar()); });
  }
  select_effect(EffectType::Exposure);
}

double Editor::advance(std::int64_t t_ns) {
  const double dt =
      play_.last_t ? std::max<double>(0.0, static_cast<double>(t_ns - *play_.last_t) * 1e-9) : 0.0;
  play_.last_t = t_ns;
  play_.now = t_ns;
  if (!status_.message.empty() && t_ns - status_.message_t > kMessageLifetimeNs)
    status_.message.clear();
  if (play_.playing) {
    // Frames elapsed since play was pressed, from the elapsed time itself (adding two rounded
    // frame start times could land a nanosecond short of a frame).
    const std::int64_t n = doc_.video().frames;
    const std::int64_t f = play_.f0 + io::frame_at_time(t_ns - play_.t0, fps_);
    play_.frame = options_.loop ? ((f % n) + n) % n : std::clamp<std::int64_t>(f, 0, n - 1);
  }
  return dt;
}

void Editor::update(const xr::InputState& input, std::int64_t t_ns) {
  const double dt = advance(t_ns);
  // A failed save (full disk, read-only folder) is tried again while the document stays here.
  if (autosave_ && autosave_->retry_due(t_ns)) autosave_->save(doc_.sidecar());
  input_ = input;
  if (input.head_tracked) view_ = xr::forward_direction(input.head);
  updating_ = true;
  panels_.place(input);
  const std::vector<ui::Event> events = controls_.pointers(input, panels_, dt);
  validate_selection();  // the document may have been edited from outside (tests, tools)
  for (const auto& e : events) handle_panel_event(*this, panels_, e);
  for (const EditorCommand c : controls_.commands(input.edges)) run(c);
  unaltered_ = EditorControls::held(input.edges, EditorCommand::Unaltered);
  if (status_.look_target && effects::angle_between_deg(*status_.look_target, view_) < 5.0)
    status_.look_target.reset();
  sync_pending();
  poll_suggestion();
  poll_tracking();
  visuals_.refresh(doc_, visualization_input());
  updating_ = false;
  show();
}

VisualizationInput Editor::visualization_input() const {
  VisualizationInput vi{effect_,      view_, play_.frame, selected_, selected_preview(),
                        previewing(), 90.0,  90.0};
  if (options_.layout == PanelLayout::Desktop) {
    const DesktopViewport& v = panels_.viewport();
    vi.view_hfov_deg = v.hfov_deg;
    vi.view_vfov_deg =
        2.0 * std::atan(std::tan(0.5 * v.hfov_deg * effects::kDegToRad) * v.height / v.width) *
        effects::kRadToDeg;
  }
  return vi;
}

EditorView Editor::view() const {
  EditorView v;
  v.effect = effect_;
  v.values = widget_values();
  const effects::FlareEffect flare = doc_.flare();
  v.flare_style = flare.style;
  v.auto_light = std::holds_alternative<effects::AutoLight>(flare.light);
  v.grain_style = doc_.grain().style;
  const auto s = doc_.interpolation(effect_);
  v.exponent = s.exponent;
  v.time_scale_deg_per_s = effects::deg_per_s_from_time_scale(s.time_scale);
  v.can_undo = doc_.undo_stack().can_undo();
  v.can_redo = doc_.undo_stack().can_redo();
  v.selected = selected_;
  v.keyframe_count = doc_.keyframes(effect_).size();
  v.grabbing = grabbing();
  v.autosave = autosave_status();
  if (const auto kind = suggestion_for(effect_)) v.suggest_title = suggestion_title(*kind);
  v.suggest_available = options_.video.has_value();
  v.suggest_strength = suggest_strength_;
  v.suggest_progress = suggestion_progress();
  v.playing = play_.playing;
  v.frame = play_.frame;
  v.fps = doc_.video().fps;
  v.thumbnails = &thumbnails_.images;
  v.thumbnails_version = thumbnails_.version;
  v.status = status_text();
  v.hud_line = hud_text();
  v.hud_message = hud_message();
  v.show_track_plot = views_.track_plot;
  v.show_minimap = views_.minimap;
  v.timeline_locked = views_.timeline_locked;
  v.coverage_deg = doc_.video().stereo().coverage_deg;
  v.visuals = &visuals_.data();
  v.track = track_view();
  return v;
}

void Editor::show() {
  if (!updating_) panels_.show(view());
}

void Editor::run(EditorCommand c) {
  switch (c) {
    case EditorCommand::Grab: grab(); break;
    case EditorCommand::GrabRelease:
      if (grabbing()) grab_release();
      break;
    case EditorCommand::Deselect: deselect(); break;
    case EditorCommand::Preview:
      if (!grabbing()) begin_preview();
      break;
    case EditorCommand::Place:
      if (previewing()) {
        doc_.cancel_pending();
        place_keyframe();
      }
      break;
    case EditorCommand::Delete: delete_nearest(); break;
    case EditorCommand::Undo: undo(); break;
    case EditorCommand::Redo: redo(); break;
    case EditorCommand::Unaltered:
    case EditorCommand::Fine: break;  // held commands: asked for with EditorControls::held
  }
}

effects::StackParams Editor::params_for_view(const Direction& direction, std::int64_t frame) const {
  if (unaltered_) return {};
  effects::StackParams sp = doc_.interpolator().evaluate(direction, frame);
  const PendingEdit* p = doc_.pending();
  const auto type = p ? p->target().stack_effect() : std::nullopt;
  if (!type) return sp;  // a flare's or grain's pending edit is drawn by their layers
  // The pending keyframe is stored in the effect's anchor's frame: so is the view there.
  const Eigen::Vector3d turned =
      doc_.anchor_frames(p->target()).apply(effects::to_unit(direction), frame);
  // At a new keyframe itself its values are exact; elsewhere interpolate with it.
  if (!p->moved() && frame == p->key().frame &&
      effects::angle_between(turned, effects::to_unit(p->key().direction)) * effects::kRadToDeg <
          1e-9) {
    sp.set(*type, p->key().params);
    return sp;
  }
  const auto rbf = p->interpolant();  // a grab that has not moved changes nothing
  if (!rbf) return sp;
  const Eigen::VectorXd v = rbf->evaluate(turned, frame);
  sp.set(*type, std::span<const double>(v.data(), static_cast<std::size_t>(v.size())));
  return sp;
}

std::function<effects::StackParams(const effects::Direction&)> Editor::params_at(
    std::int64_t frame) const {
  const PendingEdit* p = doc_.pending();
  if (unaltered_ || (p && p->target().stack_effect()))
    return [this, frame](const Direction& d) { return params_for_view(d, frame); };
  return [at = std::make_shared<const effects::StackAtFrame>(doc_.interpolator(), frame)](
             const Direction& d) { return at->evaluate(d); };
}

std::shared_ptr<const effects::RbfInterpolator> Editor::interpolant(EditTarget target) const {
  const PendingEdit* p = doc_.pending();
  if (p && p->target() == target && p->changes_interpolant()) return p->interpolant();
  return doc_.keyframe_set(target).solution();
}

void Editor::sync_pending() {
  if (PendingEdit* p = doc_.pending()) p->follow(view_, play_.frame);
}

const std::vector<double>& Editor::widget_values() const {
  const auto& ks = doc_.keyframes(effect_);
  return selected_ && *selected_ < ks.size() ? ks[*selected_].params : doc_.params(effect_);
}

void Editor::set_viewport(const DesktopViewport& v) {
  if (v == panels_.viewport()) return;
  panels_.set_viewport(v);
  show();
}

void Editor::set_loop_status(double frames_per_second, bool video_loading) {
  status_.loop_fps = frames_per_second;
  status_.video_loading = video_loading;
}

void Editor::set_thumbnails(std::vector<cv::Mat> thumbnails) {
  thumbnails_.images = std::move(thumbnails);
  ++thumbnails_.version;
}

bool Editor::finish() {
  return autosave_ ? autosave_->finish(doc_.sidecar()) : true;
}

void Editor::say(std::string message) {
  status_.message = std::move(message);
  status_.message_t = play_.now;
}

void Editor::select_effect(EditTarget type) {
  if (type != effect_) {
    selected_.reset();
    doc_.cancel_pending();  // a grab of the old effect's keyframe is cancelled
  } else if (previewing()) {
    doc_.cancel_pending();
  }
  effect_ = type;
  show();
}

void Editor::begin_gesture(const std::string& label) {
  doc_.begin_group(label);
}

void Editor::end_gesture() {
  doc_.end_group();
}

void Editor::set_playing(bool on) {
  play_.playing = on;
  play_.t0 = play_.now;
  play_.f0 = play_.frame;
}

void Editor::seek(std::int64_t frame) {
  play_.frame = std::clamp<std::int64_t>(frame, 0, doc_.video().frames - 1);
  play_.t0 = play_.now;
  play_.f0 = play_.frame;
  sync_pending();
}

std::optional<Direction> Editor::jump_to_keyframe(int step) {
  const auto& ks = doc_.keyframes(effect_);
  const effects::AnchorFrames& anchor = doc_.anchor_frames(effect_);
  const auto i = adjacent_keyframe(ks, view_, play_.frame, step, anchor);
  if (!i) {
    say(step > 0 ? "no keyframe after this frame" : "no keyframe before this frame");
    return std::nullopt;
  }
  seek(ks[*i].frame);
  status_.look_target = anchor.unapply(ks[*i].direction, ks[*i].frame);  // where it shows there
  say({});
  // The keyframe jumped to becomes the selection (its values in the widget, ready to grab); a
  // grab in progress keeps its keyframe, which follows the playhead instead.
  if (!grabbing()) select_keyframe(*i);
  return status_.look_target;
}

bool Editor::delete_nearest() {
  if (selected_) {
    const std::size_t i = *selected_;
    selected_.reset();
    if (grabbing()) doc_.cancel_pending();
    doc_.remove_keyframe(effect_, i);
    say("deleted the selected keyframe");
    return true;
  }
  const auto i = nearest_to_view();
  if (!i) {
    say("no keyframe to delete");
    return false;
  }
  doc_.remove_keyframe(effect_, *i);
  say("deleted a keyframe");
  return true;
}

void Editor::place_keyframe() {
  // A VR180 video shows nothing behind the viewer: a keyframe there would tune black.
  const effects::StereoLayout stereo = doc_.video().stereo();
  if (effects::coverage_weight(stereo, view_.azimuth_deg) <= 0.0) {
    say("outside the video (it covers azimuth -" + std::to_string(stereo.coverage_deg / 2) +
        " to " + std::to_string(stereo.coverage_deg / 2) + "): no keyframe placed");
    return;
  }
  const Direction at = doc_.anchor_frames(effect_).apply(view_, play_.frame);
  const auto edit = doc_.add_keyframe(effect_, {at, play_.frame, doc_.params(effect_)});
  say(edit.replaced ? "replaced a keyframe" : "placed a keyframe");
}

void Editor::begin_preview() {
  deselect();  // the widget goes back to the chosen values that will be placed
  const Direction at = doc_.anchor_frames(effect_).apply(view_, play_.frame);
  doc_.begin_pending(effect_, std::nullopt, {at, play_.frame, doc_.params(effect_)});
}

bool Editor::undo() {
  if (grabbing()) doc_.cancel_pending();  // undo during a grab cancels it
  const std::size_t count = doc_.keyframes(effect_).size();
  const bool ok = doc_.undo();
  keep_selection_if_stable(count);
  say(ok ? "undone" : "nothing to undo");
  return ok;
}

bool Editor::redo() {
  if (grabbing()) doc_.cancel_pending();
  const std::size_t count = doc_.keyframes(effect_).size();
  const bool ok = doc_.redo();
  keep_selection_if_stable(count);
  say(ok ? "redone" : "nothing to redo");
  return ok;
}

bool Editor::wait_for_visualizations(std::chrono::milliseconds timeout) {
  const bool current = visuals_.wait(timeout, effect_);
  show();
  return current;
}

}  // namespace vdfx::app
