/// @file
/// @brief PendingEdit: a keyframe being placed or held, with a scratch KeyframeSet moved one
/// keyframe at a time.
#include "app/editor/pending_edit.h"

#include <algorithm>

#include "app/editor/document.h"

namespace vdfx::app {

struct PendingEdit::Scratch {
  std::unique_ptr<effects::KeyframeSet> set;
  std::vector<effects::Keyframe> base;  //!< the document's keyframes it was seeded from
  std::uint64_t revision = 0;           //!< the document's revision then
  effects::InterpolationSettings settings;
  std::vector<std::size_t> dropped;  //!< indices into base left out (replaced by the key)
  std::size_t index = 0;             //!< the pending keyframe's index in the set
  effects::Keyframe current;         //!< the pending keyframe as the set has it
};

PendingEdit::PendingEdit(const Document& document, EditTarget target,
                         std::optional<std::size_t> moved, effects::Keyframe key,
                         effects::KeyframeSetOptions options, PendingStats& stats)
    : doc_(document),
      target_(target),
      moved_(moved),
      key_(std::move(key)),
      options_(options),
      stats_(stats) {
  was_changing_ = changes_interpolant();
  version_ = ++stats_.serial;
}

PendingEdit::~PendingEdit() = default;

void PendingEdit::set_key(effects::Keyframe key) {
  if (key == key_) return;
  key_ = std::move(key);
  // A new version whenever the interpolant changes: the key moved while it counts, or it began
  // to count (a held keyframe leaving its place).
  const bool changing = changes_interpolant();
  if (changing) version_ = ++stats_.serial;
  was_changing_ = changing;
}

void PendingEdit::hold_from(const effects::Direction& view, std::int64_t frame) {
  hold_ = Hold{view, frame, key_};
}

effects::Keyframe PendingEdit::placed_at(const effects::Direction& view, std::int64_t frame) const {
  // The view is a direction of the video frame at `frame`; the key is stored in the anchor's.
  const effects::AnchorFrames& anchor = doc_.anchor_frames(target_);
  if (!moved_) return {anchor.apply(view, frame), frame, doc_.params(target_)};
  const auto& ks = doc_.keyframes(target_);
  if (!hold_ || *moved_ >= ks.size()) return key_;
  effects::Keyframe k = ks[*moved_];
  const effects::Keyframe& k0 = hold_->key;
  // The offsets apply where the held keyframe showed when the hold began (the video frame at
  // the playhead then), and the result is stored as the video frame at the playhead now shows
  // it: held while looked at, it stays at the view centre whatever the camera does.
  const effects::Direction shown = anchor.unapply(k0.direction, hold_->frame);
  effects::Direction d;
  d.azimuth_deg =
      effects::wrap_azimuth_deg(shown.azimuth_deg + (view.azimuth_deg - hold_->view.azimuth_deg));
  d.altitude_deg =
      std::clamp(shown.altitude_deg + (view.altitude_deg - hold_->view.altitude_deg), -90.0, 90.0);
  k.direction = anchor.apply(d, frame);
  k.frame = std::clamp<std::int64_t>(k0.frame + (frame - hold_->frame), 0, doc_.video().frames - 1);
  return k;
}

bool PendingEdit::changes_interpolant() const {
  if (!moved_) return true;
  const auto& ks = doc_.keyframes(target_);
  if (*moved_ >= ks.size()) return false;
  return !(ks[*moved_].direction == key_.direction) || ks[*moved_].frame != key_.frame;
}

std::vector<std::size_t> PendingEdit::replaced() const {
  std::vector<std::size_t> out;
  const auto& ks = doc_.keyframes(target_);
  for (std::size_t i = 0; i < ks.size(); ++i)
    if (!(moved_ && i == *moved_) && effects::replaces(key_.direction, key_.frame, ks[i]))
      out.push_back(i);
  return out;
}

namespace {
/// The document's keyframes without `dropped`, the pending one in place of `moved` (or appended);
/// `index` receives where it is.
std::vector<effects::Keyframe> list_without(const std::vector<effects::Keyframe>& ks,
                                            const std::optional<std::size_t>& moved,
                                            const effects::Keyframe& key,
                                            const std::vector<std::size_t>& dropped,
                                            std::size_t& index) {
  std::vector<effects::Keyframe> out;
  out.reserve(ks.size() + 1);
  std::size_t d = 0;
  index = ks.size();
  for (std::size_t i = 0; i < ks.size(); ++i) {
    if (d < dropped.size() && dropped[d] == i) {
      ++d;
      continue;
    }
    if (moved && i == *moved) {
      index = out.size();
      out.push_back(key);
    } else {
      out.push_back(ks[i]);
    }
  }
  if (!moved || *moved >= ks.size()) {
    index = out.size();
    out.push_back(key);
  }
  return out;
}
}  // namespace

std::vector<effects::Keyframe> PendingEdit::keyframe_list() const {
  std::size_t index = 0;
  return list_without(doc_.keyframes(target_), moved_, key_, replaced(), index);
}

std::shared_ptr<const effects::RbfInterpolator> PendingEdit::interpolant() const {
  if (!changes_interpolant()) return nullptr;
  const auto& ks = doc_.keyframes(target_);
  Scratch* s = scratch_.get();
  bool same = s && s->settings == doc_.interpolation(target_);
  if (same && doc_.revision() != s->revision) {
    // The revision also moves for edits that leave these keyframes alone (chosen values).
    same = ks == s->base;
    if (same) s->revision = doc_.revision();
  }
  auto dropped = replaced();
  if (!same || dropped != s->dropped) {
    seed(std::move(dropped));
    return scratch_->set->solution();
  }
  if (!(key_.direction == s->current.direction) || key_.frame != s->current.frame) {
    const auto e = s->set->move(s->index, key_.direction, key_.frame);
    ++stats_.moves;
    if (e.replaced) {  // a boundary case of the replace rule: start over from the document
      seed(replaced());
      return scratch_->set->solution();
    }
    s->index = e.index;
    s->current.direction = key_.direction;
    s->current.frame = key_.frame;
  }
  if (key_.params != s->current.params) {
    s->set->set_params(s->index, key_.params);
    s->current.params = key_.params;
  }
  return s->set->solution();
}

void PendingEdit::seed(std::vector<std::size_t> dropped) const {
  if (scratch_)
    scratch_->set.reset();  // its worker (if any) stops before the new one starts
  else
    scratch_ = std::make_unique<Scratch>();
  Scratch& s = *scratch_;
  if (!seed_by_clone(dropped)) {
    auto list = list_without(doc_.keyframes(target_), moved_, key_, dropped, s.index);
    s.set.reset();
    s.set = std::make_unique<effects::KeyframeSet>(target_.dimension(), doc_.interpolation(target_),
                                                   doc_.video().fps, std::move(list), options_,
                                                   target_.neutral());
    ++stats_.full_seeds;
  }
  s.base = doc_.keyframes(target_);
  s.revision = doc_.revision();
  s.settings = doc_.interpolation(target_);
  s.dropped = std::move(dropped);
  s.current = key_;
  ++stats_.seeds;
}

bool PendingEdit::seed_by_clone(const std::vector<std::size_t>& dropped) const {
  Scratch& s = *scratch_;
  const effects::KeyframeSet& source = doc_.keyframe_set(target_);
  s.set = source.clone(options_);
  // The keyframes the pending keyframe replaces go first (from the back, so indices hold); the
  // list keeps its order, as list_without() builds it.
  const std::size_t count = doc_.keyframes(target_).size();
  std::size_t index = moved_ ? *moved_ : 0;
  for (auto it = dropped.rbegin(); it != dropped.rend(); ++it) {
    s.set->remove(*it);
    if (moved_ && *it < *moved_) --index;
  }
  if (moved_ && *moved_ < count) {
    const auto& k = s.set->keyframes()[index];
    if (!(k.direction == key_.direction) || k.frame != key_.frame) {
      const auto e = s.set->move(index, key_.direction, key_.frame);
      if (e.replaced) return false;  // a boundary case of the replace rule: solve the list
      index = e.index;
    }
    if (s.set->keyframes()[index].params != key_.params) s.set->set_params(index, key_.params);
  } else {
    const auto e = s.set->add(key_);
    if (e.replaced) return false;
    index = e.index;
  }
  s.index = index;
  if (!s.set->stats().cloned_exact) ++stats_.full_seeds;  // the clone itself solved
  return true;
}

}  // namespace vdfx::app
