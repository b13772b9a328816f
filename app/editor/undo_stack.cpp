/// @file
/// @brief UndoStack: snapshot steps with grouping.
#include "app/editor/undo_stack.h"

#include <algorithm>

namespace vdfx::app {

void UndoStack::push(const std::string& label, EffectChange change) {
  if (group_depth_ > 0 && group_has_step_) {
    auto& step = done_.back();
    auto it = std::find_if(step.changes.begin(), step.changes.end(),
                           [&](const EffectChange& c) { return c.target == change.target; });
    if (it != step.changes.end())
      it->after = std::move(change.after);
    else
      step.changes.push_back(std::move(change));
    // A drag that came back to where it started leaves nothing to undo.
    std::erase_if(step.changes, [](const EffectChange& c) { return c.before == c.after; });
    return;
  }
  if (change.before == change.after) return;
  undone_.clear();
  done_.push_back(UndoStep{label, {std::move(change)}, std::nullopt});
  if (group_depth_ > 0) group_has_step_ = true;
}

void UndoStack::push(const std::string& label, SourcesChange change) {
  if (group_depth_ > 0 && group_has_step_) {
    auto& step = done_.back();
    if (step.sources)
      step.sources->after = std::move(change.after);
    else
      step.sources = std::move(change);
    if (step.sources->before == step.sources->after) step.sources.reset();
    return;
  }
  if (change.before == change.after) return;
  undone_.clear();
  done_.push_back(UndoStep{label, {}, std::move(change)});
  if (group_depth_ > 0) group_has_step_ = true;
}

void UndoStack::begin_group(const std::string& label) {
  (void)label;
  if (group_depth_++ == 0) group_has_step_ = false;
}

void UndoStack::end_group() {
  if (group_depth_ == 0) return;
  if (--group_depth_ > 0) return;
  if (group_has_step_ && done_.back().changes.empty() && !done_.back().sources) done_.pop_back();
  group_has_step_ = false;
}

std::optional<UndoStep> UndoStack::undo() {
  while (group_depth_ > 0) end_group();
  if (done_.empty()) return std::nullopt;
  undone_.push_back(std::move(done_.back()));
  done_.pop_back();
  return undone_.back();
}

std::optional<UndoStep> UndoStack::redo() {
  while (group_depth_ > 0) end_group();
  if (undone_.empty()) return std::nullopt;
  done_.push_back(std::move(undone_.back()));
  undone_.pop_back();
  return done_.back();
}

}  // namespace vdfx::app
