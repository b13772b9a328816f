/// @file
/// @brief Parsing JSON text into nlohmann::json with places for every error (line, column or
/// JSON pointer), including what nlohmann alone would hide: duplicate keys (it keeps the last).
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace vdfx::io {

struct JsonTextError {
  std::size_t line = 0;    //!< 1-based; 0 when the error is given by `pointer` instead
  std::size_t column = 0;  //!< 1-based, in bytes
  std::string pointer;     //!< JSON pointer of the offending member (duplicate keys)
  std::string message;
  int code = 0;  //!< nlohmann's error id (1xx syntax, 406 number overflow); 0: vdfx's own check
  /// "line L, column C", or the pointer when there is no line.
  std::string place() const;
};

struct JsonText {
  nlohmann::json value;               //!< discarded (is_discarded()) when the syntax is broken
  std::vector<JsonTextError> errors;  //!< empty when the text is valid and has no duplicate keys
};

/// Parses `text`. Syntax errors and numbers that overflow a double (1e400) stop the parse and
/// give a line and column; duplicate keys are reported with their pointer and the parse goes on.
JsonText parse_json_text(std::string_view text);

/// Escapes one reference token for a JSON pointer (RFC 6901: "~" -> "~0", "/" -> "~1").
std::string json_pointer_token(std::string_view key);

}  // namespace vdfx::io
