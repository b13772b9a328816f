/// @file
/// @brief While a keyframe is previewed (placement: right trigger on nothing; grab: right
/// squeeze), the minimap field and the effect track are the preview interpolant's, equal to a
/// fresh solve with the preview keyframe, and the document's again after release or undo.
/// Synchronous and with the minimap on the MinimapWorker.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "app/editor/editor.h"
#include "app/editor/visualizations.h"
#include "editor_test_util.h"

namespace vdfx::app {
namespace {

using effects::EffectType;
using effects::Keyframe;

constexpr std::int64_t kFrame = 30;

io::Sidecar thirty_keyframes() {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> az(-170.0, 170.0), alt(-60.0, 60.0), stops(-3.0, 3.0);
  std::uniform_int_distribution<std::int64_t> frame(0, 89);
  std::vector<Keyframe> ks;
  for (int i = 0; i < 30; ++i) ks.push_back({{az(rng), alt(rng)}, frame(rng), {stops(rng)}});
  ks.push_back({{0.0, 0.0}, kFrame, {3.0}});  // the one the head looks at: grabbed
  io::Sidecar sc = test::empty_sidecar(90);
  sc.effects.push_back({EffectType::Exposure, std::nullopt, ks});
  return sc;
}

/// The field and the track (at `view`) of a fresh solve of `keyframes`.
struct Fresh {
  cv::Mat field;
  std::vector<double> track;
};
Fresh fresh(const std::vector<Keyframe>& keyframes, const Editor& ed) {
  const effects::RbfInterpolator rbf(
      keyframes, 1, ed.document().interpolation(EffectType::Exposure), 30.0, {0.0});
  return {effect_minimap(&rbf, EffectType::Exposure, kFrame, 128, 64),
          effect_track(&rbf, EffectType::Exposure, ed.view_direction(), ed.track_frames())};
}

double max_abs(const cv::Mat& a, const cv::Mat& b) {
  return cv::norm(a, b, cv::NORM_INF);
}
double max_abs(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double m = 0.0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

struct Case {
  const char* name;
  bool async;
};
class PreviewVisuals : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override {
    EditorOptions eo;
    eo.visuals.async = GetParam().async;
    ed_ = std::make_unique<Editor>(thirty_keyframes(), DocumentOptions{{.async = false}}, eo);
    ed_->seek(kFrame);
  }
  xr::ActionSync sync_;  //!< the edges InputBackend::poll would add
  /// One frame looking at (az, alt) with the right trigger and squeeze as given.
  void frame(double az, double alt, double trigger, double squeeze) {
    t_ += 33'333'333;
    auto in = test::looking(az, alt, t_);
    in.right.trigger = trigger;
    in.right.squeeze = squeeze;
    ed_->update(sync_.sync(in), t_);
    ASSERT_TRUE(ed_->wait_for_visualizations(std::chrono::seconds(30)));
  }
  /// The editor shows exactly what a fresh solve of the document's keyframes gives.
  void expect_document(const char* when) {
    const Fresh doc = fresh(ed_->document().keyframes(EffectType::Exposure), *ed_);
    EXPECT_LT(max_abs(ed_->minimap_field(), doc.field), 1e-5) << when;
    EXPECT_LT(max_abs(ed_->track_values(), doc.track), 1e-9) << when;
  }
  /// The editor shows a fresh solve of `keyframes`, which differs from the document's.
  void expect_preview(const std::vector<Keyframe>& keyframes, const std::string& when) {
    const Fresh want = fresh(keyframes, *ed_),
                doc = fresh(ed_->document().keyframes(EffectType::Exposure), *ed_);
    EXPECT_LT(max_abs(ed_->minimap_field(), want.field), 1e-5) << when;
    EXPECT_LT(max_abs(ed_->track_values(), want.track), 1e-7) << when;
    EXPECT_GT(max_abs(ed_->minimap_field(), doc.field), 0.1)
        << when << ": the field is not the document's";
    EXPECT_GT(max_abs(ed_->track_values(), doc.track), 0.1)
        << when << ": the track is not the document's";
  }

  std::unique_ptr<Editor> ed_;
  std::int64_t t_ = 0;
};

TEST_P(PreviewVisuals, PlacementPreviewIsShownAndReleaseOrUndoGoBack) {
  ed_->set_chosen_params({-2.5});
  frame(40.0, 10.0, 0.0, 0.0);
  expect_document("before the press");
  const auto doc_keys = ed_->document().keyframes(EffectType::Exposure);
  const cv::Mat before = ed_->minimap_field().clone();
  const std::vector<double> track_before = ed_->track_values();
  for (const double az : {40.0, 47.0, 55.0}) {  // press, then turn the head while placing
    frame(az, 10.0, 1.0, 0.0);
    ASSERT_TRUE(ed_->previewing());
    auto with_new = doc_keys;
    with_new.push_back({ed_->view_direction(), kFrame, {-2.5}});
    expect_preview(with_new, "placing at az " + std::to_string(az));
    EXPECT_EQ(ed_->document().keyframes(EffectType::Exposure), doc_keys)
        << "the document is untouched";
  }
  frame(55.0, 10.0, 0.0, 0.0);  // release places it: the document's field and track
  ASSERT_FALSE(ed_->previewing());
  ASSERT_EQ(ed_->document().keyframes(EffectType::Exposure).size(), doc_keys.size() + 1);
  expect_document("after release");
  ed_->undo();
  frame(40.0, 10.0, 0.0, 0.0);
  expect_document("after undo");
  EXPECT_LT(max_abs(ed_->minimap_field(), before), 1e-5) << "undo restored the field";
  EXPECT_LT(max_abs(ed_->track_values(), track_before), 1e-9) << "and the track";
}

TEST_P(PreviewVisuals, GrabPreviewTrackAndFieldFollowTheHeldKeyframe) {
  frame(0.0, 0.0, 0.0, 0.0);
  const auto doc_keys = ed_->document().keyframes(EffectType::Exposure);
  frame(0.0, 0.0, 0.0, 1.0);  // grab: nothing moved yet, the document's
  ASSERT_TRUE(ed_->grabbing());
  ASSERT_EQ(*ed_->selected_keyframe(), doc_keys.size() - 1);
  expect_document("grabbed, not moved");
  for (int step = 1; step <= 3; ++step) {  // carry it 20 deg a frame to the right
    frame(20.0 * step, 0.0, 0.0, 1.0);
    auto moved = doc_keys;
    moved.back() = *ed_->selected_preview();
    expect_preview(moved, "grab step " + std::to_string(step));
  }
  frame(60.0, 0.0, 0.0, 0.0);  // release commits the move
  ASSERT_FALSE(ed_->grabbing());
  ASSERT_NE(ed_->document().keyframes(EffectType::Exposure), doc_keys);
  expect_document("after release");
  frame(60.0, 0.0, 0.0, 1.0);  // grab again, move, and cancel by undo
  frame(90.0, 0.0, 0.0, 1.0);
  ASSERT_TRUE(ed_->grabbing());
  ed_->undo();
  frame(90.0, 0.0, 0.0, 1.0);
  ASSERT_FALSE(ed_->grabbing());
  EXPECT_EQ(ed_->document().keyframes(EffectType::Exposure), doc_keys);
  expect_document("after undo");
}

INSTANTIATE_TEST_SUITE_P(Editor, PreviewVisuals,
                         ::testing::Values(Case{"sync", false}, Case{"async", true}),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace vdfx::app
