/// @file
/// @brief The demo panels of demo_panels.h.
#include "tests/support/demo_panels.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "ui/button.h"
#include "ui/menu_list.h"
#include "ui/minimap.h"
#include "ui/plot.h"
#include "ui/slider.h"
#include "ui/timeline_strip.h"

namespace vdfx::ui::demo {

std::shared_ptr<const FontSet> demo_fonts() {
  static const auto fonts = std::make_shared<const FontSet>(FontSet::load());
  return fonts;
}

cv::Mat synthetic_frame(int index, int width, int height) {
  // Sky over ground with a sun whose position moves with the index.
  cv::Mat img(height, width, CV_8UC3);
  for (int y = 0; y < height; ++y) {
    const double t = static_cast<double>(y) / height;
    const cv::Vec3b c =
        t < 0.55 ? cv::Vec3b(static_cast<uchar>(230 - 90 * t), static_cast<uchar>(170 - 60 * t),
                             static_cast<uchar>(90 + 40 * t))
                 : cv::Vec3b(50, static_cast<uchar>(110 - 40 * t), 70);
    img.row(y).setTo(c);
  }
  const int sx = (width * (1 + index * 2)) / 16 % width;
  cv::circle(img, {sx, height / 4}, height / 8, cv::Scalar(120, 230, 255), cv::FILLED, cv::LINE_AA);
  return img;
}

std::unique_ptr<Panel> make_effect_panel() {
  auto p = std::make_unique<Panel>("effects", 1000, 1000, glm::dvec2(0.25, 0.25), demo_fonts());
  const Theme& t = p->theme();
  Stack col(Rect{0, 0, 1000, 1000}.inset(40.0), t.gap);
  p->add<Label>("title", "Effects", Label::Role::Title).set_rect(col.next(64));
  p->add<MenuList>(
       "effect_menu",
       std::vector<std::string>{"Blur", "Tint", "Exposure", "Saturation", "Contrast", "Vignette"},
       2, t.row_height)
      .set_rect(col.next(6 * t.row_height + 16));
  p->add<Slider1D>("exposure", "Exposure", Axis{-8.0, 8.0, 0.1, "%+.1f", " stops", ""}, 1.5, 0.0)
      .set_rect(col.next(140));
  const Rect row = col.next(t.row_height);
  p->add<Button>("undo", "\u2190 Undo").set_rect(split_cols(row, 2, 0, t.gap));
  p->add<Button>("redo", "Redo \u2192").set_rect(split_cols(row, 2, 1, t.gap));
  p->add<Toggle>("world_lock", "Lock panel in world", false).set_rect(col.next(t.row_height));
  return p;
}

std::unique_ptr<Panel> make_timeline_panel() {
  auto p = std::make_unique<Panel>("timeline", 2000, 1200, glm::dvec2(0.5, 0.3), demo_fonts());
  const Theme& t = p->theme();
  constexpr int kFrames = 240;
  const std::vector<int> keys = {0, 48, 120, 200};
  const int playhead = 120;
  Stack col(Rect{0, 0, 2000, 1200}.inset(40.0), t.gap);
  Stack top(col.next(t.row_height), t.gap, Stack::Axis::Horizontal);
  p->add<Button>("play", "", Icon::Play).set_rect(top.next(120));
  p->add<Button>("pause", "", Icon::Pause).set_rect(top.next(120));
  p->add<Label>("title", "Timeline \u2014 Exposure", Label::Role::Title).set_rect(top.next(900));
  p->add<Label>("time", "00:04.00 / 00:08.00  (30 fps)", Label::Role::Body, Align::Right, true)
      .set_rect(top.rest());
  auto& strip = p->add<TimelineStrip>("strip", kFrames);
  strip.set_rect(col.next(300));
  std::vector<cv::Mat> thumbs;
  for (int i = 0; i < 8; ++i) thumbs.push_back(synthetic_frame(i, 320, 180));
  strip.set_thumbnails(std::move(thumbs));
  strip.set_keyframes(keys);
  strip.set_playhead(playhead);
  const Rect bottom = col.rest();
  auto& plot = p->add<Plot>("exposure_plot", "Exposure (stops) over time", -2.0, 2.0, "%+.0f");
  plot.set_rect({bottom.x, bottom.y, 1160, bottom.h});
  std::vector<double> values(kFrames);
  for (int f = 0; f < kFrames; ++f) values[static_cast<size_t>(f)] = 1.5 * std::sin(f / 38.0);
  plot.set_values(values);
  plot.set_keyframes(keys);
  plot.set_playhead(playhead);
  auto& map = p->add<Minimap>("exposure_map", "Exposure over the sphere");
  map.set_rect({bottom.x + 1160 + t.gap, bottom.y, bottom.w - 1160 - t.gap, bottom.h});
  cv::Mat field(128, 256, CV_32FC1);
  for (int y = 0; y < field.rows; ++y)
    for (int x = 0; x < field.cols; ++x)
      field.at<float>(y, x) =
          static_cast<float>(1.5 * std::cos((x - 96) / 40.0) * std::cos((y - 64) / 45.0));
  map.set_field(field, -2.0, 2.0);
  map.set_keyframes({{-45.0, 10.0}, {0.0, 0.0}, {60.0, -20.0}, {150.0, 30.0}}, 1);
  map.set_view({20.0, 5.0}, 90.0, 80.0);
  return p;
}

}  // namespace vdfx::ui::demo
