/// @file
/// @brief The editor's "Suggest" (docs/suggest.md, "In the editor"): a suggestion for the current
/// effect on a worker, its progress in the status lines, its keyframes added as one undo step.
#include <algorithm>
#include <cctype>

#include "app/editor/editor.h"
#include "app/editor/text_format.h"

namespace vdfx::app {

namespace {

/// Keyframes one press may add: the command's default budget, within the sidecar's limit.
constexpr std::size_t kEditorBudget = 256;

std::string lower_first(std::string s) {
  if (!s.empty()) s[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(s[0])));
  return s;
}

}  // namespace

void Editor::suggest() {
  if (suggesting_) {  // pressed again: cancel
    suggesting_->cancel();
    say("cancelling the suggestion\u2026");
    return;
  }
  const auto kind = suggestion_for(effect_);
  if (!kind) return say(effect_.title() + " has no suggestion (exposure, saturation, vignette do)");
  if (!options_.video) return say("no video to suggest from");
  const std::size_t have = doc_.keyframes(effect_).size();
  if (have >= io::kMaxKeyframesPerEffect)
    return say(effect_.title() + " already has the most keyframes an effect may have");
  suggest::SuggestRequest r;
  r.kind = *kind;
  r.video = *options_.video;
  r.strength = suggest_strength_;
  r.max_keyframes = std::min(kEditorBudget, io::kMaxKeyframesPerEffect - have);
  if (r.kind == suggest::Kind::Guide) r.points = {{view_, 0, std::nullopt}};  // toward the view
  suggest_target_ = effect_;
  suggesting_ =
      std::make_unique<SuggestWorker>(std::move(r), doc_.sidecar(), options_.async_suggestions);
  poll_suggestion();  // a synchronous one is done already
}

void Editor::set_suggest_strength(double strength) {
  suggest_strength_ = std::clamp(strength, 0.0, 1.0);
}

std::optional<double> Editor::suggestion_progress() const {
  if (!suggesting_) return std::nullopt;
  return suggesting_->fraction();
}

bool Editor::wait_for_suggestion(std::chrono::milliseconds timeout) {
  if (!suggesting_) return true;
  const bool done = suggesting_->wait(timeout);
  poll_suggestion();
  show();
  return done;
}

void Editor::poll_suggestion() {
  if (!suggesting_) return;
  std::optional<SuggestOutcome> out = suggesting_->take();
  if (!out) return;
  const std::string title = suggestion_title(suggesting_->request().kind);
  suggesting_.reset();
  if (out->cancelled) return say(lower_first(title) + ": cancelled, nothing changed");
  if (!out->sidecar) return say(lower_first(title) + " failed: " + out->problem);
  apply_suggestion(suggest_target_, title, *out);
}

void Editor::apply_suggestion(EditTarget target, const std::string& label,
                              const SuggestOutcome& out) {
  std::size_t added = 0;
  doc_.begin_group(label);
  for (const suggest::SuggestedEffect& e : out.report.effects) {
    const EditTarget t(e.type);
    // A new track's own time scale (docs/suggest.md, "Time"), unless the author set one since.
    for (const auto& track : out.sidecar->effects)
      if (track.type == e.type && track.interpolation && !doc_.interpolation_override(t) &&
          doc_.keyframes(t).empty())
        doc_.set_interpolation(t, *track.interpolation);
    // In the effect's anchor's frame already: the suggestion read the document's anchors.
    for (const effects::Keyframe& k : e.fit.added) doc_.add_keyframe(t, k);
    added += e.fit.added.size();
  }
  doc_.end_group();
  if (target == effect_) selected_.reset();  // indices renumbered
  if (added == 0) return say("the suggestion adds nothing at this strength");
  const suggest::SuggestedEffect& e = out.report.effects.front();
  say("suggested " + std::to_string(added) + " keyframes" +
      fmt(" (largest error %.2f", e.fit.max_error) +
      fmt(", tolerance %.2f): undo removes them", e.tolerance));
}

}  // namespace vdfx::app
