/// @file
/// @brief The six effects of the contract: names, parameters, ranges, neutral values.
///
/// Each effect's keyframes carry a flat parameter vector laid out as in its EffectSpec
/// (tint: [r, g, b]; vignette: [radius_deg, falloff_deg]; the others one value). The sidecar
/// names ("sigma_deg", "gain", ...) and the ranges are the contract's table.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace vdfx::effects {

/// In the order the stack applies them (the paper's order).
enum class EffectType { Blur = 0, Tint, Exposure, Saturation, Contrast, Vignette };
inline constexpr int kEffectCount = 6;

struct ParamSpec {
  std::string_view name;  //!< sidecar name
  int size;               //!< 1, or 3 for the tint gain array
  double min;
  double max;
  double neutral;  //!< per component
};

struct EffectSpec {
  EffectType type;
  std::string_view name;  //!< sidecar "type"
  std::vector<ParamSpec> params;
  int dimension() const;  //!< length of the flat parameter vector
  std::vector<double> neutral() const;
};

const EffectSpec& effect_spec(EffectType type);
const std::vector<EffectSpec>& all_effect_specs();
std::optional<EffectType> effect_type_from_name(std::string_view name);
std::string_view effect_name(EffectType type);

/// Rec. 601-like weights of the contract, used for tint normalisation and saturation.
inline constexpr double kLumaR = 0.25, kLumaG = 0.5, kLumaB = 0.25;

/// Scales a tint gain so that 0.25 r + 0.5 g + 0.25 b = 1 (tint never changes brightness).
/// A gain whose weighted sum is not positive becomes neutral.
Eigen::Vector3d normalize_tint(const Eigen::Vector3d& gain);

/// Parameters of the whole stack at one view (or one pixel). Defaults are the neutral values.
struct StackParams {
  double blur_sigma_deg = 0.0;
  Eigen::Vector3d tint_gain{1.0, 1.0, 1.0};
  double exposure_stops = 0.0;
  double saturation = 1.0;
  double contrast = 1.0;
  double vignette_radius_deg = 180.0;
  double vignette_falloff_deg = 0.01;

  /// Sets one effect's parameters from its flat vector, clamped to the contract's ranges
  /// (interpolation may overshoot); tint is renormalised.
  void set(EffectType type, std::span<const double> values);
  /// The flat vector of one effect.
  std::vector<double> get(EffectType type) const;
  /// True when the effect would leave every pixel exactly unchanged.
  bool is_neutral(EffectType type) const;
};

}  // namespace vdfx::effects
