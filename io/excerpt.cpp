/// @file
/// @brief excerpt and excerpt_quoted.
#include "io/excerpt.h"

#include <cstdio>

namespace vdfx::io {

std::string excerpt(std::string_view text, std::size_t max) {
  std::size_t keep = text.size();
  if (keep > max) {
    keep = max;
    // Back off to the start of a UTF-8 sequence (continuation bytes are 10xxxxxx).
    while (keep > 0 && (static_cast<unsigned char>(text[keep]) & 0xC0) == 0x80) --keep;
  }
  std::string out;
  for (std::size_t i = 0; i < keep; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c == 0x7F) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  if (keep < text.size()) out += "... (" + std::to_string(text.size()) + " bytes)";
  return out;
}

std::string excerpt_quoted(std::string_view message, std::size_t max) {
  const std::size_t open = message.find('\'');
  const std::size_t close = message.rfind('\'');
  if (open == std::string_view::npos || close <= open) return excerpt(message, 4 * max);
  return std::string(message.substr(0, open + 1)) +
         excerpt(message.substr(open + 1, close - open - 1), max) +
         std::string(message.substr(close));
}

}  // namespace vdfx::io
