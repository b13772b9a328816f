/// @file
/// @brief The benchmarks' grain scene.
#include "app/bench/grain_setup.h"

#include "app/bench/flare_setup.h"
#include "app/bench/inputs.h"

namespace vdfx::app::bench {

effects::GrainSet grain_set(effects::GrainStyle style, double intensity, int count,
                            double sphere_m) {
  effects::GrainEffect e;
  e.style = style;
  e.seed = 7;
  e.settings = effects::GrainSettings(style);
  if (count > 0) e.settings.set(effects::GrainSetting::Count, count);
  if (sphere_m > 0) e.settings.set(effects::GrainSetting::SphereM, sphere_m);
  e.keyframes = {{{0, 0}, 0, {intensity, 1.0}}};
  return effects::GrainSet({e}, {}, 30.0);
}

effects::HeadPose grain_head() {
  const xr::Pose h = head_at(kFlareLook);
  return {xr::position_of(h), xr::rotation_of(h)};
}

}  // namespace vdfx::app::bench
