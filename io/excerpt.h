/// @file
/// @brief User-supplied text fit for a one-line message: cut to a few dozen bytes (a 10 MB number
/// made a 10 MB error line) and with control bytes spelled out (a NUL byte is "\x00").
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace vdfx::io {

/// The longest excerpt of user text a message quotes.
inline constexpr std::size_t kExcerptBytes = 64;

/// `text` with control bytes as \xNN; when longer than `max` bytes, its first `max` bytes (never
/// cutting a UTF-8 sequence) then "... (N bytes)".
std::string excerpt(std::string_view text, std::size_t max = kExcerptBytes);

/// A library's message with the part between its first and last single quote (where nlohmann
/// puts the text it read) passed through excerpt().
std::string excerpt_quoted(std::string_view message, std::size_t max = kExcerptBytes);

}  // namespace vdfx::io
