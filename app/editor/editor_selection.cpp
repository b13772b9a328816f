/// @file
/// @brief The editor's selection and grab: which keyframe the widget edits, and how a held
/// keyframe follows the view and the playhead until it is let go (the pending edit's key).
#include <algorithm>

#include "app/editor/editor.h"
#include "app/editor/visualizations.h"

namespace vdfx::app {

std::optional<effects::Keyframe> Editor::selected_preview() const {
  const auto& ks = doc_.keyframes(effect_);
  if (!sel_.index || *sel_.index >= ks.size()) return std::nullopt;
  effects::Keyframe k = ks[*sel_.index];
  if (!grabbing()) return k;
  // The keyframe keeps the offset from the view centre (in azimuth and altitude) and from the
  // playhead (in frames) that it had when grabbed, so grabbing alone moves nothing and a
  // keyframe grabbed while looking at it stays at the view centre.
  k.direction.azimuth_deg = effects::wrap_azimuth_deg(sel_.key0.direction.azimuth_deg +
                                                      (view_.azimuth_deg - sel_.view0.azimuth_deg));
  k.direction.altitude_deg =
      std::clamp(sel_.key0.direction.altitude_deg + (view_.altitude_deg - sel_.view0.altitude_deg),
                 -90.0, 90.0);
  k.frame = std::clamp<std::int64_t>(sel_.key0.frame + (play_.frame - sel_.frame0), 0,
                                     doc_.video().frames - 1);
  return k;
}

void Editor::validate_selection() {
  if (sel_.index && *sel_.index >= doc_.keyframes(effect_).size()) {
    sel_.index.reset();
    if (grabbing()) doc_.cancel_pending();
  }
}

bool Editor::select_nearest() {
  const auto& ks = doc_.keyframes(effect_);
  const auto i = nearest_keyframe(ks, view_, play_.frame, doc_.interpolation(effect_).time_scale,
                                  doc_.video().fps);
  if (!i) {
    say("no keyframe to select");
    return false;
  }
  sel_.index = *i;
  doc_.cancel_pending();
  say("selected keyframe " + std::to_string(*i + 1));
  return true;
}

bool Editor::select_keyframe(std::size_t index) {
  if (grabbing() || index >= doc_.keyframes(effect_).size()) return false;
  sel_.index = index;
  if (previewing()) doc_.cancel_pending();
  say("selected keyframe " + std::to_string(index + 1));
  return true;
}

void Editor::keep_selection_if_stable(std::size_t count_before) {
  // An undone or redone step that added or removed keyframes (a place, a delete, a move that
  // replaced another) renumbers them: the index would then name another keyframe.
  if (doc_.keyframes(effect_).size() != count_before) sel_.index.reset();
  validate_selection();
}

void Editor::deselect() {
  if (!sel_.index) return;
  sel_.index.reset();
  if (grabbing()) doc_.cancel_pending();  // a grab in progress is cancelled, not committed
  say("deselected");
}

bool Editor::grab() {
  validate_selection();
  if (!sel_.index && !select_nearest()) return false;
  sel_.view0 = view_;
  sel_.frame0 = play_.frame;
  sel_.key0 = doc_.keyframes(effect_)[*sel_.index];
  doc_.begin_pending(effect_, sel_.index, sel_.key0);  // also ends a placement
  say("holding keyframe " + std::to_string(*sel_.index + 1));
  return true;
}

void Editor::grab_release() {
  if (!grabbing()) return;
  sync_pending();
  const std::uint64_t revision = doc_.revision();
  const auto edit = doc_.commit_pending();
  if (!edit) return;
  if (doc_.revision() == revision) {  // released where it was: no edit
    say("selected keyframe " + std::to_string(*sel_.index + 1));
    return;
  }
  sel_.index = edit->index;
  say(edit->replaced ? "moved a keyframe onto another (replaced it)" : "moved a keyframe");
}

void Editor::set_selected_params(std::vector<double> params) {
  if (sel_.index) doc_.set_keyframe_params(effect_, *sel_.index, std::move(params));
}

}  // namespace vdfx::app
