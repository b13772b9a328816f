/// @file
/// @brief StackInterpolator, FlareSet and GrainSet construction with the sidecar's anchors and its
/// errors as input errors.
#include "io/sidecar_sets.h"

#include <stdexcept>
#include <string>

#include "io/input_error.h"

namespace vdfx::io {

namespace {

/// make(), its std::invalid_argument an InputError saying which of the sidecar's entries (`what`)
/// cannot be interpolated.
template <class Make>
auto built(const char* what, const Make& make) {
  try {
    return make();
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("sidecar ") + what + " cannot be interpolated: " + e.what());
  }
}

}  // namespace

effects::AnchorSources anchor_sources(const Sidecar& sidecar) {
  return {sidecar.camera ? &*sidecar.camera : nullptr, sidecar.tracks};
}

effects::StackInterpolator stack_of(const Sidecar& s) {
  return built("effects", [&] {
    return effects::StackInterpolator(s.effects, s.interpolation, s.video.fps, anchor_sources(s));
  });
}

effects::FlareSet flare_set_of(const Sidecar& s) {
  return built("flares", [&] {
    return effects::FlareSet(s.flares, s.interpolation, s.video.fps, anchor_sources(s));
  });
}

effects::GrainSet grain_set_of(const Sidecar& s) {
  return built("grain", [&] {
    return effects::GrainSet(s.grains, s.interpolation, s.video.fps, anchor_sources(s));
  });
}

}  // namespace vdfx::io
