/// @file
/// @brief Panels rendered at a scale (ui::Panel::set_render_scale): the texture has the scaled
/// size, text is rasterised at the scaled font size (so it is as tall on the texture as the
/// font size times the scale, not a blurred shrink of the full-size text), and hit testing stays
/// in layout pixels.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "sample_panels.h"
#include "ui/button.h"
#include "ui/canvas.h"
#include "ui/font.h"
#include "ui/theme.h"

namespace vdfx::ui::test {
namespace {

/// Rows of a texture region holding bright (text) pixels: the ink height of a line of text.
int ink_rows(const cv::Mat& premultiplied, const Rect& r) {
  const cv::Rect box(static_cast<int>(r.x), static_cast<int>(r.y), static_cast<int>(r.w),
                     static_cast<int>(r.h));
  cv::Mat grey;
  cv::cvtColor(premultiplied(box), grey, cv::COLOR_RGBA2GRAY);
  int first = -1, last = -1;
  for (int y = 0; y < grey.rows; ++y) {
    double v = 0.0;
    cv::minMaxLoc(grey.row(y), nullptr, &v);
    if (v > 160.0) {
      if (first < 0) first = y;
      last = y;
    }
  }
  return first < 0 ? 0 : last - first + 1;
}

TEST(RenderScale, TextIsRasterisedAtTheScaledSize) {
  const auto fonts = std::make_shared<const FontSet>(FontSet::load());
  const auto make = [&](double scale) {
    auto p = std::make_unique<Panel>("p", 600, 200, glm::dvec2(0.15, 0.05), fonts);
    p->add<Label>("l", "HHHH", Label::Role::Title).set_rect({20, 40, 560, 120});
    p->set_render_scale(scale);
    return p;
  };
  auto full = make(1.0), small = make(0.4);
  const cv::Mat& a = full->texture();
  const cv::Mat& b = small->texture();
  EXPECT_EQ(b.cols, 240);
  EXPECT_EQ(b.rows, 80);
  // DejaVu's capital H is 0.63 of the font's pixel height (ascent + descent): 48 px -> 30
  // rows; at scale 0.4 the font is rasterised at 19 px -> 12 rows.
  const int ha = ink_rows(a, {20, 40, 560, 120}), hb = ink_rows(b, {8, 16, 224, 48});
  const int title = Theme::dark().font_title;
  EXPECT_NEAR(ha, 0.63 * title, 1.5);
  EXPECT_NEAR(hb, 0.63 * std::lround(title * 0.4), 1.0);
  // Crisp: the scaled text has as many fully-inked stem pixels per row as a sharp rasterisation
  // (a shrink of the full-size texture would smear them into grey).
  cv::Mat grey;
  cv::cvtColor(b, grey, cv::COLOR_RGBA2GRAY);
  EXPECT_GT(cv::countNonZero(grey > 230), 4 * 2 * hb);  // two stems per H, four Hs, every row
}

TEST(RenderScale, HitTestingStaysInLayoutPixels) {
  auto p = make_effect_panel();
  const Rect undo = p->find("undo")->rect();
  p->set_render_scale(0.4);
  EXPECT_EQ(p->widget_at(undo.centre()), p->find("undo"));
  EXPECT_EQ(p->texture().cols, static_cast<int>(std::lround(p->width_px() * 0.4)));
  // Damage comes back in texture pixels.
  p->texture();
  p->find("undo")->set_hovered(true);
  const auto rects = p->dirty_rects();
  ASSERT_EQ(rects.size(), 1u);
  EXPECT_LE(rects[0].right(), 0.4 * (undo.right() + Widget::kPaintMargin) + 1.0);
  EXPECT_GE(rects[0].x, 0.4 * (undo.x - Widget::kPaintMargin) - 1.0);
}

}  // namespace
}  // namespace vdfx::ui::test
