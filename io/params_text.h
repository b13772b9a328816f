/// @file
/// @brief The "effects" object of `vdfx eval` (and of the web player's module) written straight
/// to text: the bytes nlohmann::json's compact dump() makes of the same object (numbers in the
/// same shortest round-trip form), without building one. At 2000 views building and freeing
/// those objects cost vdfx eval more than evaluating the views.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "effects/effect_types.h"

namespace vdfx::effects {
class StackInterpolator;
}

namespace vdfx::io {

/// A number as nlohmann::json's dump() writes it ("1.0", "0.1", "1e-07"; "null" when not
/// finite).
void append_json_number(std::string& out, double v);
void append_json_integer(std::string& out, std::int64_t v);
/// A string without characters JSON must escape (names, keys), quoted.
void append_json_name(std::string& out, std::string_view s);

/// Every stack effect's parameters under its name, in the contract's order, each with
/// "active" (it has keyframes): {"blur":{"sigma_deg":0.0,"active":false},...}.
void append_stack_params_json(std::string& out, const effects::StackInterpolator& stack,
                              const effects::StackParams& params);

}  // namespace vdfx::io
