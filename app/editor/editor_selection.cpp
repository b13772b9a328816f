/// @file
/// @brief The editor's selection and grab: which keyframe the widget edits, and holding it (the
/// pending edit keeps the hold: where it began and where the keyframe is now).
#include "app/editor/editor.h"
#include "app/editor/visualizations.h"

namespace vdfx::app {

std::optional<effects::Keyframe> Editor::selected_preview() const {
  const auto& ks = doc_.keyframes(effect_);
  if (!selected_ || *selected_ >= ks.size()) return std::nullopt;
  if (!grabbing()) return ks[*selected_];
  return doc_.pending()->placed_at(view_, play_.frame);
}

void Editor::validate_selection() {
  if (selected_ && *selected_ >= doc_.keyframes(effect_).size()) {
    selected_.reset();
    if (grabbing()) doc_.cancel_pending();
  }
}

std::optional<std::size_t> Editor::nearest_to_view() const {
  // Measured where the keyframes are stored: the view turned into the effect's anchor's frame.
  return nearest_keyframe(doc_.keyframes(effect_),
                          doc_.anchor_frames(effect_).apply(view_, play_.frame), play_.frame,
                          doc_.interpolation(effect_).time_scale, doc_.video().fps);
}

bool Editor::select_nearest() {
  const auto i = nearest_to_view();
  if (!i) {
    say("no keyframe to select");
    return false;
  }
  selected_ = *i;
  doc_.cancel_pending();
  say("selected keyframe " + std::to_string(*i + 1));
  return true;
}

bool Editor::select_keyframe(std::size_t index) {
  if (grabbing() || index >= doc_.keyframes(effect_).size()) return false;
  selected_ = index;
  if (previewing()) doc_.cancel_pending();
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
  if (grabbing()) doc_.cancel_pending();  // a grab in progress is cancelled, not committed
  say("deselected");
}

bool Editor::grab() {
  validate_selection();
  if (!selected_ && !select_nearest()) return false;
  // Also ends a placement. The keyframe keeps its offsets from the view and the playhead.
  doc_.begin_pending(effect_, selected_, doc_.keyframes(effect_)[*selected_])
      .hold_from(view_, play_.frame);
  say("holding keyframe " + std::to_string(*selected_ + 1));
  return true;
}

void Editor::grab_release() {
  if (!grabbing()) return;
  sync_pending();
  const std::uint64_t revision = doc_.revision();
  const auto edit = doc_.commit_pending();
  if (!edit) return;
  if (doc_.revision() == revision) {  // released where it was: no edit
    say("selected keyframe " + std::to_string(*selected_ + 1));
    return;
  }
  selected_ = edit->index;
  say(edit->replaced ? "moved a keyframe onto another (replaced it)" : "moved a keyframe");
}

void Editor::set_selected_params(std::vector<double> params) {
  if (selected_) doc_.set_keyframe_params(effect_, *selected_, std::move(params));
}

}  // namespace vdfx::app
