/// @file
/// @brief Document: edits through KeyframeSet, snapshots for undo, sidecar rebuild.
#include "app/editor/document.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "effects/interpolation_check.h"
#include "io/input_error.h"

namespace vdfx::app {

using effects::EffectType;

namespace {

// A flare or grain entry without what the document keeps beside its other targets' (keyframe
// sets, overrides, anchors).
template <class Layer>
Layer head_of(Layer layer) {
  layer.keyframes.clear();
  layer.interpolation.reset();
  layer.anchor = {};
  return layer;
}

}  // namespace

Document::Document(io::Sidecar sidecar, DocumentOptions options)
    : video_(sidecar.video),
      defaults_(sidecar.interpolation),
      camera_(std::move(sidecar.camera)),
      tracks_(std::move(sidecar.tracks)),
      options_(options) {
  std::array<std::vector<effects::Keyframe>, EditTarget::kCount> loaded;
  for (auto& track : sidecar.effects) {
    overrides_[idx(track.type)] = track.interpolation;
    anchors_[idx(track.type)] = track.anchor;
    loaded[idx(track.type)] = std::move(track.keyframes);
  }
  // The first flare and grain are edited; the others ride along.
  const auto take_first = [&](auto& from, auto& first, auto& more, EditTarget t) {
    if (from.empty()) return;
    overrides_[idx(t)] = from.front().interpolation;
    anchors_[idx(t)] = from.front().anchor;
    loaded[idx(t)] = from.front().keyframes;
    first = head_of(std::move(from.front()));
    more.assign(std::make_move_iterator(from.begin() + 1), std::make_move_iterator(from.end()));
  };
  take_first(sidecar.flares, flare_, more_flares_, EditTarget::flare());
  take_first(sidecar.grains, grain_, more_grains_, EditTarget::grain());
  resolve_anchors();
  for (const EditTarget t : all_edit_targets()) {
    params_[idx(t)] = t.neutral();
    rebuild(t, std::move(loaded[idx(t)]));
  }
}

effects::FlareEffect Document::new_flare() {
  effects::FlareEffect f;
  f.style = effects::FlareStyle::Directional;
  f.light = effects::AutoLight{};
  f.settings = effects::default_flare_settings(f.style);
  return f;
}

io::Sidecar Document::sidecar() const {
  io::Sidecar s;
  s.video = video_;
  s.interpolation = defaults_;
  s.camera = camera_;
  s.tracks = tracks_;
  for (const auto& spec : effects::all_effect_specs()) {
    const auto i = idx(spec.type);
    if (sets_[i]->keyframes().empty() && !overrides_[i] && anchors_[i].is_video()) continue;
    s.effects.push_back({spec.type, overrides_[i], sets_[i]->keyframes(), anchors_[i]});
  }
  // The edited entry first, when there is one to write, then the rest as read.
  const auto put = [&](auto& out, const auto& head, const auto& fresh, const auto& more,
                       EditTarget t) {
    const auto i = idx(t);
    if (head || !sets_[i]->keyframes().empty() || overrides_[i] || !anchors_[i].is_video()) {
      auto& e = out.emplace_back(head.value_or(fresh));
      e.keyframes = sets_[i]->keyframes();
      e.interpolation = overrides_[i];
      e.anchor = anchors_[i];
    }
    out.insert(out.end(), more.begin(), more.end());
  };
  put(s.flares, flare_, new_flare(), more_flares_, EditTarget::flare());
  put(s.grains, grain_, effects::GrainEffect{}, more_grains_, EditTarget::grain());
  return s;
}

effects::InterpolationSettings Document::interpolation(EditTarget t) const {
  return overrides_[idx(t)].value_or(defaults_);
}

effects::StackInterpolator Document::interpolator() const {
  effects::StackInterpolator::Solutions solutions;
  effects::StackInterpolator::Anchors anchors;
  for (std::size_t i = 0; i < solutions.size(); ++i) {
    auto s = sets_[i]->solution();
    if (s && !s->empty()) solutions[i] = std::move(s);
    anchors[i] = {anchors_[i], frames_[i]};  // a stack effect's EditTarget index is its type's
  }
  return effects::StackInterpolator(std::move(solutions), std::move(anchors));
}

std::vector<double> Document::clamp_params(EditTarget t, std::vector<double> params) {
  if (static_cast<int>(params.size()) != t.dimension())
    throw std::invalid_argument("Document: " + std::string(t.name()) + " takes " +
                                std::to_string(t.dimension()) + " values, got " +
                                std::to_string(params.size()));
  std::size_t k = 0;
  for (const auto& p : t.params())
    for (int c = 0; c < p.size; ++c, ++k) params[k] = std::clamp(params[k], p.min, p.max);
  if (t == EffectType::Tint) {
    const Eigen::Vector3d g = effects::normalize_tint({params[0], params[1], params[2]});
    params = {g[0], g[1], g[2]};
  }
  return params;
}

EffectSnapshot Document::snapshot(EditTarget t) const {
  EffectSnapshot s{overrides_[idx(t)], sets_[idx(t)]->keyframes(),
                   params_[idx(t)],    anchors_[idx(t)],
                   std::nullopt,       std::nullopt};
  if (t.is_flare()) s.flare = flare_;
  if (t.is_grain()) s.grain = grain_;
  return s;
}

void Document::rebuild(EditTarget t, std::vector<effects::Keyframe> keyframes) {
  try {
    sets_[idx(t)] = std::make_unique<effects::KeyframeSet>(t.dimension(), interpolation(t),
                                                           video_.fps, std::move(keyframes),
                                                           options_.keyframes, t.neutral());
  } catch (const std::invalid_argument& e) {
    throw io::InputError(std::string(t.name()) + ": " + e.what());
  }
}

void Document::restore(EditTarget t, const EffectSnapshot& s) {
  if (!(anchors_[idx(t)] == s.anchor)) {
    anchors_[idx(t)] = s.anchor;
    if (!restoring_step_) resolve_anchors();
  }
  const effects::InterpolationSettings before = interpolation(t);
  overrides_[idx(t)] = s.interpolation;
  params_[idx(t)] = s.params;
  if (t.is_flare()) flare_ = s.flare;
  if (t.is_grain()) grain_ = s.grain;
  if (!(interpolation(t) == before)) {
    rebuild(t, s.keyframes);
    return;
  }
  // The same settings: the set keeps what did not change (a locally interpolated effect
  // re-solves only the windows the undone edit touched).
  if (sets_[idx(t)]->keyframes() == s.keyframes) return;
  try {
    sets_[idx(t)]->assign(s.keyframes);
  } catch (const std::invalid_argument& e) {
    throw io::InputError(std::string(t.name()) + ": " + e.what());
  }
}

void Document::record(const std::string& label, EditTarget t, EffectSnapshot before) {
  undo_.push(label, EffectChange{t, std::move(before), snapshot(t)});
  changed();
}

void Document::changed() {
  ++revision_;
  // A drag is one group of many changes (one a frame): the listener (autosave: two atomic writes,
  // four fsyncs) hears of it once, when the group closes, not on the frame thread every frame.
  if (undo_.in_group()) {
    unheard_ = true;
    return;
  }
  if (listener_) listener_();
}

void Document::end_group() {
  undo_.end_group();
  if (undo_.in_group() || !std::exchange(unheard_, false)) return;
  if (listener_) listener_();
}

effects::KeyframeSet::Edit Document::add_keyframe(EditTarget t, const effects::Keyframe& keyframe) {
  auto before = snapshot(t);
  effects::Keyframe k = keyframe;
  k.params = clamp_params(t, std::move(k.params));
  const auto edit = sets_[idx(t)]->add(std::move(k));
  record(edit.replaced ? "replace keyframe" : "add keyframe", t, std::move(before));
  return edit;
}

effects::KeyframeSet::Edit Document::move_keyframe(EditTarget t, std::size_t index,
                                                   const effects::Direction& direction,
                                                   std::int64_t frame) {
  const auto& ks = sets_[idx(t)]->keyframes();
  if (index < ks.size() && ks[index].frame == frame && ks[index].direction == direction)
    return {index, std::nullopt, true};
  auto before = snapshot(t);
  const auto edit = sets_[idx(t)]->move(index, direction, frame);
  record(edit.replaced ? "move keyframe (replaced one)" : "move keyframe", t, std::move(before));
  return edit;
}

void Document::remove_keyframe(EditTarget t, std::size_t index) {
  auto before = snapshot(t);
  sets_[idx(t)]->remove(index);
  record("delete keyframe", t, std::move(before));
}

void Document::set_keyframe_params(EditTarget t, std::size_t index, std::vector<double> params) {
  params = clamp_params(t, std::move(params));
  if (index < keyframes(t).size() && keyframes(t)[index].params == params) return;
  auto before = snapshot(t);
  sets_[idx(t)]->set_params(index, std::move(params));
  record("keyframe parameters", t, std::move(before));
}

void Document::set_params(EditTarget t, std::vector<double> params) {
  params = clamp_params(t, std::move(params));
  if (params == params_[idx(t)]) return;
  auto before = snapshot(t);
  params_[idx(t)] = std::move(params);
  record(std::string(t.name()) + " value", t, std::move(before));
}

void Document::set_interpolation(EditTarget t, const effects::InterpolationSettings& settings) {
  const std::string name(t.name());
  if (const auto problem = effects::interpolation_problem(settings))
    throw io::InputError(name + ": " + *problem);
  if (interpolation(t) == settings && overrides_[idx(t)]) return;
  auto before = snapshot(t);
  overrides_[idx(t)] = settings;
  rebuild(t, sets_[idx(t)]->keyframes());
  record(name + " interpolation", t, std::move(before));
}

void Document::set_flare_style(effects::FlareStyle style) {
  effects::FlareEffect f = flare();
  if (flare_ && f.style == style) return;
  auto before = snapshot(EditTarget::flare());
  if (f.settings.plane_m == effects::default_flare_settings(f.style).plane_m)
    f.settings.plane_m = effects::default_flare_settings(style).plane_m;
  f.style = style;
  flare_ = std::move(f);
  record("flare style", EditTarget::flare(), std::move(before));
}

void Document::set_flare_light(const effects::FlareLight& light) {
  if (flare_ && flare_->light == light) return;
  auto before = snapshot(EditTarget::flare());
  effects::FlareEffect f = flare();
  f.light = light;
  flare_ = std::move(f);
  record("flare light", EditTarget::flare(), std::move(before));
}

void Document::set_grain_style(effects::GrainStyle style) {
  if (grain_ && grain_->style == style) return;
  auto before = snapshot(EditTarget::grain());
  effects::GrainEffect g = grain();
  // A setting still at the old style's default takes the new style's (object_cloud's sphere).
  for (const effects::GrainSetting id : effects::grain_style_settings(style))
    if (g.settings.get(id) == effects::grain_setting_default(g.style, id))
      g.settings.set(id, effects::grain_setting_default(style, id));
  g.style = style;
  grain_ = std::move(g);
  record("grain style", EditTarget::grain(), std::move(before));
}

PendingEdit& Document::begin_pending(EditTarget t, std::optional<std::size_t> moved,
                                     effects::Keyframe key) {
  pending_.reset();
  pending_ = std::make_unique<PendingEdit>(*this, t, moved, std::move(key), options_.keyframes,
                                           pending_stats_);
  return *pending_;
}

std::optional<effects::KeyframeSet::Edit> Document::commit_pending() {
  if (!pending_) return std::nullopt;
  const std::unique_ptr<PendingEdit> p = std::move(pending_);
  if (p->moved())
    return move_keyframe(p->target(), *p->moved(), p->key().direction, p->key().frame);
  return add_keyframe(p->target(), p->key());
}

std::uint64_t Document::solutions_version() const {
  std::uint64_t v = 0;
  for (const auto& set : sets_) v += set->solution_version();
  return v;
}

namespace {

/// Sets the flag for its scope, cleared also when a restore throws.
struct RestoringStep {
  explicit RestoringStep(bool& flag) : flag_(flag) { flag_ = true; }
  ~RestoringStep() { flag_ = false; }
  RestoringStep(const RestoringStep&) = delete;
  RestoringStep& operator=(const RestoringStep&) = delete;
  bool& flag_;
};

}  // namespace

// A step may change anchors and the tracks they name together (deleting a track re-anchors its
// effects): the anchors are resolved once, against the restored tracks, after the whole step.
bool Document::undo() {
  const auto step = undo_.undo();
  if (!step) return false;
  {
    const RestoringStep hold(restoring_step_);
    for (auto it = step->changes.rbegin(); it != step->changes.rend(); ++it)
      restore(it->target, it->before);
    if (step->sources) restore(step->sources->before);
  }
  resolve_anchors();
  changed();
  return true;
}

bool Document::redo() {
  const auto step = undo_.redo();
  if (!step) return false;
  {
    const RestoringStep hold(restoring_step_);
    if (step->sources) restore(step->sources->after);
    for (const auto& c : step->changes) restore(c.target, c.after);
  }
  resolve_anchors();
  changed();
  return true;
}

}  // namespace vdfx::app
