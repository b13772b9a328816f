/// @file
/// @brief PreviewInterpolant: a scratch KeyframeSet moved one keyframe per frame.
#include "app/editor_preview.h"

namespace vdfx::app {

namespace {
/// Indices of the keyframes the preview keyframe replaces: KeyframeSet's own rule (same frame,
/// within kReplaceAngleDeg), so that the scratch set's move() never finds one to remove.
std::vector<std::size_t> replaced_by(const PreviewTarget& t) {
  const Eigen::Vector3d n = effects::to_unit(t.key.direction);
  std::vector<std::size_t> out;
  const auto& ks = *t.keyframes;
  for (std::size_t i = 0; i < ks.size(); ++i) {
    if ((t.moved && i == *t.moved) || ks[i].frame != t.key.frame) continue;
    if (effects::angle_between(n, effects::to_unit(ks[i].direction)) <= effects::kReplaceAngleDeg * effects::kDegToRad)
      out.push_back(i);
  }
  return out;
}

/// The list for `dropped`; `index` receives where the preview keyframe is in it.
std::vector<effects::Keyframe> list_without(const PreviewTarget& t, const std::vector<std::size_t>& dropped,
                                            std::size_t& index) {
  const auto& ks = *t.keyframes;
  std::vector<effects::Keyframe> out;
  out.reserve(ks.size() + 1);
  std::size_t d = 0;
  index = ks.size();
  for (std::size_t i = 0; i < ks.size(); ++i) {
    if (d < dropped.size() && dropped[d] == i) {
      ++d;
      continue;
    }
    if (t.moved && i == *t.moved) {
      index = out.size();
      out.push_back(t.key);
    } else {
      out.push_back(ks[i]);
    }
  }
  if (!t.moved || *t.moved >= ks.size()) {
    index = out.size();
    out.push_back(t.key);
  }
  return out;
}
}  // namespace

std::vector<effects::Keyframe> preview_keyframe_list(const PreviewTarget& target) {
  std::size_t index = 0;
  return list_without(target, replaced_by(target), index);
}

std::shared_ptr<const effects::RbfInterpolator> PreviewInterpolant::update(const PreviewTarget& t) {
  bool same = set_ && t.effect == effect_ && t.moved == moved_ && t.dimension == dimension_ &&
              t.neutral == neutral_ && t.settings == settings_ && t.fps == fps_;
  if (same && t.revision != revision_) {
    // The revision also moves for edits that leave these keyframes alone (chosen values).
    same = *t.keyframes == base_;
    if (same) revision_ = t.revision;
  }
  auto dropped = replaced_by(t);
  if (!same || dropped != dropped_) {
    seed(t, std::move(dropped));
    return set_->solution();
  }
  if (!(t.key.direction == current_.direction) || t.key.frame != current_.frame) {
    const auto e = set_->move(index_, t.key.direction, t.key.frame);
    ++moves_;
    if (e.replaced) {  // a boundary case of the rule above: start over from the document
      seed(t, replaced_by(t));
      return set_->solution();
    }
    index_ = e.index;
    current_.direction = t.key.direction;
    current_.frame = t.key.frame;
  }
  if (t.key.params != current_.params) {
    set_->set_params(index_, t.key.params);
    current_.params = t.key.params;
  }
  return set_->solution();
}

void PreviewInterpolant::reset() {
  set_.reset();
  base_.clear();
  dropped_.clear();
}

void PreviewInterpolant::seed(const PreviewTarget& t, std::vector<std::size_t> dropped) {
  set_.reset();  // its worker (if any) stops before the new one starts
  if (!seed_by_clone(t, dropped)) {
    auto list = list_without(t, dropped, index_);
    set_.reset();
    set_ = std::make_unique<effects::KeyframeSet>(t.dimension, t.settings, t.fps, std::move(list), options_, t.neutral);
    ++full_seeds_;
  }
  base_ = *t.keyframes;
  revision_ = t.revision;
  moved_ = t.moved;
  effect_ = t.effect;
  dimension_ = t.dimension;
  neutral_ = t.neutral;
  settings_ = t.settings;
  fps_ = t.fps;
  dropped_ = std::move(dropped);
  current_ = t.key;
  ++seeds_;
}

bool PreviewInterpolant::seed_by_clone(const PreviewTarget& t, const std::vector<std::size_t>& dropped) {
  if (!t.source || &t.source->keyframes() != t.keyframes || t.source->dimension() != t.dimension) return false;
  set_ = t.source->clone(options_);
  // The keyframes the preview keyframe replaces go first (from the back, so indices hold); the
  // list keeps its order, as list_without() builds it.
  std::size_t index = t.moved ? *t.moved : 0;
  for (auto it = dropped.rbegin(); it != dropped.rend(); ++it) {
    set_->remove(*it);
    if (t.moved && *it < *t.moved) --index;
  }
  if (t.moved && *t.moved < t.keyframes->size()) {
    const auto& k = set_->keyframes()[index];
    if (!(k.direction == t.key.direction) || k.frame != t.key.frame) {
      const auto e = set_->move(index, t.key.direction, t.key.frame);
      if (e.replaced) return false;  // a boundary case of the replace rule: solve the list
      index = e.index;
    }
    if (set_->keyframes()[index].params != t.key.params) set_->set_params(index, t.key.params);
  } else {
    const auto e = set_->add(t.key);
    if (e.replaced) return false;
    index = e.index;
  }
  index_ = index;
  if (!set_->stats().cloned_exact) ++full_seeds_;  // the clone itself solved
  return true;
}

}  // namespace vdfx::app
