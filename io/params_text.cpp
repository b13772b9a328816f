/// @file
/// @brief The eval JSON written as text, number by number as nlohmann::json writes them.
#include "io/params_text.h"

#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <utility>
#include <vector>

#include "effects/stack_interpolator.h"

namespace vdfx::io {

void append_json_number(std::string& out, double v) {
  if (!std::isfinite(v)) {
    out += "null";
    return;
  }
  // nlohmann's own formatter (Grisu2, shortest round trip, its exponent and ".0" rules): the
  // text stays byte for byte what dump() gave before.
  char buf[64];
  const char* end = nlohmann::detail::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, static_cast<std::size_t>(end - buf));
}

void append_json_integer(std::string& out, std::int64_t v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, static_cast<std::size_t>(r.ptr - buf));
}

void append_json_name(std::string& out, std::string_view s) {
  out += '"';
  out += s;
  out += '"';
}

void append_stack_params_json(std::string& out, const effects::StackInterpolator& stack,
                              const effects::StackParams& params) {
  out += '{';
  bool first_effect = true;
  for (const effects::EffectSpec& spec : effects::all_effect_specs()) {
    if (!std::exchange(first_effect, false)) out += ',';
    append_json_name(out, spec.name);
    out += ":{";
    const std::vector<double> values = params.get(spec.type);
    std::size_t offset = 0;
    for (const effects::ParamSpec& ps : spec.params) {
      append_json_name(out, ps.name);
      out += ':';
      const auto at = [&](std::size_t i) {
        return offset + i < values.size() ? values[offset + i] : ps.neutral;
      };
      if (ps.size == 1) {
        append_json_number(out, at(0));
      } else {
        out += '[';
        for (int i = 0; i < ps.size; ++i) {
          if (i) out += ',';
          append_json_number(out, at(static_cast<std::size_t>(i)));
        }
        out += ']';
      }
      out += ',';
      offset += static_cast<std::size_t>(ps.size);
    }
    out += stack.active(spec.type) ? "\"active\":true}" : "\"active\":false}";
  }
  out += '}';
}

}  // namespace vdfx::io
