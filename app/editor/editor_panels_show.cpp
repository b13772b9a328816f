/// @file
/// @brief EditorPanels::show: the editor's state (one EditorView a frame) on the widgets.
#include <algorithm>

#include "app/editor/editor_panels.h"
#include "app/editor/text_format.h"

namespace vdfx::app {

using effects::EffectType;

void EditorPanels::show(const EditorView& view) {
  show_effect(view.effect);
  show_effect_panel(view);
  show_timeline(view);
  show_visualizations(view);
}

void EditorPanels::show_values(EditTarget target, std::span<const double> v) {
  const auto put = [](ui::Slider1D* slider, double value) {
    if (!slider->pressed()) slider->set_value(value);  // it shows its own value while dragged
  };
  if (target.is_flare()) return put(flare_intensity_, v[0]);
  if (target.is_grain()) {
    put(grain_intensity_, v[0]);
    put(grain_size_, v[1]);
    return;
  }
  if (effect_widgets_[static_cast<std::size_t>(target.index())]->pressed()) return;
  switch (*target.stack_effect()) {
    case EffectType::Tint: {
      // The wheel keeps its hue and saturation unless the gains moved them (the tint's
      // normalisation would nudge it).
      const glm::dvec2 hs = ui::hue_sat_from_tint_gain({v[0], v[1], v[2]});
      if (glm::length(hs - glm::dvec2(tint_->hue(), tint_->sat())) > 1e-6)
        tint_->set_hue_sat(hs.x, hs.y);
      break;
    }
    case EffectType::Vignette: vignette_->set_value({v[0], v[1]}); break;
    case EffectType::Blur: blur_->set_value(v[0]); break;
    case EffectType::Exposure: exposure_->set_value(v[0]); break;
    case EffectType::Saturation: saturation_->set_value(v[0]); break;
    case EffectType::Contrast: contrast_->set_value(v[0]); break;
  }
}

void EditorPanels::show_effect_panel(const EditorView& v) {
  show_values(v.effect, v.values);
  flare_style_->select(static_cast<int>(v.flare_style));
  auto_light_->set_on(v.auto_light);
  const auto style =
      std::find(effects::kGrainStyles.begin(), effects::kGrainStyles.end(), v.grain_style);
  grain_style_->select(static_cast<int>(style - effects::kGrainStyles.begin()));
  if (!exponent_->pressed()) exponent_->set_value(v.exponent);
  if (!time_scale_->pressed()) time_scale_->set_value(v.time_scale_deg_per_s);
  undo_->set_enabled(v.can_undo);
  redo_->set_enabled(v.can_redo);
  const std::string name = v.effect.title();
  if (v.selected) {
    const std::string which =
        std::to_string(*v.selected + 1) + " of " + std::to_string(v.keyframe_count);
    title_->set_text(name + (v.grabbing ? " \u2014 moving keyframe " : " \u2014 keyframe ") +
                     which);
  } else {
    title_->set_text("Effects \u2014 " + name);
  }
  delete_nearest_->set_label(v.selected ? "Delete selected" : "Delete nearest");
  deselect_->set_enabled(v.selected.has_value());
  status_->set_text(v.autosave);
  if (!suggest_strength_->pressed()) suggest_strength_->set_value(100.0 * v.suggest_strength);
  suggest_->set_label(v.suggest_progress ? fmt("Cancel (%.0f %%)", 100.0 * *v.suggest_progress)
                                         : v.suggest_title);
  suggest_->set_enabled(v.suggest_available);
}

void EditorPanels::show_timeline(const EditorView& v) {
  play_->set_icon(v.playing ? ui::Icon::Pause : ui::Icon::Play);
  strip_->set_playhead(static_cast<int>(v.frame));
  time_->set_text(fmt("frame %.0f", static_cast<double>(v.frame)) +
                  fmt("  %.2f s", static_cast<double>(v.frame) / v.fps));
  if (v.thumbnails && v.thumbnails_version != shown_.thumbnails) {
    strip_->set_thumbnails(*v.thumbnails);
    shown_.thumbnails = v.thumbnails_version;
  }
  strip_->set_track_band({v.track.first, v.track.last, v.track.held});
  track_.show(v.track);
  marker_->show(v.track);
  keyboard_->show(v.track.rename);
  if (hint_) hint_->set_text(v.status);
  if (hud_line_) {
    hud_line_->set_text(v.hud_line);
    hud_message_->set_text(v.hud_message);
  }
}

void EditorPanels::show_visualizations(const EditorView& v) {
  show_tracks_->set_on(v.show_track_plot);
  show_minimap_->set_on(v.show_minimap);
  lock_->set_on(v.timeline_locked);
  plot_->set_rect(v.show_track_plot ? plot_rect_ : ui::Rect{});
  minimap_->set_rect(v.show_minimap ? minimap_rect_ : ui::Rect{});
  minimap_->set_coverage(v.coverage_deg);
  const Visualizations* d = v.visuals;
  if (!d) return;
  if (d->markers_version != shown_.markers) {
    strip_->set_keyframes(d->marker_frames);
    strip_->set_highlighted(d->highlighted_frames);
    shown_.markers = d->markers_version;
  }
  if (d->track_version != shown_.track) {
    plot_->set_values(d->track);
    plot_->set_range(d->track_lo, d->track_hi);
    plot_->set_keyframes(d->track_marks);
    shown_.track = d->track_version;
  }
  plot_->set_playhead(d->track_playhead);
  if (d->field_version != shown_.field && !d->field.empty()) {
    minimap_->set_field(d->field, d->field_lo, d->field_hi);
    shown_.field = d->field_version;
  }
  minimap_->set_keyframes(d->dots, d->nearest, d->selected);
  minimap_->set_view(d->view, d->view_hfov_deg, d->view_vfov_deg);
}

}  // namespace vdfx::app
