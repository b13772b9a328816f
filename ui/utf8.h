/// @file
/// @brief UTF-8 decoding for labels (degree sign, arrows, Latin-1 and beyond).
#pragma once

#include <string>
#include <string_view>

namespace vdfx::ui {

inline constexpr char32_t kReplacementChar = 0xFFFD;

/// Decodes UTF-8; malformed, overlong or surrogate sequences become U+FFFD, one per bad byte.
std::u32string decode_utf8(std::string_view s);
/// Encodes one code point (used by tests and for building labels from code points).
std::string encode_utf8(char32_t cp);

}  // namespace vdfx::ui
