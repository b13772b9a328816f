/// @file
/// @brief Fuzz target: the sidecar reader and validator (io::validate_sidecar_text). Properties:
/// only problems are reported, never an exception; a valid sidecar writes and reads back equal;
/// and evaluates to finite parameters, flare intensities and grain intensities and sizes too
/// (issue 11, class 4: what validates never gives NaN).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "effects/flare_set.h"
#include "effects/grain_interpolator.h"
#include "effects/stack_interpolator.h"
#include "fuzz_check.h"
#include "io/sidecar.h"
#include "io/sidecar_sets.h"
#include "io/sidecar_validate.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace vdfx;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const io::SidecarReport report = io::validate_sidecar_text(text, "fuzz.vdfx.json");
  VDFX_FUZZ_CHECK(report.ok() == report.sidecar.has_value());
  if (!report.ok()) return 0;
  const io::Sidecar& s = *report.sidecar;
  const io::SidecarReport again = io::validate_sidecar_text(io::format_sidecar(s), "again");
  VDFX_FUZZ_CHECK(again.ok() && *again.sidecar == s);
  // Cheap enough for a fuzzer's inputs (a few kilobytes: a few dozen keyframes at most).
  const effects::StackInterpolator stack = io::stack_of(s);
  for (const effects::EffectTrack& track : s.effects) {
    for (const effects::Keyframe& k : track.keyframes) {
      const effects::StackParams p = stack.evaluate(k.direction, k.frame);
      for (const double v : p.get(track.type)) VDFX_FUZZ_CHECK(std::isfinite(v));
    }
  }
  const effects::StackParams far =
      stack.evaluate(effects::Direction{-123.0, 45.0}, s.video.frames - 1);
  VDFX_FUZZ_CHECK(std::isfinite(far.exposure_stops) && std::isfinite(far.blur_sigma_deg) &&
                  std::isfinite(far.tint_gain.sum()) && std::isfinite(far.vignette_radius_deg));
  // The extension types: a valid file's keyframes interpolate (no exception) to finite values.
  const effects::FlareSet flares = io::flare_set_of(s);
  for (std::size_t i = 0; i < s.flares.size(); ++i)
    for (const effects::Keyframe& k : s.flares[i].keyframes)
      VDFX_FUZZ_CHECK(std::isfinite(flares.intensity(i, effects::to_unit(k.direction), k.frame)));
  for (const effects::GrainEffect& g : s.grains) {
    const effects::GrainInterpolator grain(g, s.interpolation, s.video.fps);
    for (const effects::Keyframe& k : g.keyframes) {
      const effects::GrainParams p = grain.evaluate(k.direction, k.frame);
      VDFX_FUZZ_CHECK(std::isfinite(p.intensity) && std::isfinite(p.size));
    }
  }
  return 0;
}
