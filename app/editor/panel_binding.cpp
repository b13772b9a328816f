/// @file
/// @brief Panel events -> editor actions.
#include "app/editor/panel_binding.h"

#include "app/editor/editor.h"

namespace vdfx::app {

namespace {

/// A value widget's event: a drag (or a thumbstick gesture) is one undo step.
void value_event(Editor& ed, const EditorPanels& p, PanelControl control, const ui::Event& e) {
  if (e.kind == ui::EventKind::DragBegin) ed.begin_gesture(e.widget);
  if (e.kind == ui::EventKind::DragEnd) ed.end_gesture();
  if (e.kind != ui::EventKind::ValueChanged) return;
  if (control == PanelControl::Exponent)
    ed.set_exponent(e.new_value.x);
  else if (control == PanelControl::TimeScale)
    ed.set_time_scale_deg_per_s(e.new_value.x);
  else
    ed.set_widget_values(p.values_of(ed.current_effect(), e, ed.widget_values()));
}

/// A button's click.
void clicked(Editor& ed, PanelControl control) {
  switch (control) {
    case PanelControl::SetLight: ed.set_light_here(); break;
    case PanelControl::Undo: ed.undo(); break;
    case PanelControl::Suggest: ed.suggest(); break;
    case PanelControl::Redo: ed.redo(); break;
    case PanelControl::Delete: ed.delete_nearest(); break;
    case PanelControl::Deselect: ed.deselect(); break;
    case PanelControl::Play: ed.set_playing(!ed.playing()); break;
    case PanelControl::PreviousKey: ed.jump_to_keyframe(-1); break;
    case PanelControl::NextKey: ed.jump_to_keyframe(+1); break;
    case PanelControl::TrackSubject: ed.track_subject(); break;
    case PanelControl::TrackCamera: ed.track_camera(); break;
    case PanelControl::TrackCorrect: ed.correct_track(); break;
    case PanelControl::TrackAnchor: ed.next_anchor(); break;
    case PanelControl::TrackDelete: ed.delete_track(); break;
    case PanelControl::TrackRename: ed.begin_rename(); break;
    case PanelControl::RenameCancel: ed.cancel_rename(); break;
    case PanelControl::RenameCommit: ed.commit_rename(); break;
    default: break;
  }
}

/// A menu's, toggle's, strip's or minimap's new value.
void changed(Editor& ed, PanelControl control, glm::dvec2 v) {
  const int index = static_cast<int>(v.x);
  const bool on = v.x > 0.5;
  switch (control) {
    case PanelControl::EffectMenu: ed.select_effect(EditTarget::from_index(index)); break;
    case PanelControl::FlareStyle:
      ed.set_flare_style(static_cast<effects::FlareStyle>(index));
      break;
    case PanelControl::AutoLight: ed.set_auto_light(on); break;
    case PanelControl::GrainStyle:
      ed.set_grain_style(effects::kGrainStyles.at(static_cast<std::size_t>(v.x)));
      break;
    case PanelControl::Minimap:  // a dot pressed (-1: the map away from every dot)
      if (v.x >= 0.0) ed.select_keyframe(static_cast<std::size_t>(v.x));
      break;
    case PanelControl::Strip: ed.seek(static_cast<std::int64_t>(v.x)); break;
    case PanelControl::ShowTrackPlot: ed.show_track_plot(on); break;
    case PanelControl::ShowMinimap: ed.show_minimap(on); break;
    case PanelControl::LockTimeline: ed.lock_timeline(on); break;
    case PanelControl::SuggestStrength: ed.set_suggest_strength(v.x / 100.0); break;
    default: break;
  }
}

}  // namespace

void handle_panel_event(Editor& ed, const EditorPanels& p, const ui::Event& e) {
  const PanelControl control = p.control_of(e.source, ed.current_effect());
  switch (control) {
    case PanelControl::EffectValues:
    case PanelControl::Exponent:
    case PanelControl::TimeScale: return value_event(ed, p, control, e);
    case PanelControl::Strip:
      if (e.kind == ui::EventKind::DragBegin) ed.set_playing(false);  // scrubbing stops playback
      break;
    default: break;
  }
  if (e.kind == ui::EventKind::Clicked && control == PanelControl::RenameKey)
    ed.rename_key(p.rename_keyboard().key_of(e.source));
  if (e.kind == ui::EventKind::Clicked) clicked(ed, control);
  if (e.kind == ui::EventKind::ValueChanged) changed(ed, control, e.new_value);
}

}  // namespace vdfx::app
