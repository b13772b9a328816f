/// @file
/// @brief Names of the blur methods.
#include "xr/render/blur_method.h"

namespace vdfx::xr {

std::string_view blur_method_name(BlurMethod m) {
  return m == BlurMethod::Exact ? "exact" : "pyramid";
}

std::optional<BlurMethod> blur_method_from_name(std::string_view name) {
  if (name == "exact") return BlurMethod::Exact;
  if (name == "pyramid") return BlurMethod::Pyramid;
  return std::nullopt;
}

}  // namespace vdfx::xr
