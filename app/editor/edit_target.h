/// @file
/// @brief What the editor edits: one of the six stack effects, the sidecar's first lens flare or
/// its first grain effect. Each has keyframes of a flat parameter vector (the effect's spec;
/// flare: intensity; grain: intensity and size), so the document, the pending edit, the undo
/// stack and the visualizations treat all eight alike.
///
/// A stack effect converts to its target implicitly, so code about the six effects reads as
/// before (`doc.keyframes(EffectType::Tint)`).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "effects/effect_types.h"

namespace vdfx::app {

class EditTarget {
 public:
  static constexpr int kCount = effects::kEffectCount + 2;

  constexpr EditTarget(effects::EffectType type)
      : index_(static_cast<int>(type)) {}  // NOLINT: implicit
  static constexpr EditTarget flare() { return EditTarget(effects::kEffectCount); }
  static constexpr EditTarget grain() { return EditTarget(effects::kEffectCount + 1); }
  /// The target at menu position `index` (clamped to 0..kCount-1).
  static EditTarget from_index(int index);

  constexpr int index() const { return index_; }
  constexpr bool is_flare() const { return index_ == effects::kEffectCount; }
  constexpr bool is_grain() const { return index_ == effects::kEffectCount + 1; }
  /// The stack effect, nullopt for the flare and the grain.
  std::optional<effects::EffectType> stack_effect() const;

  /// The sidecar's name ("exposure", ..., "flare", "grain").
  std::string_view name() const;
  /// The name as the panels show it ("Exposure", ..., "Flare", "Grain").
  std::string title() const;
  /// The keyframed parameters, in the flat vector's order.
  const std::vector<effects::ParamSpec>& params() const;
  int dimension() const;
  std::vector<double> neutral() const;

  constexpr bool operator==(const EditTarget&) const = default;

 private:
  constexpr explicit EditTarget(int index) : index_(index) {}
  int index_;
};

/// Every target in menu order: the stack (blur ... vignette), then flare and grain.
const std::array<EditTarget, EditTarget::kCount>& all_edit_targets();

}  // namespace vdfx::app
