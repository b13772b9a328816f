/// @file
/// @brief Document: edits through KeyframeSet, snapshots for undo, sidecar rebuild.
#include "app/document.h"

#include <algorithm>
#include <stdexcept>

#include "io/input_error.h"

namespace vdfx::app {

using effects::EffectType;

Document::Document(io::Sidecar sidecar, DocumentOptions options)
    : video_(sidecar.video),
      defaults_(sidecar.interpolation),
      flares_(std::move(sidecar.flares)),
      grains_(std::move(sidecar.grains)),
      options_(options) {
  std::array<std::vector<effects::Keyframe>, effects::kEffectCount> loaded;
  for (auto& track : sidecar.effects) {
    overrides_[idx(track.type)] = track.interpolation;
    loaded[idx(track.type)] = std::move(track.keyframes);
  }
  for (const auto& spec : effects::all_effect_specs()) {
    params_[idx(spec.type)] = spec.neutral();
    rebuild(spec.type, std::move(loaded[idx(spec.type)]));
  }
}

io::Sidecar Document::sidecar() const {
  io::Sidecar s;
  s.video = video_;
  s.interpolation = defaults_;
  s.flares = flares_;
  s.grains = grains_;
  for (const auto& spec : effects::all_effect_specs()) {
    const auto i = idx(spec.type);
    if (sets_[i]->keyframes().empty() && !overrides_[i]) continue;
    s.effects.push_back({spec.type, overrides_[i], sets_[i]->keyframes()});
  }
  return s;
}

effects::InterpolationSettings Document::interpolation(EffectType type) const {
  return overrides_[idx(type)].value_or(defaults_);
}

effects::StackInterpolator Document::interpolator() const {
  effects::StackInterpolator::Solutions solutions;
  for (std::size_t i = 0; i < solutions.size(); ++i) {
    auto s = sets_[i]->solution();
    if (s && !s->empty()) solutions[i] = std::move(s);
  }
  return effects::StackInterpolator(std::move(solutions));
}

std::vector<double> Document::clamp_params(EffectType type, std::vector<double> params) {
  const auto& spec = effects::effect_spec(type);
  if (static_cast<int>(params.size()) != spec.dimension())
    throw std::invalid_argument("Document: " + std::string(spec.name) + " takes " +
                                std::to_string(spec.dimension()) + " values, got " +
                                std::to_string(params.size()));
  std::size_t k = 0;
  for (const auto& p : spec.params)
    for (int c = 0; c < p.size; ++c, ++k) params[k] = std::clamp(params[k], p.min, p.max);
  if (type == EffectType::Tint) {
    const Eigen::Vector3d g = effects::normalize_tint({params[0], params[1], params[2]});
    params = {g[0], g[1], g[2]};
  }
  return params;
}

EffectSnapshot Document::snapshot(EffectType type) const {
  return {overrides_[idx(type)], sets_[idx(type)]->keyframes(), params_[idx(type)]};
}

void Document::rebuild(EffectType type, std::vector<effects::Keyframe> keyframes) {
  const auto& spec = effects::effect_spec(type);
  try {
    sets_[idx(type)] = std::make_unique<effects::KeyframeSet>(
        spec.dimension(), interpolation(type), video_.fps, std::move(keyframes),
        options_.keyframes, spec.neutral());
  } catch (const std::invalid_argument& e) {
    throw io::InputError(std::string(spec.name) + ": " + e.what());
  }
}

void Document::restore(EffectType type, const EffectSnapshot& s) {
  overrides_[idx(type)] = s.interpolation;
  params_[idx(type)] = s.params;
  rebuild(type, s.keyframes);
}

void Document::record(const std::string& label, EffectType type, EffectSnapshot before) {
  undo_.push(label, EffectChange{type, std::move(before), snapshot(type)});
  changed();
}

void Document::changed() {
  ++revision_;
  if (listener_) listener_();
}

effects::KeyframeSet::Edit Document::add_keyframe(EffectType type, const effects::Keyframe& keyframe) {
  auto before = snapshot(type);
  effects::Keyframe k = keyframe;
  k.params = clamp_params(type, std::move(k.params));
  const auto edit = sets_[idx(type)]->add(std::move(k));
  record(edit.replaced ? "replace keyframe" : "add keyframe", type, std::move(before));
  return edit;
}

effects::KeyframeSet::Edit Document::move_keyframe(EffectType type, std::size_t index,
                                                   const effects::Direction& direction, std::int64_t frame) {
  const auto& ks = sets_[idx(type)]->keyframes();
  if (index < ks.size() && ks[index].frame == frame && ks[index].direction == direction)
    return {index, std::nullopt, true};
  auto before = snapshot(type);
  const auto edit = sets_[idx(type)]->move(index, direction, frame);
  record(edit.replaced ? "move keyframe (replaced one)" : "move keyframe", type, std::move(before));
  return edit;
}

void Document::remove_keyframe(EffectType type, std::size_t index) {
  auto before = snapshot(type);
  sets_[idx(type)]->remove(index);
  record("delete keyframe", type, std::move(before));
}

void Document::set_keyframe_params(EffectType type, std::size_t index, std::vector<double> params) {
  params = clamp_params(type, std::move(params));
  if (index < keyframes(type).size() && keyframes(type)[index].params == params) return;
  auto before = snapshot(type);
  sets_[idx(type)]->set_params(index, std::move(params));
  record("keyframe parameters", type, std::move(before));
}

void Document::set_params(EffectType type, std::vector<double> params) {
  params = clamp_params(type, std::move(params));
  if (params == params_[idx(type)]) return;
  auto before = snapshot(type);
  params_[idx(type)] = std::move(params);
  record(std::string(effects::effect_name(type)) + " value", type, std::move(before));
}

void Document::set_interpolation(EffectType type, const effects::InterpolationSettings& settings) {
  const auto& spec = effects::effect_spec(type);
  if (!(settings.exponent > effects::kExponentMin && settings.exponent < effects::kExponentMax))
    throw io::InputError(std::string(spec.name) + ": exponent " + std::to_string(settings.exponent) +
                         " outside (0, 4)");
  if (!(settings.time_scale > effects::kTimeScaleMin && settings.time_scale <= effects::kTimeScaleMax))
    throw io::InputError(std::string(spec.name) + ": time scale " +
                         std::to_string(settings.time_scale) + " outside (0, 1000]");
  if (interpolation(type) == settings && overrides_[idx(type)]) return;
  auto before = snapshot(type);
  overrides_[idx(type)] = settings;
  rebuild(type, sets_[idx(type)]->keyframes());
  record(std::string(spec.name) + " interpolation", type, std::move(before));
}

PendingEdit& Document::begin_pending(EffectType type, std::optional<std::size_t> moved, effects::Keyframe key) {
  pending_.reset();
  pending_ = std::make_unique<PendingEdit>(*this, type, moved, std::move(key), options_.keyframes, pending_stats_);
  return *pending_;
}

std::optional<effects::KeyframeSet::Edit> Document::commit_pending() {
  if (!pending_) return std::nullopt;
  const std::unique_ptr<PendingEdit> p = std::move(pending_);
  if (p->moved()) return move_keyframe(p->effect(), *p->moved(), p->key().direction, p->key().frame);
  return add_keyframe(p->effect(), p->key());
}

std::uint64_t Document::solutions_version() const {
  std::uint64_t v = 0;
  for (const auto& set : sets_) v += set->solution_version();
  return v;
}

bool Document::undo() {
  const auto step = undo_.undo();
  if (!step) return false;
  for (auto it = step->changes.rbegin(); it != step->changes.rend(); ++it) restore(it->type, it->before);
  changed();
  return true;
}

bool Document::redo() {
  const auto step = undo_.redo();
  if (!step) return false;
  for (const auto& c : step->changes) restore(c.type, c.after);
  changed();
  return true;
}

}  // namespace vdfx::app
