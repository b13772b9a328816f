/// @file
/// @brief observe_frame: find_brightest_region into the set's tracker.
#include "effects/flare_set_cv.h"

#include "effects/auto_light.h"

namespace vdfx::effects {

void observe_frame(FlareSet& set, std::int64_t frame, const cv::Mat& rgb) {
  if (!set.uses_auto_light()) return;
  // A frame measured before keeps its measurement; recording it again marks it the latest shown
  // (the tracker's memory keeps the frames nearest to it).
  set.record_light(frame, set.observed(frame)
                              ? std::nullopt
                              : find_brightest_region(rgb, set.auto_light_options()));
}

}  // namespace vdfx::effects
