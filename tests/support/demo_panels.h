/// @file
/// @brief Demo editor panels built only from ui/ widgets, with synthetic thumbnails and fields:
/// an effect panel and a timeline panel. The golden images, the interaction tests and the
/// render benchmark (tests/bench/ui_bench.cpp) all draw these: test support (the library
/// `vdfx_test_support`), never part of ui/ itself.
#pragma once

#include <memory>
#include <opencv2/core.hpp>

#include "ui/panel.h"

namespace vdfx::ui::demo {

/// DejaVu Sans from FontSet::kDefaultFontDir, loaded once per process.
std::shared_ptr<const FontSet> demo_fonts();

/// 1000 x 1000 px, 0.25 x 0.25 m: title, menu of the six effects, exposure slider, undo/redo,
/// a world-lock toggle.
std::unique_ptr<Panel> make_effect_panel();
/// 2000 x 1200 px, 0.5 x 0.3 m: play/pause, timeline strip with thumbnails and keyframes,
/// a plot of exposure over time and a minimap of it over the sphere.
std::unique_ptr<Panel> make_timeline_panel();

/// A deterministic synthetic "video frame" (BGR), different per index.
cv::Mat synthetic_frame(int index, int width, int height);

}  // namespace vdfx::ui::demo
