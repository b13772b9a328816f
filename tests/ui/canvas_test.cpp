/// @file
/// @brief Canvas coverage, premultiplication, clipping, images; theme contrast; colour maths.
#include "ui/canvas.h"

#include <gtest/gtest.h>

#include <numbers>

#include "ui/colour.h"
#include "ui/colour_wheel.h"
#include "ui/theme.h"

namespace vdfx::ui {
namespace {

double alpha_sum(const Canvas& c) {
  double s = 0;
  for (int y = 0; y < c.height(); ++y)
    for (int x = 0; x < c.width(); ++x) s += c.image().at<cv::Vec4b>(y, x)[3] / 255.0;
  return s;
}

TEST(Canvas, DiscCoverageMatchesArea) {
  for (double r : {5.3, 12.0, 30.7}) {
    Canvas c(80, 80);
    c.fill_circle({40.2, 39.7}, r, {1, 1, 1, 1});
    EXPECT_NEAR(alpha_sum(c), std::numbers::pi * r * r, 0.01 * std::numbers::pi * r * r + 2.0);
  }
}

TEST(Canvas, RoundedRectCoverageMatchesArea) {
  Canvas c(120, 80);
  const double w = 90.5, h = 50.25, r = 12.0;
  c.fill_rounded_rect({10, 10, w, h}, r, {0, 1, 0, 1});
  const double area = w * h - (4.0 - std::numbers::pi) * r * r;
  EXPECT_NEAR(alpha_sum(c), area, 0.01 * area);
  EXPECT_EQ(c.image().at<cv::Vec4b>(35, 50), cv::Vec4b(0, 255, 0, 255));
  EXPECT_EQ(c.image().at<cv::Vec4b>(11, 11)[3], 0);  // cut corner
}

TEST(Canvas, StoresPremultipliedAndComposites) {
  Canvas c(10, 10);
  c.fill_rect({0, 0, 10, 10}, {1.f, 0.5f, 0.f, 0.5f});
  EXPECT_EQ(c.image().at<cv::Vec4b>(5, 5), cv::Vec4b(128, 64, 0, 128));
  c.fill_rect({0, 0, 10, 10}, {0.f, 0.f, 1.f, 1.f});  // opaque over anything is itself
  EXPECT_EQ(c.image().at<cv::Vec4b>(5, 5), cv::Vec4b(0, 0, 255, 255));
  const cv::Mat straight = c.to_straight_rgba();
  EXPECT_EQ(straight.at<cv::Vec4b>(5, 5), cv::Vec4b(0, 0, 255, 255));
}

TEST(Canvas, ClipStackLimitsDrawing) {
  Canvas c(40, 40);
  c.push_clip({10, 10, 20, 20});
  c.push_clip({0, 0, 15, 40});
  c.fill_rect({0, 0, 40, 40}, {1, 1, 1, 1});
  c.pop_clip();
  c.pop_clip();
  EXPECT_DOUBLE_EQ(alpha_sum(c), 5.0 * 20.0);
  EXPECT_THROW(c.pop_clip(), std::logic_error);
}

TEST(Canvas, PolylineJointsAreNotDoubleBlended) {
  Canvas c(60, 60);
  const glm::dvec2 pts[] = {{10, 30}, {30, 30}, {30, 50}};
  c.polyline(pts, 6.0, {1, 1, 1, 0.5f});
  // The joint pixel is covered by both segments but blended once.
  EXPECT_EQ(c.image().at<cv::Vec4b>(30, 30)[3], 128);
}

TEST(Canvas, ImageBlitScalesAndSwapsChannels) {
  cv::Mat bgr(2, 2, CV_8UC3, cv::Scalar(255, 0, 0));  // blue in OpenCV's BGR
  Canvas c(20, 20);
  c.image(bgr, {4, 4, 8, 8}, ChannelOrder::Bgr);
  EXPECT_EQ(c.image().at<cv::Vec4b>(8, 8), cv::Vec4b(0, 0, 255, 255));
  EXPECT_EQ(c.image().at<cv::Vec4b>(2, 2)[3], 0);
  EXPECT_EQ(c.image().at<cv::Vec4b>(11, 11)[3], 255);
  EXPECT_EQ(c.image().at<cv::Vec4b>(12, 12)[3], 0);
}

// WCAG 2 contrast >= 4.5:1 for every text/background pair, with the translucent panel seen
// over black and over white video.
TEST(Theme, TextContrastMeetsWcagAA) {
  const Theme& t = Theme::dark();
  const Rgba backdrops[] = {Rgba::hex(0x000000), Rgba::hex(0xffffff)};
  struct Pair {
    const char* name;
    Rgba fg, bg;
  };
  const Pair pairs[] = {
      {"text/surface", t.text, t.surface},         {"text/hover", t.text, t.surface_hover},
      {"text/pressed", t.text, t.surface_pressed}, {"text/selection", t.text, t.selection},
      {"muted/surface", t.text_muted, t.surface},  {"muted/hover", t.text_muted, t.surface_hover},
  };
  for (const Rgba& back : backdrops) {
    const Rgba panel = over(t.panel_bg, back);
    EXPECT_GE(contrast_ratio(t.text, panel), 4.5);
    EXPECT_GE(contrast_ratio(t.text_muted, panel), 4.5);
    for (const Pair& p : pairs) EXPECT_GE(contrast_ratio(p.fg, over(p.bg, panel)), 4.5) << p.name;
  }
}

TEST(Colour, ContrastRatioKnownValues) {
  EXPECT_NEAR(contrast_ratio(Rgba::hex(0x000000), Rgba::hex(0xffffff)), 21.0, 1e-9);
  EXPECT_NEAR(contrast_ratio(Rgba::hex(0x777777), Rgba::hex(0xffffff)), 4.48, 0.01);
}

struct TintCase {
  double hue, sat;
};
const TintCase kTintCases[] = {{0, 0}, {0, 1}, {60, 0.5}, {120, 1}, {200, 0.6}, {300, 0.25}};

TEST(ColourWheel, TintGainIsNormalisedAndRoundTrips) {
  for (const auto& c : kTintCases) {
    const Eigen::Vector3d g = tint_gain_from_hue_sat(c.hue, c.sat);
    EXPECT_NEAR(0.25 * g.x() + 0.5 * g.y() + 0.25 * g.z(), 1.0, 1e-12);
    const glm::dvec2 hs = hue_sat_from_tint_gain(g);
    EXPECT_NEAR(hs.y, c.sat, 1e-6);  // hsv() works in float
    if (c.sat > 0) {
      EXPECT_NEAR(hs.x, c.hue, 1e-4);
    }
  }
  EXPECT_TRUE(tint_gain_from_hue_sat(123, 0).isApprox(Eigen::Vector3d::Ones()));
}

TEST(ColourWheel, DragMapsAngleToHueAndRadiusToSaturation) {
  ColourWheel w("w", "Tint");
  w.set_rect({0, 0, 800, 500});
  const glm::dvec2 c = w.disc_centre();
  const double r = w.disc_radius();
  w.drag_to(c + glm::dvec2(0.0, -0.5 * r));  // straight up on screen: 90 deg
  EXPECT_NEAR(w.hue(), 90.0, 1e-9);
  EXPECT_NEAR(w.sat(), 0.5, 1e-9);
  w.drag_to(c + glm::dvec2(-3.0 * r, 0.0));  // beyond the rim: clamps
  EXPECT_NEAR(w.hue(), 180.0, 1e-9);
  EXPECT_DOUBLE_EQ(w.sat(), 1.0);
}

}  // namespace
}  // namespace vdfx::ui
