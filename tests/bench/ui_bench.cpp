/// @file
/// @brief CPU canvas and panel rendering: full renders of the two demo panels, a hover-change
/// re-render, a playback step of the demo and of the editor's timeline panel (against a full
/// redraw of the same panel), one text draw, one rounded-rect fill, and the memory-bound peers (a
/// plain copy and a memset of the same 1000 x 1000 RGBA image), all measured in the same run.
///
/// Report CPU-time medians (--benchmark_repetitions=N --benchmark_report_aggregates_only=true):
/// the machine is shared, so wall time is noisy.
#include <benchmark/benchmark.h>

#include <cstring>
#include <opencv2/core.hpp>

#include "app/editor/editor.h"
#include "tests/support/demo_panels.h"
#include "ui/button.h"
#include "ui/canvas.h"
#include "ui/plot.h"
#include "ui/theme.h"
#include "ui/timeline_strip.h"

namespace {

using namespace vdfx::ui;

/// Full renders: mark_dirty() forces the whole panel to be drawn again each iteration.
void BM_EffectPanelFull(benchmark::State& state) {
  auto p = demo::make_effect_panel();
  p->texture();  // glyph cache warm, like every frame after the first
  for (auto _ : state) {
    p->mark_dirty();
    p->render_if_dirty();
    benchmark::DoNotOptimize(p->texture().data);
  }
}
BENCHMARK(BM_EffectPanelFull)->Unit(benchmark::kMillisecond);

void BM_TimelinePanelFull(benchmark::State& state) {
  auto p = demo::make_timeline_panel();
  p->texture();
  for (auto _ : state) {
    p->mark_dirty();
    p->render_if_dirty();
    benchmark::DoNotOptimize(p->texture().data);
  }
}
BENCHMARK(BM_TimelinePanelFull)->Unit(benchmark::kMillisecond);

/// The pointer moves onto a button and off it again: two hover changes and two renders per
/// iteration, so the figure is the cost of ONE hover change times two.
void BM_EffectPanelHoverButton(benchmark::State& state) {
  auto p = demo::make_effect_panel();
  Widget& undo = *p->find("undo");
  p->texture();
  for (auto _ : state) {
    undo.set_hovered(true);
    p->render_if_dirty();
    undo.set_hovered(false);
    p->render_if_dirty();
    benchmark::DoNotOptimize(p->texture().data);
  }
  state.counters["renders_per_iter"] = 2;
}
BENCHMARK(BM_EffectPanelHoverButton)->Unit(benchmark::kMillisecond);

/// The pointer moves between two rows of the effect menu (the largest widget on the panel).
void BM_EffectPanelHoverMenuRow(benchmark::State& state) {
  auto p = demo::make_effect_panel();
  Widget& menu = *p->find("effect_menu");
  const Rect r = menu.rect();
  p->texture();
  menu.set_hovered(true);
  for (auto _ : state) {
    menu.hover_at({r.x + 100, r.y + 30});
    p->render_if_dirty();
    menu.hover_at({r.x + 100, r.y + 110});
    p->render_if_dirty();
    benchmark::DoNotOptimize(p->texture().data);
  }
  state.counters["renders_per_iter"] = 2;
}
BENCHMARK(BM_EffectPanelHoverMenuRow)->Unit(benchmark::kMillisecond);

/// Playback: the playhead moves one frame, on the strip and on the plot (what the editor
/// redraws every video frame while playing).
void BM_TimelinePlayheadStep(benchmark::State& state) {
  auto p = demo::make_timeline_panel();
  auto& strip = *p->find_as<TimelineStrip>("strip");
  auto& plot = *p->find_as<Plot>("exposure_plot");
  p->texture();
  int frame = 0;
  for (auto _ : state) {
    frame = (frame + 1) % 240;
    strip.set_playhead(frame);
    plot.set_playhead(frame);
    p->render_if_dirty();
    benchmark::DoNotOptimize(p->texture().data);
  }
}
BENCHMARK(BM_TimelinePlayheadStep)->Unit(benchmark::kMillisecond);

/// The editor's own timeline panel while playing, head still, nothing else changing: each
/// iteration steps the editor one video frame (not timed) and times the panel's re-render.
/// Arg 0: the full-redraw peer (mark_dirty() first: every pixel drawn, the cost before damage
/// tracking followed the playhead); arg 1: the partial redraw the editor does now. The current
/// effect has no keyframes, so the minimap's field does not change with the frame (with
/// keyframes it does, and the minimap is redrawn as its content changes).
void BM_EditorTimelinePlaying(benchmark::State& state) {
  vdfx::io::Sidecar sc;
  sc.video = {"clip.mp4", 30.0, 900, 3840, 1920};
  vdfx::app::Editor ed(sc, vdfx::app::DocumentOptions{{.async = false}},
                       vdfx::app::EditorOptions{});
  ed.select_effect(vdfx::effects::EffectType::Contrast);
  ed.document().add_keyframe(vdfx::effects::EffectType::Exposure, {{30.0, 0.0}, 100, {1.0}});
  vdfx::xr::InputState in = vdfx::xr::neutral_input_state(0);
  in.head_tracked = true;
  std::int64_t t = 0;
  ed.update(in, t);
  ed.set_playing(true);
  Panel& p = *ed.panel(vdfx::app::kTimelinePanelId);
  p.texture();
  const bool full = state.range(0) == 0;
  for (auto _ : state) {
    state.PauseTiming();
    t += 33'333'334;
    in.t_ns = t;
    ed.update(in, t);
    if (full) p.mark_dirty();
    state.ResumeTiming();
    p.render_if_dirty();
    benchmark::DoNotOptimize(p.texture().data);
  }
  state.counters["full_renders"] = p.full_render_count();
  state.SetLabel(full ? "full redraw (peer)" : "partial: playhead columns, labels");
}
BENCHMARK(BM_EditorTimelinePlaying)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_TextDraw(benchmark::State& state) {
  Canvas c(1000, 100);
  const auto fonts = demo::demo_fonts();
  const Theme& t = Theme::dark();
  c.clear(t.panel_bg);
  for (auto _ : state) {
    c.text(*fonts->regular, t.font_body, "Exposure +1.5 stops", {20, 10, 960, 80}, Align::Left,
           t.text);
    benchmark::DoNotOptimize(c.image().data);
  }
}
BENCHMARK(BM_TextDraw)->Unit(benchmark::kMicrosecond);

/// A 900 x 600 widget surface over the panel background (translucent colour over opaque-ish).
void BM_RoundedRectFill(benchmark::State& state) {
  Canvas c(1000, 1000);
  const Theme& t = Theme::dark();
  c.clear(t.panel_bg);
  for (auto _ : state) {
    c.fill_rounded_rect({50.5, 50.5, 900, 600}, t.corner_radius, t.surface);
    benchmark::DoNotOptimize(c.image().data);
  }
  state.SetBytesProcessed(state.iterations() * 900LL * 600 * 4);
}
BENCHMARK(BM_RoundedRectFill)->Unit(benchmark::kMicrosecond);

/// Peer: copying a whole 1000 x 1000 RGBA image, the memory-bound floor of a full render.
void BM_PeerCopy1000(benchmark::State& state) {
  cv::Mat src(1000, 1000, CV_8UC4, cv::Scalar(20, 23, 29, 230)), dst(1000, 1000, CV_8UC4);
  for (auto _ : state) {
    src.copyTo(dst);
    benchmark::DoNotOptimize(dst.data);
  }
  state.SetBytesProcessed(state.iterations() * 1000LL * 1000 * 4);
}
BENCHMARK(BM_PeerCopy1000)->Unit(benchmark::kMicrosecond);

/// Peer: setting every byte of the same image.
void BM_PeerMemset1000(benchmark::State& state) {
  cv::Mat dst(1000, 1000, CV_8UC4);
  int v = 0;
  for (auto _ : state) {
    std::memset(dst.data, ++v & 0xff, dst.total() * dst.elemSize());
    benchmark::DoNotOptimize(dst.data);
  }
  state.SetBytesProcessed(state.iterations() * 1000LL * 1000 * 4);
}
BENCHMARK(BM_PeerMemset1000)->Unit(benchmark::kMicrosecond);

}  // namespace
