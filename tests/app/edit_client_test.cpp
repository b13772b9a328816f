/// @file
/// @brief EditorClient without GL: panel uploads follow panel renders, quads sit at the panel
/// poses, unaltered passes through, the parameters carry the trigger's preview.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "app/window/editor_client.h"
#include "editor_test_util.h"
#include "effects/effect_shaders.h"

namespace vdfx::app {
namespace {

using effects::EffectType;

// Keeps what a GL texture would hold, per slot.
struct FakeTextures : PanelTextures {
  struct Call {
    std::size_t slot;
    bool whole;
    std::vector<cv::Rect> regions;
  };
  std::vector<Call> calls;         //!< panel uploads (pointer marks are uploaded once, apart)
  std::vector<std::size_t> marks;  //!< slots of the pointer marks' textures
  std::map<std::size_t, cv::Mat> images;
  unsigned upload(std::size_t slot, const cv::Mat& image,
                  const std::vector<cv::Rect>& regions) override {
    if (slot >= 1000)
      marks.push_back(slot);
    else
      calls.push_back({slot, regions.empty(), regions});
    if (regions.empty()) {
      images[slot] = image.clone();
    } else {
      for (const auto& r : regions) image(r).copyTo(images[slot](r));
    }
    return static_cast<unsigned>(100 + slot);
  }
};

EditorOptions desktop() {
  EditorOptions o;
  o.layout = PanelLayout::Desktop;
  return o;
}

struct Fixture {
  Editor editor{test::empty_sidecar(), DocumentOptions{{.async = false}}, desktop()};
  FakeTextures* fake = new FakeTextures;
  EditorClient client{editor, std::unique_ptr<PanelTextures>(fake)};
  FrameInfo info;
  xr::ActionSync sync;  //!< the edges InputBackend::poll would add
  void step(const xr::InputState& in) { client.update(sync.sync(in), in.t_ns, info); }
};

// What the GL texture must show: the panel's own pixels (premultiplied, first row at the top).
cv::Mat expected_texture(ui::Panel& p) {
  return p.texture();
}

// The panels the client draws: the shown ones (the track marker is hidden until there is a track).
std::vector<ui::Panel*> shown_panels(Editor& editor) {
  std::vector<ui::Panel*> shown;
  for (ui::Panel* p : editor.panels())
    if (p->visible()) shown.push_back(p);
  return shown;
}

// The client's slot of a panel (its texture is 100 + slot): its place among all the editor's
// panels, the hidden ones included.
std::size_t slot_of(Editor& editor, const ui::Panel* panel) {
  const auto all = editor.panels();
  return static_cast<std::size_t>(std::find(all.begin(), all.end(), panel) - all.begin());
}

TEST(EditClient, QuadsAtPanelPosesUploadOnlyWhenPanelsRerender) {
  Fixture f;
  f.step(test::looking(10.0, 5.0, 0));
  const auto q1 = f.client.quads();
  const auto panels = shown_panels(f.editor);
  // The panels, then the pointer's marks (their textures made once).
  ASSERT_EQ(q1.size(), panels.size() + f.client.pointer_quads().size());
  ASSERT_EQ(f.fake->calls.size(), panels.size());
  EXPECT_EQ(f.fake->marks.size(), 3u);
  for (std::size_t i = 0; i < panels.size(); ++i) {
    EXPECT_TRUE(f.fake->calls[i].whole);
    EXPECT_EQ(q1[i].space, xr::ReferenceSpace::Local);
    EXPECT_EQ(q1[i].pose, panels[i]->pose());
    EXPECT_DOUBLE_EQ(q1[i].size_m.x(), panels[i]->size_m().x);
    EXPECT_DOUBLE_EQ(q1[i].size_m.y(), panels[i]->size_m().y);
    EXPECT_EQ(q1[i].texture, 100 + slot_of(f.editor, panels[i]));
  }
  // Uploads follow renders: one per panel whose render count moved, none without a render.
  const auto renders = [&] {
    int n = 0;
    for (ui::Panel* p : panels) n += p->render_count();
    return n;
  };
  f.step(test::looking(10.0, 5.0, 33'333'333));
  const int r0 = renders();
  f.client.quads();
  EXPECT_EQ(f.fake->calls.size() - panels.size(), static_cast<std::size_t>(renders() - r0));
  const std::size_t settled = f.fake->calls.size();
  f.client.quads();
  f.client.quads();
  EXPECT_EQ(f.fake->calls.size(), settled) << "no render, no upload";

  // Another effect: the effect panel re-renders, and only its damage goes up.
  f.editor.select_effect(EffectType::Tint);
  f.step(test::looking(10.0, 5.0, 66'666'666));
  f.client.quads();
  ASSERT_GT(f.fake->calls.size(), settled);
  for (std::size_t k = settled; k < f.fake->calls.size(); ++k) {
    EXPECT_FALSE(f.fake->calls[k].whole);
    EXPECT_FALSE(f.fake->calls[k].regions.empty());
  }
  // Whole or partial, the texture equals the panel's image.
  for (std::size_t i = 0; i < panels.size(); ++i)
    EXPECT_EQ(cv::norm(f.fake->images[slot_of(f.editor, panels[i])], expected_texture(*panels[i]),
                       cv::NORM_INF),
              0.0)
        << i;
}

TEST(EditClient, PanelRenderedElsewhereIsUploadedWhole) {
  Fixture f;
  f.step(test::looking(0.0, 0.0, 0));
  f.client.quads();
  const std::size_t n = f.fake->calls.size();
  f.editor.select_effect(EffectType::Vignette);
  f.step(test::looking(0.0, 0.0, 1));
  for (ui::Panel* p : f.editor.panels()) p->texture();  // someone else renders (replay overlay)
  f.client.quads();
  ASSERT_GT(f.fake->calls.size(), n);
  const auto& last = f.fake->calls.back();
  ASSERT_EQ(last.regions.size(), 1u);
  EXPECT_EQ(last.regions[0].area(), f.fake->images[last.slot].total()) << "the whole panel";
  const auto panels = shown_panels(f.editor);
  for (std::size_t i = 0; i < panels.size(); ++i)
    EXPECT_EQ(cv::norm(f.fake->images[slot_of(f.editor, panels[i])], expected_texture(*panels[i]),
                       cv::NORM_INF),
              0.0)
        << i;
}

TEST(EditClient, UnalteredPassesThrough) {
  Fixture f;
  xr::InputState in = test::looking(0.0, 0.0, 0);
  f.step(in);
  EXPECT_FALSE(f.client.unaltered());
  in.right.secondary = true;  // b held
  in.t_ns = 1;
  f.step(in);
  EXPECT_TRUE(f.client.unaltered());
  in.right.secondary = false;
  in.t_ns = 2;
  f.step(in);
  EXPECT_FALSE(f.client.unaltered());
}

TEST(EditClient, ParamsCarryThePreviewAndRevisionFollowsEdits) {
  Fixture f;
  xr::InputState in = test::looking(20.0, 0.0, 0);
  f.step(in);
  EXPECT_EQ(f.client.active_effects(), 0u);
  const std::uint64_t r0 = f.client.params_revision();
  f.editor.set_chosen_params({2.0});  // exposure +2
  in.right.trigger = 1.0;             // aim straight up: on no panel -> preview
  in.t_ns = 1;
  f.step(in);
  ASSERT_TRUE(f.editor.previewing());
  EXPECT_EQ(f.client.active_effects(), effects::shader_bit(EffectType::Exposure));
  EXPECT_NE(f.client.params_revision(), r0);
  EXPECT_DOUBLE_EQ(f.client.params(f.editor.view_direction(), f.editor.frame()).exposure_stops,
                   2.0);
  // Turning the head while previewing moves the preview: a new revision.
  const std::uint64_t r1 = f.client.params_revision();
  in = test::looking(40.0, 0.0, 2);
  in.right.trigger = 1.0;
  f.step(in);
  EXPECT_NE(f.client.params_revision(), r1);
  EXPECT_DOUBLE_EQ(f.client.params(f.editor.view_direction(), f.editor.frame()).exposure_stops,
                   2.0);
  // Release: placed; the effect stays compiled in because it now has a keyframe.
  in.right.trigger = 0.0;
  in.t_ns = 3;
  f.step(in);
  EXPECT_FALSE(f.editor.previewing());
  EXPECT_EQ(f.editor.document().keyframes(EffectType::Exposure).size(), 1u);
  EXPECT_EQ(f.client.active_effects(), effects::shader_bit(EffectType::Exposure));
  // Nothing changes: the revision stays.
  const std::uint64_t r2 = f.client.params_revision();
  in.t_ns = 4;
  f.step(in);
  EXPECT_EQ(f.client.params_revision(), r2);
  EXPECT_TRUE(f.editor.undo());
  in.t_ns = 5;
  f.step(in);
  EXPECT_NE(f.client.params_revision(), r2);
  EXPECT_EQ(f.client.active_effects(), 0u);
}

TEST(EditClient, PlayheadReachesTheLoop) {
  Fixture f;
  f.step(test::looking(0.0, 0.0, 0));
  EXPECT_EQ(f.info.video_frame, 0);
  EXPECT_TRUE(f.info.video_paused);
  f.editor.seek(42);
  f.step(test::looking(0.0, 0.0, 1));
  EXPECT_EQ(f.info.video_frame, 42);
  EXPECT_NE(f.client.status_line().find("42"), std::string::npos);
}

}  // namespace
}  // namespace vdfx::app
