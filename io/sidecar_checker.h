/// @file
/// @brief The sidecar reader's field checks, shared by the format-1 reader
/// (io/sidecar_validate.cpp) and the readers of the extension types (io/sidecar_flare.cpp): every
/// problem is collected with the file, a JSON pointer and what is wrong, in one wording.
/// Internal to io/.
#pragma once

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "effects/effect_types.h"
#include "effects/keyframe.h"
#include "io/excerpt.h"
#include "io/json_text.h"
#include "io/sidecar_validate.h"

namespace vdfx::io::detail {

using nlohmann::json;

/// A number for messages: integral values without ".0", others in shortest round-trip form.
inline std::string num(double v) {
  if (v == std::floor(v) && std::abs(v) < 1e15) return std::to_string(static_cast<long long>(v));
  return json(v).dump();
}

inline const char* type_name(const json& v) {
  if (v.is_number_integer()) return "integer";
  if (v.is_number_float()) return "number";
  return v.type_name();
}

struct Range {
  double lo;
  double hi;
  bool lo_open;
  bool hi_open;
  bool contains(double v) const {
    return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
  std::string text() const {
    return std::string(lo_open ? "(" : "[") + num(lo) + ", " + num(hi) + (hi_open ? ")" : "]");
  }
};

class Checker {
 public:
  Checker(std::string file, std::vector<Problem>& out) : file_(std::move(file)), out_(out) {}

  void error(const std::string& ptr, std::string msg) {
    out_.push_back({file_, ptr, std::move(msg)});
  }
  /// Problems reported so far (a reader compares counts to know whether a part was fine).
  std::size_t problems() const { return out_.size(); }

  /// The object at `ptr`, or null (reported) when `v` is not an object.
  const json* object(const json& v, const std::string& ptr) {
    if (v.is_object()) return &v;
    error(ptr, std::string("expected an object, found ") + type_name(v));
    return nullptr;
  }

  /// Reports every key that is not in `known` (a reader must never silently drop data).
  void only_keys(const json& obj, const std::string& ptr,
                 std::initializer_list<const char*> known) {
    only_keys_in(obj, ptr, known);
  }
  void only_keys(const json& obj, const std::string& ptr, const std::vector<std::string>& known) {
    only_keys_in(obj, ptr, known);
  }
  template <class Names>
  void only_keys_in(const json& obj, const std::string& ptr, const Names& known) {
    for (const auto& [k, v] : obj.items()) {
      bool ok = false;
      for (const auto& n : known) ok = ok || k == n;
      if (!ok) {
        std::string list;
        for (const auto& n : known) list += std::string(list.empty() ? "" : ", ") + n;
        error(ptr + "/" + excerpt(json_pointer_token(k)),
              "unknown field \"" + excerpt(k) + "\" (expected: " + list + ")");
      }
    }
  }

  /// The member `key` of `obj`; reports it when missing and `required`.
  const json* member(const json& obj, const std::string& ptr, const char* key,
                     bool required = true) {
    const auto it = obj.find(key);
    if (it != obj.end()) return &*it;
    if (required) error(ptr, std::string("missing field \"") + key + "\"");
    return nullptr;
  }

  std::optional<double> number(const json& v, const std::string& ptr, const Range& range) {
    if (!v.is_number()) {
      error(ptr, std::string("expected a number, found ") + type_name(v));
      return std::nullopt;
    }
    const double d = v.get<double>();
    // JSON has no NaN or infinity literal and the parser rejects overflow, but a document built
    // in memory can still hold them.
    if (!std::isfinite(d)) {
      error(ptr, "not a finite number");
      return std::nullopt;
    }
    if (!range.contains(d)) {
      error(ptr, "value " + num(d) + " is out of range " + range.text());
      return std::nullopt;
    }
    return d;
  }

  /// An integer in [lo, hi]. A number with a fractional part is rejected; 75.0 is taken as 75.
  std::optional<std::int64_t> integer(const json& v, const std::string& ptr, std::int64_t lo,
                                      std::int64_t hi, const std::string& range_text) {
    std::int64_t i = 0;
    if (v.is_number_unsigned()) {
      const auto u = v.get<std::uint64_t>();
      if (u > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
        error(ptr, "value " + v.dump() + " is out of range " + range_text);
        return std::nullopt;
      }
      i = static_cast<std::int64_t>(u);
    } else if (v.is_number_integer()) {
      i = v.get<std::int64_t>();
    } else if (v.is_number_float()) {
      const double d = v.get<double>();
      if (!std::isfinite(d)) {
        error(ptr, "not a finite number");
        return std::nullopt;
      }
      if (d != std::floor(d)) {
        error(ptr, "expected an integer, found " + num(d));
        return std::nullopt;
      }
      // 2^63 is exactly representable; anything at or beyond it does not fit.
      if (d < -9223372036854775808.0 || d >= 9223372036854775808.0) {
        error(ptr, "value " + num(d) + " is out of range " + range_text);
        return std::nullopt;
      }
      i = static_cast<std::int64_t>(d);
    } else {
      error(ptr, std::string("expected an integer, found ") + type_name(v));
      return std::nullopt;
    }
    if (i < lo || i > hi) {
      error(ptr, "value " + std::to_string(i) + " is out of range " + range_text);
      return std::nullopt;
    }
    return i;
  }

  std::optional<std::string> string(const json& v, const std::string& ptr) {
    if (v.is_string()) return v.get<std::string>();
    error(ptr, std::string("expected a string, found ") + type_name(v));
    return std::nullopt;
  }

 private:
  std::string file_;
  std::vector<Problem>& out_;
};

/// True when an "effects" entry is an object whose "type" is the string `type` (which reader
/// takes it: the extension types have readers of their own).
inline bool has_type(const json& entry, const char* type) {
  if (!entry.is_object()) return false;
  const auto t = entry.find("type");
  return t != entry.end() && t->is_string() && t->get<std::string>() == type;
}

/// An entry's optional "interpolation" override (format 1's checks): `out` is set when `entry`
/// (at `ptr`) has one, left as it is otherwise.
void read_interpolation_override(Checker& c, const json& entry, const std::string& ptr,
                                 std::optional<effects::InterpolationSettings>& out);

/// False, reported at `ptr`, when an array holds more than kMaxKeyframesPerEffect keyframes (the
/// solver's limit): then they are not read at all, one clear message and no time spent.
bool keyframe_count_ok(Checker& c, const json& keyframes, const std::string& ptr);

/// A keyframe's direction and frame (format 1's checks, frame within [0, frames) when known);
/// its "params" must be an object, whose fields the caller reads.
void read_keyframe_place(Checker& c, const json& v, const std::string& ptr,
                         std::optional<std::int64_t> frames, effects::Keyframe& out);

/// The keyframes of an extension effect (flare, grain), whose params are the scalars `specs`:
/// each required and within its range; each keyframe starts from the specs' neutral values.
void read_scalar_keyframes(Checker& c, const json& v, const std::string& ptr,
                           std::optional<std::int64_t> frames,
                           std::span<const effects::ParamSpec> specs,
                           std::vector<effects::Keyframe>& out);

}  // namespace vdfx::io::detail
