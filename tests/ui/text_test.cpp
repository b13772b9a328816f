/// @file
/// @brief UTF-8 decoding, font loading errors, measurement, kerning, ellipsis, glyph cache.
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>

#include "sample_panels.h"
#include "ui/canvas.h"
#include "ui/font.h"
#include "ui/theme.h"
#include "ui/utf8.h"

namespace vdfx::ui::test {
namespace {

struct Utf8Case {
  const char* name;
  std::string bytes;
  std::u32string expected;
};
// gtest prints the case by its name, not as a dump of its bytes.
void PrintTo(const Utf8Case& c, std::ostream* os) {
  *os << c.name;
}

const Utf8Case kUtf8Cases[] = {
    {"ascii", "az 09", U"az 09"},
    {"latin1", "\xc3\xa9\xc3\xbc\xc3\x9f", U"\u00e9\u00fc\u00df"},
    {"degree", "45\xc2\xb0", U"45\u00b0"},
    {"arrows", "\xe2\x86\x90\xe2\x86\x92", U"\u2190\u2192"},
    {"four_bytes", "\xf0\x9f\x98\x80", U"\U0001F600"},
    {"lone_continuation",
     "a\x80"
     "b",
     U"a\uFFFDb"},
    {"truncated", "a\xe2\x86", U"a\uFFFD\uFFFD"},
    {"overlong", "\xc0\xaf", U"\uFFFD\uFFFD"},
    {"surrogate", "\xed\xa0\x80", U"\uFFFD\uFFFD\uFFFD"},
};

class Utf8 : public ::testing::TestWithParam<Utf8Case> {};
TEST_P(Utf8, Decodes) {
  EXPECT_EQ(decode_utf8(GetParam().bytes), GetParam().expected);
}
INSTANTIATE_TEST_SUITE_P(Table, Utf8, ::testing::ValuesIn(kUtf8Cases),
                         [](const auto& i) { return std::string(i.param.name); });

TEST(Utf8, EncodeRoundTrips) {
  for (char32_t cp : {U'A', U'\u00b0', U'\u2192', U'\U0001F600'})
    EXPECT_EQ(decode_utf8(encode_utf8(cp)), std::u32string(1, cp));
}

TEST(Font, MissingFileNamesThePath) {
  try {
    Font::load("/nonexistent/dir/NoSuchFont.ttf");
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/NoSuchFont.ttf"), std::string::npos);
  }
  EXPECT_THROW(FontSet::load("/nonexistent/dir"), std::runtime_error);
}

TEST(Font, HasTheSymbolsLabelsUse) {
  const Font& f = *test_fonts()->regular;
  for (char32_t cp :
       {U'\u00b0', U'\u2190', U'\u2192', U'\u00e9', U'\u00d7', U'\u03c3', U'\u2026', U'\u2014'})
    EXPECT_TRUE(f.has_glyph(cp)) << static_cast<unsigned>(cp);
}

TEST(Font, MetricsAndMeasureScaleWithSize) {
  const Font& f = *test_fonts()->regular;
  const FontMetrics m = f.metrics(40);
  EXPECT_NEAR(m.ascent + m.descent, 40.0, 1e-3);
  const double w20 = f.measure("Exposure", 20), w40 = f.measure("Exposure", 40);
  EXPECT_GT(w20, 0.0);
  EXPECT_NEAR(w40 / w20, 2.0, 1e-9);
  EXPECT_GT(f.measure("Exposure +1", 40), w40);
}

TEST(Font, KerningTightensAV) {
  const Font& f = *test_fonts()->regular;
  EXPECT_LT(f.measure("AV", 40), f.measure("A", 40) + f.measure("V", 40) - 0.5);
}

TEST(Font, EllipsisFitsTheWidth) {
  const Font& f = *test_fonts()->regular;
  const std::string text = "Vignette radius and falloff";
  EXPECT_EQ(fit_text(f, 40, text, 1e6), text);
  for (double width : {100.0, 200.0, 300.0}) {
    const std::string s = fit_text(f, 40, text, width);
    EXPECT_LE(f.measure(s, 40), width);
    EXPECT_EQ(s.substr(s.size() - 3), "\u2026");
    EXPECT_EQ(text.rfind(s.substr(0, s.size() - 3), 0), 0u) << s;  // a prefix of the text
  }
}

TEST(Font, GlyphCacheIsReused) {
  auto fonts = FontSet::load();
  Canvas c(400, 80);
  c.text(*fonts.regular, 40, "Hello", {0, 0, 400, 80}, Align::Left, Theme::dark().text);
  const size_t n = fonts.regular->cached_glyphs();
  EXPECT_GT(n, 0u);
  c.text(*fonts.regular, 40, "Hello", {0, 0, 400, 80}, Align::Left, Theme::dark().text);
  EXPECT_EQ(fonts.regular->cached_glyphs(), n);
}

TEST(Text, ClippedToItsBox) {
  Canvas c(400, 100);
  const Rect box{50, 20, 120, 60};
  c.text(*test_fonts()->regular, 40, "WWWWWWWWWWWW", box, Align::Left, {1, 1, 1, 1});
  int inside = 0;
  for (int y = 0; y < c.height(); ++y)
    for (int x = 0; x < c.width(); ++x) {
      const int a = c.image().at<cv::Vec4b>(y, x)[3];
      if (!box.contains({x + 0.5, y + 0.5}))
        ASSERT_EQ(a, 0) << x << "," << y;
      else
        inside += a > 0;
    }
  EXPECT_GT(inside, 200);
}

// Legibility: the smallest text is at least 0.8 degrees tall at arm's length (0.6 m) on panels
// drawn at kPixelsPerMetre.
TEST(Theme, SmallestTextSubtendsEnoughAtArmsLength) {
  const double metres = Theme::dark().font_small / kPixelsPerMetre;
  const double degrees = 2.0 * std::atan(0.5 * metres / 0.6) * 180.0 / 3.14159265358979;
  EXPECT_GE(degrees, 0.8);
}

}  // namespace
}  // namespace vdfx::ui::test
