/// @file
/// @brief Document and undo/redo: every command undoes to the identical sidecar bytes.
#include <gtest/gtest.h>

#include <functional>

#include "app/editor/document.h"
#include "editor_test_util.h"
#include "io/input_error.h"

namespace vdfx::app {
namespace {

using effects::EffectType;
using effects::Keyframe;

Document make_doc() {
  io::Sidecar s = test::empty_sidecar();
  s.effects.push_back(
      {EffectType::Exposure,
       std::nullopt,
       {{{30.0, 0.0}, 10, {1.0}}, {{-60.0, 10.0}, 20, {-2.0}}, {{120.0, -5.0}, 40, {0.5}}}});
  s.effects.push_back({EffectType::Tint, std::nullopt, {{{0.0, 0.0}, 0, {1.2, 0.9, 1.0}}}});
  return Document(s, DocumentOptions{{.async = false}});
}

struct CommandCase {
  const char* name;
  std::function<void(Document&)> apply;
};

class DocumentUndo : public ::testing::TestWithParam<CommandCase> {};

TEST_P(DocumentUndo, UndoRestoresBytesAndRedoReapplies) {
  Document doc = make_doc();
  const std::string before = io::format_sidecar(doc.sidecar());
  const auto params_before = doc.params(EffectType::Exposure);
  GetParam().apply(doc);
  const std::string after = io::format_sidecar(doc.sidecar());
  const auto params_after = doc.params(EffectType::Exposure);
  ASSERT_EQ(doc.undo_stack().undo_size(), 1u);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(io::format_sidecar(doc.sidecar()), before);
  EXPECT_EQ(doc.params(EffectType::Exposure), params_before);
  ASSERT_TRUE(doc.redo());
  EXPECT_EQ(io::format_sidecar(doc.sidecar()), after);
  EXPECT_EQ(doc.params(EffectType::Exposure), params_after);
  // The solution follows the restored keyframes: it reproduces each of them.
  const auto rbf = doc.keyframe_set(EffectType::Exposure).solution();
  for (const auto& k : doc.keyframes(EffectType::Exposure))
    EXPECT_NEAR(rbf->evaluate(k.direction, k.frame)[0], k.params[0], 1e-8);
}

INSTANTIATE_TEST_SUITE_P(
    Commands, DocumentUndo,
    ::testing::Values(
        CommandCase{"add",
                    [](Document& d) {
                      d.add_keyframe(EffectType::Exposure, {{90.0, 20.0}, 5, {3.0}});
                    }},
        CommandCase{"add_new_effect",
                    [](Document& d) {
                      d.add_keyframe(EffectType::Blur, {{0.0, 0.0}, 0, {2.0}});
                    }},
        CommandCase{"replace",
                    [](Document& d) {
                      d.add_keyframe(EffectType::Exposure, {{30.3, 0.1}, 10, {4.0}});
                    }},
        CommandCase{"move",
                    [](Document& d) {
                      d.move_keyframe(EffectType::Exposure, 1, {-50.0, 0.0}, 25);
                    }},
        CommandCase{"delete", [](Document& d) { d.remove_keyframe(EffectType::Exposure, 0); }},
        CommandCase{"delete_last_of_effect",
                    [](Document& d) { d.remove_keyframe(EffectType::Tint, 0); }},
        CommandCase{"keyframe_params",
                    [](Document& d) { d.set_keyframe_params(EffectType::Exposure, 2, {-1.0}); }},
        CommandCase{"chosen_params",
                    [](Document& d) { d.set_params(EffectType::Exposure, {2.5}); }},
        CommandCase{"interpolation",
                    [](Document& d) {
                      d.set_interpolation(EffectType::Exposure, {1.5, 2.0});
                    }}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(Document, ReplaceWithinHalfDegreeOnSameFrameOnly) {
  Document doc = make_doc();
  auto e = doc.add_keyframe(EffectType::Exposure, {{30.4, 0.0}, 10, {4.0}});
  EXPECT_TRUE(e.replaced.has_value());
  EXPECT_EQ(doc.keyframes(EffectType::Exposure).size(), 3u);
  e = doc.add_keyframe(EffectType::Exposure, {{30.4, 0.0}, 11, {4.0}});
  EXPECT_FALSE(e.replaced.has_value());
  e = doc.add_keyframe(EffectType::Exposure, {{31.0, 0.0}, 10, {4.0}});
  EXPECT_FALSE(e.replaced.has_value());
  EXPECT_EQ(doc.keyframes(EffectType::Exposure).size(), 5u);
}

TEST(Document, GroupIsOneUndoStepAndNewEditClearsRedo) {
  Document doc = make_doc();
  doc.begin_group("drag");
  for (double v : {0.5, 1.0, 1.5, 2.0}) doc.set_params(EffectType::Exposure, {v});
  doc.end_group();
  EXPECT_EQ(doc.undo_stack().undo_size(), 1u);
  EXPECT_EQ(doc.params(EffectType::Exposure), std::vector<double>{2.0});
  doc.undo();
  EXPECT_EQ(doc.params(EffectType::Exposure), std::vector<double>{0.0});
  EXPECT_TRUE(doc.undo_stack().can_redo());
  doc.set_params(EffectType::Exposure, {-1.0});
  EXPECT_FALSE(doc.undo_stack().can_redo());
}

TEST(Document, UnlimitedUndoBackToTheStart) {
  Document doc = make_doc();
  const std::string start = io::format_sidecar(doc.sidecar());
  std::vector<std::string> states{start};
  for (int i = 0; i < 40; ++i) {
    doc.add_keyframe(EffectType::Saturation,
                     {{-170.0 + 8.0 * i, (i % 7) * 5.0 - 15.0}, i, {0.1 * (i % 30)}});
    states.push_back(io::format_sidecar(doc.sidecar()));
  }
  for (int i = 40; i > 0; --i) {
    ASSERT_TRUE(doc.undo());
    ASSERT_EQ(io::format_sidecar(doc.sidecar()), states[static_cast<std::size_t>(i - 1)]) << i;
  }
  EXPECT_FALSE(doc.undo());
  for (int i = 1; i <= 40; ++i) {
    ASSERT_TRUE(doc.redo());
    ASSERT_EQ(io::format_sidecar(doc.sidecar()), states[static_cast<std::size_t>(i)]);
  }
}

TEST(Document, ParamsAreClampedAndTintNormalised) {
  Document doc = make_doc();
  doc.set_params(EffectType::Exposure, {20.0});
  EXPECT_EQ(doc.params(EffectType::Exposure), std::vector<double>{8.0});
  doc.set_params(EffectType::Tint, {2.0, 2.0, 2.0});
  const auto& g = doc.params(EffectType::Tint);
  EXPECT_NEAR(0.25 * g[0] + 0.5 * g[1] + 0.25 * g[2], 1.0, 1e-12);
}

TEST(Document, SidecarListsEffectsInStackOrderWithOverrides) {
  Document doc = make_doc();
  doc.set_interpolation(EffectType::Vignette, {2.5, 0.5});
  const io::Sidecar s = doc.sidecar();
  ASSERT_EQ(s.effects.size(), 3u);
  EXPECT_EQ(s.effects[0].type, EffectType::Tint);
  EXPECT_EQ(s.effects[1].type, EffectType::Exposure);
  EXPECT_EQ(s.effects[2].type, EffectType::Vignette);
  EXPECT_TRUE(s.effects[2].keyframes.empty());
  ASSERT_TRUE(s.effects[2].interpolation.has_value());
  EXPECT_EQ(s.effects[2].interpolation->exponent, 2.5);
  EXPECT_THROW(doc.set_interpolation(EffectType::Blur, {4.0, 1.0}), io::InputError);
}

}  // namespace
}  // namespace vdfx::app
