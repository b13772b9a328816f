/// @file
/// @brief GrainInterpolator: a two-parameter RbfInterpolator with the grain ranges.
#include "effects/grain_interpolator.h"

#include <algorithm>
#include <stdexcept>

namespace vdfx::effects {
namespace {
std::vector<double> neutral() {
  std::vector<double> n;
  for (const ParamSpec& p : grain_param_specs()) n.push_back(p.neutral);
  return n;
}
}  // namespace

GrainInterpolator::GrainInterpolator(const GrainEffect& e, const InterpolationSettings& defaults,
                                     double fps)
    : rbf_(std::make_shared<const RbfInterpolator>(
          e.keyframes, kGrainParamCount, e.interpolation.value_or(defaults), fps, neutral())) {}

GrainInterpolator::GrainInterpolator(std::shared_ptr<const RbfInterpolator> rbf)
    : rbf_(std::move(rbf)) {
  if (!rbf_ || rbf_->dimension() != kGrainParamCount)
    throw std::invalid_argument("GrainInterpolator: a two-value interpolant is needed");
}

GrainParams GrainInterpolator::evaluate(const Eigen::Vector3d& unit, std::int64_t frame) const {
  double v[kGrainParamCount];
  rbf_->evaluate_into(unit, frame, v);
  const auto& specs = grain_param_specs();
  GrainParams p;
  p.intensity = std::clamp(v[0], specs[0].min, specs[0].max);
  p.size = std::clamp(v[1], specs[1].min, specs[1].max);
  return p;
}

GrainParams GrainInterpolator::evaluate(const Direction& d, std::int64_t frame) const {
  return evaluate(to_unit(d), frame);
}

}  // namespace vdfx::effects
