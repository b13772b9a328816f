/// @file
/// @brief EditTarget: names and parameter specs of the editor's eight targets.
#include "app/editor/edit_target.h"

#include <algorithm>
#include <utility>

#include "effects/flare.h"
#include "effects/grain.h"

namespace vdfx::app {

EditTarget EditTarget::from_index(int index) {
  return EditTarget(std::clamp(index, 0, kCount - 1));
}

std::optional<effects::EffectType> EditTarget::stack_effect() const {
  if (index_ >= effects::kEffectCount) return std::nullopt;
  return static_cast<effects::EffectType>(index_);
}

std::string_view EditTarget::name() const {
  if (is_flare()) return "flare";
  if (is_grain()) return "grain";
  return effects::effect_name(*stack_effect());
}

std::string EditTarget::title() const {
  std::string n(name());
  if (!n.empty()) n[0] = static_cast<char>(n[0] - 'a' + 'A');
  return n;
}

const std::vector<effects::ParamSpec>& EditTarget::params() const {
  static const std::vector<effects::ParamSpec> flare{effects::kFlareIntensitySpec};
  if (is_flare()) return flare;
  if (is_grain()) return effects::grain_param_specs();
  return effects::effect_spec(*stack_effect()).params;
}

int EditTarget::dimension() const {
  int n = 0;
  for (const auto& p : params()) n += p.size;
  return n;
}

std::vector<double> EditTarget::neutral() const {
  std::vector<double> v;
  for (const auto& p : params()) v.insert(v.end(), static_cast<std::size_t>(p.size), p.neutral);
  return v;
}

const std::array<EditTarget, EditTarget::kCount>& all_edit_targets() {
  static const auto all = []<std::size_t... I>(std::index_sequence<I...>) {
    return std::array<EditTarget, EditTarget::kCount>{
        EditTarget::from_index(static_cast<int>(I))...};
  }
  (std::make_index_sequence<EditTarget::kCount>{});
  return all;
}

}  // namespace vdfx::app
