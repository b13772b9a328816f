/// @file
/// @brief The benchmarks' flare scene.
#include "app/bench_flare_setup.h"

#include <glm/gtc/quaternion.hpp>
#include <stdexcept>

#include "xr/eye_views.h"

namespace vdfx::app::bench {

xr::Pose flare_head(const effects::Direction& look) {
  xr::Pose p;
  p.position = {0.0, 1.6, 0.0};
  p.orientation = glm::quat_cast(xr::camera_rotation(look, 0.0));
  return p;
}

effects::FlareLayout flare_layout(effects::FlareStyle style, int rings) {
  effects::FlareSettings s = effects::default_flare_settings(style);
  s.rings = rings;
  const xr::Pose h = flare_head();
  const auto l = effects::layout_flare(style, s, {xr::position_of(h), xr::rotation_of(h)},
                                       effects::to_unit(kFlareLight), 1.0);
  if (!l) throw std::logic_error("the bench flare adds nothing");
  return *l;
}

}  // namespace vdfx::app::bench
