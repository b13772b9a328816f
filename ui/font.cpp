/// @file
/// @brief stb_truetype wrapper of font.h; the one translation unit that compiles stb_truetype.
#include "ui/font.h"

#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <unordered_map>

#include "ui/utf8.h"

#define STB_TRUETYPE_IMPLEMENTATION
#define STBTT_STATIC
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wcast-qual"
#endif
#include <stb/stb_truetype.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace vdfx::ui {

namespace {
constexpr int kSubpixelSteps = 4;

struct SizeCache {
  float scale = 0.f;
  std::unordered_map<std::int64_t, GlyphBitmap> bitmaps;  // key: glyph * steps + subpixel
};
}  // namespace

struct Font::Impl {
  std::vector<unsigned char> data;
  stbtt_fontinfo info{};
  int ascent = 0, descent = 0, line_gap = 0;  // font units
  int fallback = 0;
  mutable std::map<int, SizeCache> sizes;

  SizeCache& size(int px) const {
    auto [it, inserted] = sizes.try_emplace(px);
    if (inserted) it->second.scale = stbtt_ScaleForPixelHeight(&info, static_cast<float>(px));
    return it->second;
  }
};

Font::Font(std::string path) : path_(std::move(path)), impl_(std::make_unique<Impl>()) {}
Font::~Font() = default;

std::shared_ptr<Font> Font::load(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::runtime_error("font file " + path +
                             " cannot be opened (install fonts-dejavu-core or pass a font "
                             "directory)");
  std::shared_ptr<Font> font(new Font(path));
  Impl& im = *font->impl_;
  im.data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  const int offset = stbtt_GetFontOffsetForIndex(im.data.data(), 0);
  if (im.data.empty() || offset < 0 || !stbtt_InitFont(&im.info, im.data.data(), offset))
    throw std::runtime_error("font file " + path + " is not a TrueType font");
  stbtt_GetFontVMetrics(&im.info, &im.ascent, &im.descent, &im.line_gap);
  im.fallback = stbtt_FindGlyphIndex(&im.info, '?');
  return font;
}

FontMetrics Font::metrics(int px) const {
  const float s = impl_->size(px).scale;
  return {impl_->ascent * s, -impl_->descent * s, impl_->line_gap * s};
}

int Font::glyph_index(char32_t cp) const {
  const int g = stbtt_FindGlyphIndex(&impl_->info, static_cast<int>(cp));
  return g != 0 ? g : impl_->fallback;
}

bool Font::has_glyph(char32_t cp) const {
  return stbtt_FindGlyphIndex(&impl_->info, static_cast<int>(cp)) != 0;
}

LineLayout Font::layout(std::u32string_view text, int px) const {
  const float s = impl_->size(px).scale;
  LineLayout out;
  out.glyphs.reserve(text.size());
  double pen = 0.0;
  int prev = -1;
  for (char32_t cp : text) {
    const int g = glyph_index(cp);
    if (prev >= 0) pen += s * stbtt_GetGlyphKernAdvance(&impl_->info, prev, g);
    out.glyphs.push_back({g, pen});
    int advance = 0, lsb = 0;
    stbtt_GetGlyphHMetrics(&impl_->info, g, &advance, &lsb);
    pen += s * advance;
    prev = g;
  }
  out.width = pen;
  return out;
}

double Font::measure(std::string_view utf8, int px) const {
  return layout(decode_utf8(utf8), px).width;
}

const GlyphBitmap& Font::glyph(int glyph, int px, int subpixel) const {
  SizeCache& sc = impl_->size(px);
  const std::int64_t key = static_cast<std::int64_t>(glyph) * kSubpixelSteps + subpixel;
  auto it = sc.bitmaps.find(key);
  if (it != sc.bitmaps.end()) return it->second;
  GlyphBitmap bm;
  const float shift = static_cast<float>(subpixel) / kSubpixelSteps;
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  stbtt_GetGlyphBitmapBoxSubpixel(&impl_->info, glyph, sc.scale, sc.scale, shift, 0.f, &x0, &y0,
                                  &x1, &y1);
  bm.width = x1 - x0;
  bm.height = y1 - y0;
  bm.left = x0;
  bm.top = y0;
  if (bm.width > 0 && bm.height > 0) {
    bm.coverage.assign(static_cast<size_t>(bm.width) * bm.height, 0);
    stbtt_MakeGlyphBitmapSubpixel(&impl_->info, bm.coverage.data(), bm.width, bm.height, bm.width,
                                  sc.scale, sc.scale, shift, 0.f, glyph);
  }
  return sc.bitmaps.emplace(key, std::move(bm)).first->second;
}

size_t Font::cached_glyphs() const {
  size_t n = 0;
  for (const auto& [px, sc] : impl_->sizes) n += sc.bitmaps.size();
  return n;
}

FontSet FontSet::load(const std::string& dir) {
  return {Font::load(dir + "/DejaVuSans.ttf"), Font::load(dir + "/DejaVuSans-Bold.ttf")};
}

}  // namespace vdfx::ui
