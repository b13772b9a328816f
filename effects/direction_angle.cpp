/// @file
/// @brief angle_between_deg.
#include "effects/direction_angle.h"

namespace vdfx::effects {

double angle_between_deg(const Direction& a, const Direction& b) {
  return angle_between(to_unit(a), to_unit(b)) * kRadToDeg;
}

}  // namespace vdfx::effects
