/// @file
/// @brief The editor's status texts: the one-line status (window title, the Hands timeline's
/// hint), the heads-up line and its message.
#include <cmath>
#include <cstdio>

#include "app/editor/editor.h"
#include "app/editor/text_format.h"

namespace vdfx::app {

using effects::EffectType;

std::string Editor::status_text() const {
  const auto& chosen = widget_values();
  std::string s = options_.read_only_note.empty() ? std::string()
                                                  : "READ-ONLY: " + options_.read_only_note + " | ";
  s += effect_.title() + " ";
  if (effect_ == EffectType::Tint)
    s += fmt("gain %.2f", chosen[0]) + fmt(" %.2f", chosen[1]) + fmt(" %.2f", chosen[2]);
  else if (effect_ == EffectType::Vignette)
    s += fmt("radius %.0f", chosen[0]) + fmt(" falloff %.0f deg", chosen[1]);
  else if (effect_ == EffectType::Exposure)
    s += fmt("%+.1f stops", chosen[0]);
  else if (effect_ == EffectType::Blur)
    s += fmt("%.1f deg", chosen[0]);
  else if (effect_.is_grain())
    s += fmt("intensity %.2f", chosen[0]) + fmt(" size %.2f", chosen[1]);
  else
    s += fmt("%.2f", chosen[0]);
  s += " | frame " + std::to_string(play_.frame) + "/" + std::to_string(doc_.video().frames);
  s += " | " + std::to_string(doc_.keyframes(effect_).size()) + " keyframes";
  if (play_.playing) s += " | playing";
  if (const auto p = suggestion_progress()) s += fmt(" | suggesting %.0f %%", 100.0 * *p);
  if (const auto p = tracking_progress()) s += fmt(" | tracking %.0f %%", 100.0 * *p);
  if (previewing()) s += " | PREVIEW: release to place";
  if (const auto k = selected_preview()) {
    // Stored directions are in the effect's anchor's frame: say which, unless it is the video's.
    const effects::Anchor& anchor = doc_.anchor(effect_);
    const std::string frame_of = anchor.is_video() ? "" : effects::anchor_name(anchor) + " ";
    const std::string where = frame_of + fmt("az %.0f", k->direction.azimuth_deg) +
                              fmt(" alt %.0f", k->direction.altitude_deg) + " frame " +
                              std::to_string(k->frame);
    const std::string which =
        std::to_string(*selected_ + 1) + "/" + std::to_string(doc_.keyframes(effect_).size());
    s += grabbing() ? " | GRAB keyframe " + which + " -> " + where + ": release to move"
                    : " | SELECTED keyframe " + which + " (" + where + "): widget edits it";
  }
  if (unaltered_) s += " | UNALTERED";
  if (status_.look_target) {
    const double daz =
        effects::wrap_azimuth_deg(status_.look_target->azimuth_deg - view_.azimuth_deg);
    const double dalt = status_.look_target->altitude_deg - view_.altitude_deg;
    s += " | look " + fmt("%.0f deg ", std::abs(daz)) + (daz >= 0 ? "right" : "left") + ", " +
         fmt("%.0f deg ", std::abs(dalt)) + (dalt >= 0 ? "up" : "down");
  }
  if (!status_.message.empty()) s += " | " + status_.message;
  return s;
}
std::string Editor::hud_text() const {
  const double fps = doc_.video().fps;
  const double t = static_cast<double>(play_.frame) / fps;
  const int minutes = static_cast<int>(t / 60.0);
  std::string s = options_.read_only_note.empty() ? std::string() : "READ-ONLY   ";
  s += "frame " + std::to_string(play_.frame) + " / " + std::to_string(doc_.video().frames) +
       "   " + std::to_string(minutes) + ":" + fmt("%05.2f", t - 60.0 * minutes) + "   az " +
       fmt("%.0f\u00b0", view_.azimuth_deg) + " alt " + fmt("%.0f\u00b0", view_.altitude_deg) +
       "   " + effect_.title() + " (" + std::to_string(doc_.keyframes(effect_).size()) +
       " keyframes)";
  if (selected_) s += (grabbing() ? "   moving " : "   selected ") + std::to_string(*selected_ + 1);
  if (play_.playing) s += "   \u25b6";
  if (status_.loop_fps > 0.0) s += "   " + fmt("%.0f fps", status_.loop_fps);
  return s;
}
std::string Editor::hud_message() const {
  if (!status_.message.empty()) return status_.message;
  if (const auto p = suggestion_progress())
    return suggestion_title(suggesting_->request().kind) +
           fmt(": %.0f %% done (press it again to cancel)", 100.0 * *p);
  if (tracking_) return track_view().line;
  // Until a save succeeds again, or a file changed under the editor: where the work is.
  if (autosave_ && (autosave_->failing() || autosave_->diverted_to())) return autosave_->status();
  if (!options_.read_only_note.empty()) return "READ-ONLY: " + options_.read_only_note;
  if (status_.video_loading) return "loading the video\u2026";
  if (previewing()) return "release to place the keyframe at the centre of the view";
  if (grabbing()) return "turn or scrub to move the keyframe; release to drop it";
  if (unaltered_) return "showing the unaltered film";
  if (selected_) return "the widget edits the selected keyframe; G (hold) moves it, L deselects";
  // At most about 95 characters: the heads-up line's width at the default window.
  return "click or Space: keyframe at the centre   right-drag: look (I: flip)   arrows: step   "
         "Shift: fine";
}

}  // namespace vdfx::app
