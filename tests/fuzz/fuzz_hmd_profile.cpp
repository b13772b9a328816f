/// @file
/// @brief Fuzz target: the HMD profile reader (xr::parse_hmd_profile_text). Properties: a bad
/// profile is io::InputError and nothing else; a good one has finite values in their documented
/// ranges and a lens model that inverts at the centre of each eye.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_check.h"
#include "io/input_error.h"
#include "xr/headset/hmd_profile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace vdfx;
  xr::HmdProfile p;
  try {
    p = xr::parse_hmd_profile_text(std::string_view(reinterpret_cast<const char*>(data), size),
                                   "fuzz.json");
  } catch (const io::InputError&) {
    return 0;
  }
  VDFX_FUZZ_CHECK(std::isfinite(p.refresh_hz) && p.refresh_hz > 0.0);
  VDFX_FUZZ_CHECK(std::isfinite(p.ipd_m) && p.ipd_m > 0.0);
  for (const xr::Eye e : xr::kEyes) {
    const xr::EyeProfile& ep = p.eye(e);
    VDFX_FUZZ_CHECK(ep.width >= 1 && ep.width <= 16384 && ep.height >= 1 && ep.height <= 16384);
    const effects::EyeLens lens = p.eye_lens(e);
    const auto centre =
        lens.lens.panel_to_view(Eigen::Vector2d(0.0, 0.0), 1, effects::InverseMethod::Newton);
    VDFX_FUZZ_CHECK(centre && std::isfinite(centre->x()) && std::isfinite(centre->y()));
  }
  return 0;
}
