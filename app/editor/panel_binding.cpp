/// @file
/// @brief Panel events -> editor actions; editor state -> widgets.
#include "app/editor/panel_binding.h"

#include <algorithm>
#include <cstdio>

#include "app/editor/editor.h"
#include "app/editor/text_format.h"

namespace vdfx::app {

using effects::EffectType;

void handle_panel_event(Editor& ed, EditorPanels& p, const ui::Event& e) {
  using ui::EventKind;
  const ui::Widget* w = e.source;
  const bool drag_begin = e.kind == EventKind::DragBegin, drag_end = e.kind == EventKind::DragEnd;
  const bool changed = e.kind == EventKind::ValueChanged, clicked = e.kind == EventKind::Clicked;
  const EditTarget effect = ed.current_effect();
  Document& doc = ed.document();
  if (w == p.menu && changed) {
    ed.select_effect(EditTarget::from_index(static_cast<int>(e.new_value.x)));
  } else if (p.edits_values(effect, w) || w == p.exponent || w == p.time_scale) {
    // A drag (or a thumbstick gesture) is one undo step.
    if (drag_begin) doc.begin_group(e.widget);
    if (drag_end) doc.end_group();
    if (!changed) return;
    if (w == p.exponent || w == p.time_scale) {
      auto s = doc.interpolation(effect);
      if (w == p.exponent)
        s.exponent = e.new_value.x;
      else
        s.time_scale = effects::time_scale_from_deg_per_s(e.new_value.x);
      doc.set_interpolation(effect, s);
    } else if (ed.selected_keyframe()) {
      ed.set_selected_params(p.values_of(effect, e, ed.widget_values()));
    } else {
      ed.set_chosen_params(p.values_of(effect, e, ed.widget_values()));
    }
  } else if (w == p.flare_style && changed) {
    ed.set_flare_style(static_cast<effects::FlareStyle>(static_cast<int>(e.new_value.x)));
  } else if (clicked && w == p.set_light) {
    ed.set_light_here();
  } else if (w == p.auto_light && changed) {
    ed.set_auto_light(e.new_value.x > 0.5);
  } else if (w == p.grain_style && changed) {
    ed.set_grain_style(effects::kGrainStyles.at(static_cast<std::size_t>(e.new_value.x)));
  } else if (clicked && w == p.undo) {
    ed.undo();
  } else if (clicked && w == p.redo) {
    ed.redo();
  } else if (clicked && w == p.delete_nearest) {
    ed.delete_nearest();
  } else if (clicked && w == p.deselect) {
    ed.deselect();
  } else if (w == p.minimap && changed) {
    if (e.new_value.x >= 0.0) ed.select_keyframe(static_cast<std::size_t>(e.new_value.x));
  } else if (clicked && w == p.play) {
    ed.set_playing(!ed.playing());
  } else if (clicked && w == p.prev_key) {
    ed.jump_to_keyframe(-1);
  } else if (clicked && w == p.next_key) {
    ed.jump_to_keyframe(+1);
  } else if (w == p.strip && drag_begin) {
    ed.set_playing(false);
  } else if (w == p.strip && changed) {
    ed.seek(static_cast<std::int64_t>(e.new_value.x));
  } else if (w == p.lock && changed) {
    ed.lock_timeline(e.new_value.x > 0.5);
  }
}

void show_editor_state(const Editor& ed, EditorPanels& p) {
  const Document& doc = ed.document();
  const EditTarget effect = ed.current_effect();
  p.show_values(effect, ed.widget_values());
  p.show_options(doc.flare(), doc.grain());
  const auto s = doc.interpolation(effect);
  if (!p.exponent->pressed()) p.exponent->set_value(s.exponent);
  if (!p.time_scale->pressed())
    p.time_scale->set_value(effects::deg_per_s_from_time_scale(s.time_scale));
  p.undo->set_enabled(doc.undo_stack().can_undo());
  p.redo->set_enabled(doc.undo_stack().can_redo());
  const std::string name = effect.title();
  if (const auto& sel = ed.selected_keyframe()) {
    const std::string which =
        std::to_string(*sel + 1) + " of " + std::to_string(doc.keyframes(effect).size());
    p.title->set_text(name + (ed.grabbing() ? " \u2014 moving keyframe " : " \u2014 keyframe ") +
                      which);
  } else {
    p.title->set_text("Effects \u2014 " + name);
  }
  p.delete_nearest->set_label(ed.selected_keyframe() ? "Delete selected" : "Delete nearest");
  p.deselect->set_enabled(ed.selected_keyframe().has_value());
  p.play->set_icon(ed.playing() ? ui::Icon::Pause : ui::Icon::Play);
  p.strip->set_playhead(static_cast<int>(ed.frame()));
  const double fps = doc.video().fps;
  p.time->set_text(fmt("frame %.0f", static_cast<double>(ed.frame())) +
                   fmt("  %.2f s", static_cast<double>(ed.frame()) / fps));
  p.status->set_text(ed.autosave_status());
  if (p.hint) p.hint->set_text(ed.status_text());
  if (p.hud_line) {
    p.hud_line->set_text(ed.hud_text());
    p.hud_message->set_text(ed.hud_message());
  }
}

}  // namespace vdfx::app
