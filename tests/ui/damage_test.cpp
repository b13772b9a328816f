/// @file
/// @brief Damage tracking: which rectangles a change dirties, and that a partial re-render gives
/// exactly the pixels of a full render of the same state.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <ostream>

#include "sample_panels.h"
#include "ui/button.h"
#include "ui/canvas.h"
#include "ui/menu_list.h"
#include "ui/minimap.h"
#include "ui/plot.h"
#include "ui/slider.h"
#include "ui/theme.h"
#include "ui/timeline_strip.h"

namespace vdfx::ui::test {
namespace {

/// Largest per-channel difference between two premultiplied textures.
double max_diff(const cv::Mat& a, const cv::Mat& b) {
  return cv::norm(a, b, cv::NORM_INF);
}

Rect whole_pixels(const Rect& r, int w, int h) {
  const double x0 = std::floor(r.x), y0 = std::floor(r.y);
  return Rect{x0, y0, std::ceil(r.right()) - x0, std::ceil(r.bottom()) - y0}.intersect(
      {0, 0, static_cast<double>(w), static_cast<double>(h)});
}

struct DamageCase {
  const char* name;
  std::function<std::unique_ptr<Panel>()> make;
  /// Changes applied one after the other; the incremental panel renders after each.
  std::vector<std::function<void(Panel&)>> steps;
};
// gtest prints the case by its name, not as a dump of its bytes.
void PrintTo(const DamageCase& c, std::ostream* os) {
  *os << c.name;
}

void hover(Panel& p, const char* id, bool on) {
  p.find(id)->set_hovered(on);
}

/// What the editor does every video frame while playing: the strip and the plot follow.
void playhead(Panel& p, int frame) {
  p.find_as<TimelineStrip>("strip")->set_playhead(frame);
  p.find_as<Plot>("exposure_plot")->set_playhead(frame);
}

const DamageCase kDamageCases[] = {
    {"HoverButton", make_effect_panel, {[](Panel& p) { hover(p, "undo", true); }}},
    {"HoverMovesToNeighbour",
     make_effect_panel,
     {[](Panel& p) { hover(p, "undo", true); },
      [](Panel& p) { hover(p, "undo", false), hover(p, "redo", true); }}},
    {"MenuRowHover", make_effect_panel, {[](Panel& p) {
       auto& m = *p.find("effect_menu");
       m.set_hovered(true);
       m.hover_at({m.rect().x + 50, m.rect().y + 40});
     }}},
    {"MenuHoverMovesDownTwoRows",  // the second step redraws just the two rows' bands
     make_effect_panel,
     {[](Panel& p) {
        auto& m = *p.find("effect_menu");
        m.set_hovered(true);
        m.hover_at({m.rect().x + 50, m.rect().y + 40});
      },
      [](Panel& p) {
        auto& m = *p.find("effect_menu");
        m.hover_at({m.rect().x + 50, m.rect().y + 40 + 2 * Theme::dark().row_height});
      }}},
    {"SliderDragAndFocus", make_effect_panel, {[](Panel& p) {
       auto& s = *p.find_as<Slider1D>("exposure");
       s.set_pressed(true), s.set_focused(true), s.set_value(-7.3);
     }}},
    {"ToggleClick", make_effect_panel, {[](Panel& p) {
       p.find_as<Toggle>("world_lock")->set_on(true);
     }}},
    {"LabelMoves",  // the old place must be wiped, the new one drawn
     make_effect_panel,
     {[](Panel& p) {
       p.find("title")->set_rect({300, 40, 500, 64});
     }}},
    {"StripPlayheadAndFocusRing",  // the ring reaches 6.5 px above the strip's rect
     make_timeline_panel,
     {[](Panel& p) {
       auto& s = *p.find_as<TimelineStrip>("strip");
       s.set_playhead(31), s.set_focused(true);
     }}},
    {"NewMinimapFieldAndThumbnails",  // cached scaled images must follow new content
     make_timeline_panel,
     {[](Panel& p) {
        p.find_as<Minimap>("exposure_map")->set_field(cv::Mat(64, 128, CV_32FC1, 0.7f), -1, 1);
      },
      [](Panel& p) {
        std::vector<cv::Mat> thumbs;
        for (int i = 0; i < 8; ++i) thumbs.push_back(synthetic_frame(i + 5, 320, 180));
        p.find_as<TimelineStrip>("strip")->set_thumbnails(std::move(thumbs));
      }}},
    {"PlaybackStepsOverKeyframesAndTheEnds",  // diamonds and dots at the playhead grow and shrink
     make_timeline_panel,
     {[](Panel& p) { playhead(p, 121); }, [](Panel& p) { playhead(p, 199); },
      [](Panel& p) { playhead(p, 200); }, [](Panel& p) { playhead(p, 201); },
      [](Panel& p) { playhead(p, 0); }, [](Panel& p) { playhead(p, 1); },
      [](Panel& p) { playhead(p, 239); }, [](Panel& p) { playhead(p, 9); },
      [](Panel& p) { playhead(p, 10); }, [](Panel& p) { playhead(p, 99); },
      [](Panel& p) { playhead(p, 100); }, [](Panel& p) { playhead(p, 48); }}},
    {"PlaybackWhileStripFocusedAndPressed",
     make_timeline_panel,
     {[](Panel& p) { p.find("strip")->set_focused(true), p.find("strip")->set_pressed(true); },
      [](Panel& p) { playhead(p, 121); }, [](Panel& p) { playhead(p, 122); }}},
    {"PlotPlayhead",
     make_timeline_panel,
     {[](Panel& p) { p.find_as<Plot>("exposure_plot")->set_playhead(200); },
      [](Panel& p) { hover(p, "play", true); }}},
};

/// A partial re-render after each step gives exactly the pixels of a full render of the final
/// state, at a render scale (1: the panel's own pixels; 0.4: a desktop panel's on-screen size).
void check_partial_equals_full(const DamageCase& c, double scale) {
  const auto make = [&] {
    auto p = c.make();
    p->set_render_scale(scale);
    return p;
  };
  auto incremental = make();
  incremental->texture();
  for (const auto& step : c.steps) {
    step(*incremental);
    ASSERT_TRUE(incremental->dirty());
    EXPECT_TRUE(incremental->render_if_dirty());
  }
  EXPECT_EQ(incremental->full_render_count(), 1) << "the changes should have rendered partially";
  EXPECT_EQ(incremental->render_count(), 1 + static_cast<int>(c.steps.size()));

  auto fresh = make();
  for (const auto& step : c.steps) step(*fresh);
  const cv::Mat& full = fresh->texture();
  EXPECT_EQ(fresh->full_render_count(), 1);
  EXPECT_EQ(full.cols, static_cast<int>(std::lround(fresh->width_px() * scale)));
  EXPECT_EQ(max_diff(incremental->texture(), full), 0.0);
}

class PartialRender : public ::testing::TestWithParam<DamageCase> {};

TEST_P(PartialRender, EqualsFullRenderOfTheSameState) {
  check_partial_equals_full(GetParam(), 1.0);
}
TEST_P(PartialRender, EqualsFullRenderAtADesktopRenderScale) {
  check_partial_equals_full(GetParam(), 0.4);
}

INSTANTIATE_TEST_SUITE_P(Panels, PartialRender, ::testing::ValuesIn(kDamageCases),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(Damage, HoverDirtiesOnlyThatWidgetsPaintBounds) {
  auto p = make_effect_panel();
  p->texture();
  EXPECT_TRUE(p->dirty_rects().empty());
  Widget& undo = *p->find("undo");
  undo.set_hovered(true);
  const std::vector<Rect> rects = p->dirty_rects();
  ASSERT_EQ(rects.size(), 1u);
  EXPECT_EQ(rects[0], whole_pixels(undo.paint_bounds(), 1000, 1000));
  EXPECT_TRUE(rects[0].intersect(p->find("redo")->rect()).empty());
  EXPECT_LT(rects[0].w * rects[0].h, 0.1 * 1000 * 1000);
}

TEST(Damage, MenuHoverRowChangeDirtiesOnlyTheTwoRows) {
  auto p = make_effect_panel();
  auto& m = *p->find("effect_menu");
  const Rect r = m.rect();
  const double row = Theme::dark().row_height;
  m.set_hovered(true);
  m.hover_at({r.x + 50, r.y + 40});
  p->texture();
  m.hover_at({r.x + 50, r.y + 40 + row});  // next row down: two adjacent bands
  const std::vector<Rect> rects = p->dirty_rects();
  ASSERT_EQ(rects.size(), 1u);
  EXPECT_LE(rects[0].h, 2 * row + 4);
  EXPECT_GE(rects[0].h, 2 * row);
  EXPECT_LT(rects[0].h, 0.5 * r.h);
  EXPECT_GE(rects[0].y, r.y);
}

TEST(Damage, PlaybackStepDirtiesOnlyThePlayheadColumns) {
  auto p = make_timeline_panel();
  p->texture();
  const auto& strip = *p->find_as<TimelineStrip>("strip");
  const auto& plot = *p->find_as<Plot>("exposure_plot");
  for (const int f : {121, 122, 199, 200, 201}) {  // 200 holds a keyframe
    if (f == 199) {  // jump there first: a jump may damage the span between
      playhead(*p, 198);
      p->render_if_dirty();
    }
    playhead(*p, f);
    const auto rects = p->dirty_rects();
    ASSERT_EQ(rects.size(), 2u) << f;  // one box on the strip, one on the plot
    double area = 0.0;
    for (const Rect& r : rects) {
      area += r.w * r.h;
      EXPECT_LT(r.w, 200.0) << f << ": " << r.x << "," << r.y << " " << r.w << "x"
                            << r.h;  // a column (label included), not the widget's width
    }
    // They sit over the new playhead on each widget.
    const Rect a = plot.plot_area();
    const double plot_x = a.x + a.w * f / 239.0;
    const glm::dvec2 on_strip{strip.x_of(f), strip.rect().centre().y},
        on_plot{plot_x, a.centre().y};
    EXPECT_TRUE(rects[0].contains(on_strip) || rects[1].contains(on_strip)) << f;
    EXPECT_TRUE(rects[0].contains(on_plot) || rects[1].contains(on_plot)) << f;
    EXPECT_LT(area, 0.05 * 2000 * 1200) << f;  // a full redraw is all of it
    EXPECT_TRUE(rects[0].intersect(p->find("exposure_map")->rect()).empty());
    EXPECT_TRUE(rects[1].intersect(p->find("exposure_map")->rect()).empty());
    p->render_if_dirty();
  }
  EXPECT_EQ(p->full_render_count(), 1);
}

TEST(Damage, TwoWidgetsFarApartGiveTwoRectangles) {
  auto p = make_effect_panel();
  p->texture();
  p->find("title")->set_rect({40, 40, 400, 64});  // same place? no: narrower
  p->find_as<Toggle>("world_lock")->set_on(true);
  const std::vector<Rect> rects = p->dirty_rects();
  ASSERT_EQ(rects.size(), 2u);
  EXPECT_TRUE(rects[0].intersect(rects[1]).empty());
}

TEST(Damage, AddingAWidgetOrMarkDirtyRendersEverything) {
  auto p = make_effect_panel();
  p->texture();
  p->mark_dirty();
  ASSERT_EQ(p->dirty_rects().size(), 1u);
  EXPECT_EQ(p->dirty_rects()[0], (Rect{0, 0, 1000, 1000}));
  p->texture();
  EXPECT_EQ(p->full_render_count(), 2);
  p->add<Label>("extra", "Extra").set_rect({40, 900, 300, 50});
  p->texture();
  EXPECT_EQ(p->full_render_count(), 3);
}

TEST(Damage, PartialRenderOffMakesEveryRenderFull) {
  auto p = make_effect_panel();
  p->set_partial_render(false);
  p->texture();
  p->find("undo")->set_hovered(true);
  EXPECT_EQ(p->dirty_rects().size(), 1u);
  EXPECT_EQ(p->dirty_rects()[0], (Rect{0, 0, 1000, 1000}));
  p->texture();
  EXPECT_EQ(p->full_render_count(), 2);
}

TEST(Damage, ATextureHeldByTheCallerDoesNotChange) {
  auto p = make_effect_panel();
  const cv::Mat kept = p->texture();  // a header copy shares the pixels
  const cv::Mat before = kept.clone();
  p->find("undo")->set_hovered(true);
  const cv::Mat& after = p->texture();
  EXPECT_EQ(max_diff(kept, before), 0.0);
  EXPECT_GT(max_diff(after, before), 0.0);
  EXPECT_EQ(p->full_render_count(), 1);
}

TEST(CanvasClearRect, SetsOnlyPixelCentresInsideRectAndClip) {
  Canvas c(8, 6);
  c.clear({1, 1, 1, 1});
  c.push_clip({0, 0, 5, 6});
  c.clear_rect({2.4, 1.6, 4.0, 2.0},
               {0, 0, 0, 0});  // centres x 2.5..4.5 (the clip ends at 5), y 2.5..3.5
  c.pop_clip();
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 8; ++x) {
      const bool cleared = x >= 2 && x <= 4 && y >= 2 && y <= 3;
      EXPECT_EQ(c.image().at<cv::Vec4b>(y, x)[3], cleared ? 0 : 255) << x << "," << y;
    }
}

}  // namespace
}  // namespace vdfx::ui::test
