/// @file
/// @brief Golden images of every widget kind and of the two mock editor panels.
/// Bless new goldens with: VDFX_BLESS=1 ./build/tests/vdfx_test_ui --gtest_filter='Golden*'
#include "golden.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <ostream>

#include "sample_panels.h"
#include "ui/button.h"
#include "ui/colour_wheel.h"
#include "ui/menu_list.h"
#include "ui/minimap.h"
#include "ui/plot.h"
#include "ui/slider.h"
#include "ui/timeline_strip.h"

namespace vdfx::ui::test {
namespace {

// stb_truetype and the canvas are deterministic integer/float code: only libm differences
// (pow in colour maps, atan2 in the wheel) could move a pixel, and then by a step or two.
constexpr double kMaxTolerance = 3.0;
constexpr double kMeanTolerance = 0.05;

std::unique_ptr<Panel> panel(int w, int h) {
  return std::make_unique<Panel>("golden", w, h, glm::dvec2(w, h) / kPixelsPerMetre, test_fonts());
}

std::unique_ptr<Panel> buttons() {
  auto p = panel(1000, 440);
  const char* names[] = {"normal", "hover", "pressed", "focused", "disabled"};
  Stack col(Rect{0, 0, 1000, 440}.inset(32.0), 16.0);
  Rect row = col.next(76);
  for (int i = 0; i < 3; ++i) {
    auto& b = p->add<Button>(names[i], names[i] == std::string("normal") ? "Normal" : names[i]);
    b.set_rect(split_cols(row, 3, i, 16.0));
    b.set_hovered(i == 1);
    b.set_pressed(i == 2);
  }
  row = col.next(76);
  auto& f = p->add<Button>("focused", "Focused \u2192");
  f.set_rect(split_cols(row, 3, 0, 16.0));
  f.set_focused(true);
  auto& d = p->add<Button>("disabled", "Disabled");
  d.set_rect(split_cols(row, 3, 1, 16.0));
  d.set_enabled(false);
  p->add<Button>("play", "Play", Icon::Play).set_rect(split_cols(row, 3, 2, 16.0));
  p->add<Toggle>("on", "Toggle on", true).set_rect(col.next(76));
  p->add<Toggle>("off", "Toggle off", false).set_rect(col.next(76));
  return p;
}

std::unique_ptr<Panel> labels() {
  auto p = panel(1000, 380);
  Stack col(Rect{0, 0, 1000, 380}.inset(32.0), 8.0);
  p->add<Label>("t", "Title 48 px bold", Label::Role::Title).set_rect(col.next(64));
  p->add<Label>("b", "Body 40 px: azimuth 45° ← → é ü ß ±0.5", Label::Role::Body)
      .set_rect(col.next(56));
  p->add<Label>("s", "Small 34 px muted: the smallest text", Label::Role::Small, Align::Left, true)
      .set_rect(col.next(50));
  p->add<Label>("r", "Right aligned", Label::Role::Body, Align::Right).set_rect(col.next(56));
  p->add<Label>("e", "A label far too long for its box gets an ellipsis at the end",
                Label::Role::Body)
      .set_rect(col.next(56));
  return p;
}

std::unique_ptr<Panel> sliders() {
  auto p = panel(1000, 340);
  Stack col(Rect{0, 0, 1000, 340}.inset(32.0), 16.0);
  auto& a =
      p->add<Slider1D>("exposure", "Exposure", Axis{-8, 8, 0.1, "%+.1f", " stops", ""}, -2.5, 0.0);
  a.set_rect(col.next(130));
  auto& b = p->add<Slider1D>("blur", "Blur σ", Axis{0, 10, 0.1, "%.1f", "°", ""}, 6.0, 0.0);
  b.set_rect(col.next(130));
  b.set_focused(true);
  b.set_hovered(true);
  return p;
}

std::unique_ptr<Panel> pad() {
  auto p = panel(700, 760);
  auto& w = p->add<Pad2D>("vignette", "Vignette", Axis{0, 180, 1, "%.0f", "°", "radius"},
                          Axis{0.01, 180, 1, "%.0f", "°", "falloff"}, glm::dvec2(90, 30));
  w.set_rect(Rect{0, 0, 700, 760}.inset(32.0));
  return p;
}

std::unique_ptr<Panel> wheel() {
  auto p = panel(800, 520);
  auto& w = p->add<ColourWheel>("tint", "Tint", 200.0, 0.6);
  w.set_rect(Rect{0, 0, 800, 520}.inset(32.0));
  return p;
}

std::unique_ptr<Panel> menu() {
  auto p = panel(700, 500);
  auto& m = p->add<MenuList>("menu",
                             std::vector<std::string>{"Blur", "Tint", "Exposure", "Saturation",
                                                      "Contrast", "Vignette", "Grain", "Flare"},
                             4, 76.0);
  m.set_rect(Rect{0, 0, 700, 500}.inset(32.0));
  m.set_focused(true);
  return p;
}

std::unique_ptr<Panel> timeline() {
  auto p = panel(1600, 420);
  auto& s = p->add<TimelineStrip>("strip", 100);
  s.set_rect(Rect{0, 0, 1600, 420}.inset(32.0));
  std::vector<cv::Mat> thumbs;
  for (int i = 0; i < 6; ++i) thumbs.push_back(synthetic_frame(i, 240, 135));
  s.set_thumbnails(std::move(thumbs));
  s.set_keyframes({5, 30, 62, 90});
  s.set_highlighted({90});
  s.set_playhead(30);
  return p;
}

std::unique_ptr<Panel> plot() {
  auto p = panel(1200, 520);
  auto& w = p->add<Plot>("plot", "Saturation over time", 0.0, 2.0, "%.1f");
  w.set_rect(Rect{0, 0, 1200, 520}.inset(32.0));
  std::vector<double> v(60);
  for (size_t i = 0; i < v.size(); ++i) v[i] = 1.0 + 0.8 * std::sin(static_cast<double>(i) / 7.0);
  w.set_values(v);
  w.set_keyframes({0, 22, 44});
  w.set_playhead(22);
  return p;
}

std::unique_ptr<Panel> minimap() {
  auto p = panel(900, 560);
  auto& m = p->add<Minimap>("map", "Blur over the sphere");
  m.set_rect(Rect{0, 0, 900, 560}.inset(32.0));
  cv::Mat field(90, 180, CV_32FC1);
  for (int y = 0; y < field.rows; ++y)
    for (int x = 0; x < field.cols; ++x)
      field.at<float>(y, x) = static_cast<float>(x + y) / 270.0f * 10.0f;
  m.set_field(field, 0.0, 10.0);
  m.set_keyframes({{-120.0, 20.0}, {10.0, -10.0}, {170.0, 0.0}}, 2);
  m.set_view({170.0, 0.0}, 100.0, 90.0);  // straddles the +-180 seam
  return p;
}

struct GoldenCase {
  const char* name;
  std::function<std::unique_ptr<Panel>()> make;
};
// gtest prints the case by its name, not as a dump of its bytes.
void PrintTo(const GoldenCase& c, std::ostream* os) {
  *os << c.name;
}

const GoldenCase kCases[] = {
    {"buttons", buttons},
    {"labels", labels},
    {"sliders", sliders},
    {"pad2d", pad},
    {"colour_wheel", wheel},
    {"menu_list", menu},
    {"timeline_strip", timeline},
    {"plot", plot},
    {"minimap", minimap},
    {"effect_panel", make_effect_panel},
    {"timeline_panel", make_timeline_panel},
};

class Golden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, MatchesCommittedImage) {
  auto p = GetParam().make();
  const cv::Mat& tex = p->texture();
  ASSERT_EQ(tex.type(), CV_8UC4);
  EXPECT_EQ(compare_with_golden(tex, GetParam().name, kMaxTolerance, kMeanTolerance), "");
}

INSTANTIATE_TEST_SUITE_P(Widgets, Golden, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

// The comparison itself must catch a change: one widget value moved is a failure.
TEST(GoldenCompare, DetectsAChangedWidget) {
  if (std::getenv("VDFX_BLESS")) return;  // comparing would overwrite the golden
  auto p = make_effect_panel();
  p->find_as<Slider1D>("exposure")->set_value(-6.0);
  const std::string msg =
      compare_with_golden(p->texture(), "effect_panel", kMaxTolerance, kMeanTolerance);
  EXPECT_NE(msg.find("max difference"), std::string::npos) << msg;
}

}  // namespace
}  // namespace vdfx::ui::test
