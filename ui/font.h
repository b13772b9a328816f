/// @file
/// @brief TrueType fonts rasterised with stb_truetype, with a glyph cache per pixel size.
///
/// Glyphs are rasterised on first use at a quarter-pixel horizontal offset (4 buckets) and kept
/// per (pixel size, glyph, offset); kerning comes from the font's GPOS/kern tables. A Font is
/// not thread-safe (its caches fill lazily): panels are drawn on one thread.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace vdfx::ui {

/// One rasterised glyph: an 8-bit coverage bitmap placed relative to the pen on the baseline.
struct GlyphBitmap {
  int width = 0, height = 0;
  int left = 0;  //!< x of the bitmap's first column relative to the (integer) pen position
  int top = 0;   //!< y of the bitmap's first row relative to the baseline (negative = above)
  std::vector<std::uint8_t> coverage;  //!< width * height, row-major
};

/// A glyph placed on a line: index into the font and pen x (pixels from the line start).
struct PlacedGlyph {
  int glyph = 0;
  double x = 0.0;
};

struct LineLayout {
  std::vector<PlacedGlyph> glyphs;
  double width = 0.0;  //!< advance width of the whole line, kerning included
};

struct FontMetrics {
  double ascent = 0.0;   //!< pixels above the baseline
  double descent = 0.0;  //!< pixels below the baseline (positive)
  double line_gap = 0.0;
};

class Font {
 public:
  /// Loads a TrueType file; throws std::runtime_error naming the path when it is missing or is
  /// not a font.
  static std::shared_ptr<Font> load(const std::string& path);
  ~Font();
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;

  const std::string& path() const { return path_; }
  /// Metrics at a pixel height (ascent + descent == px).
  FontMetrics metrics(int px) const;
  /// Glyph index of a code point, or of '?' when the font lacks it.
  int glyph_index(char32_t cp) const;
  bool has_glyph(char32_t cp) const;
  /// Lays out one line of decoded text: advances plus pairwise kerning.
  LineLayout layout(std::u32string_view text, int px) const;
  /// Width of UTF-8 text in pixels at px.
  double measure(std::string_view utf8, int px) const;
  /// Cached bitmap of a glyph at px, rasterised at horizontal offset subpixel/4 pixel.
  const GlyphBitmap& glyph(int glyph, int px, int subpixel) const;
  /// Number of glyph bitmaps rasterised so far (the cache's size; tests check reuse).
  size_t cached_glyphs() const;

 private:
  struct Impl;
  explicit Font(std::string path);
  std::string path_;
  std::unique_ptr<Impl> impl_;
};

/// The toolkit's two faces.
struct FontSet {
  std::shared_ptr<Font> regular;
  std::shared_ptr<Font> bold;

  /// DejaVu Sans and DejaVu Sans Bold from dir (fonts-dejavu-core puts them in
  /// /usr/share/fonts/truetype/dejavu). Throws naming the missing file.
  static FontSet load(const std::string& dir = kDefaultFontDir);
  static constexpr const char* kDefaultFontDir = "/usr/share/fonts/truetype/dejavu";
};

}  // namespace vdfx::ui
