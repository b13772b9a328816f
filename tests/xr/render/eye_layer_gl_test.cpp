/// @file
/// @brief The compositor's world-space layer seam: layers are drawn after the effect stack (a
/// vignette does not darken them), before the UI quads (a panel covers them), in the order
/// given, once per eye with that eye's own view, and timed under their own stage name.
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "effects/effect_shaders.h"
#include "gl_test_support.h"
#include "xr/render/compositor.h"

namespace vdfx::xr {
namespace {

constexpr int kW = 96, kH = 96;

/// Fills a rectangle of the bound eye buffer with a colour (scissored clear) and records the
/// views it was drawn for.
class RectLayer final : public EyeLayer {
 public:
  RectLayer(const char* name, cv::Rect rect, cv::Vec3f rgb) : name_(name), rect_(rect), rgb_(rgb) {}
  const char* name() const override { return name_; }
  void draw(const RenderView& view, int eye, int width, int height) override {
    calls.push_back({eye, view.position.x(), width, height});
    glEnable(GL_SCISSOR_TEST);
    // GL rows count from the bottom; rect_ is in image rows (top = 0).
    glScissor(rect_.x, height - rect_.y - rect_.height, rect_.width, rect_.height);
    glClearColor(rgb_[0], rgb_[1], rgb_[2], 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
  }
  struct Call {
    int eye;
    double eye_x;
    int width, height;
  };
  std::vector<Call> calls;

 private:
  const char* name_;
  cv::Rect rect_;
  cv::Vec3f rgb_;
};

class EyeLayerGlTest : public test::GlTest {};

TEST_F(EyeLayerGlTest, LayersComeAfterTheEffectsBeforeTheQuadsInOrderPerEye) {
  CompositorConfig c;
  c.eye_width = kW;
  c.eye_height = kH;
  c.distortion.method = DistortionMethod::None;
  c.gpu_timing = true;
  Compositor comp(c);
  comp.set_video_frame(test::sunrise_float());
  // The vignette blacks out the whole view: whatever is bright was drawn after the effects.
  effects::StackParams p;
  p.vignette_radius_deg = 0.0;
  p.vignette_falloff_deg = 0.01;
  RectLayer first("first", {10, 10, 40, 40}, {0.2f, 0.4f, 0.6f});
  RectLayer second("second", {30, 30, 40, 40}, {0.9f, 0.1f, 0.3f});
  std::array<EyeLayer*, 2> layers{&first, &second};
  // An opaque panel over the middle, in front of the head.
  GlTexture panel(8, 8, TexFormat::RGBA8);
  panel.upload(cv::Mat(8, 8, CV_8UC4, cv::Scalar(0, 255, 0, 255)));  // green
  QuadLayer quad;
  quad.space = ReferenceSpace::View;
  quad.pose.position = {0, 0, -1};
  quad.size_m = {0.2, 0.2};
  quad.texture = panel.id();
  for (int e = 0; e < 2; ++e) {
    RenderView v = RenderView::look_at({0.0, 0.0}, 0.0, 90.0, kW, kH);
    v.position = {e == 0 ? -0.03 : 0.03, 0.0, 0.0};
    comp.render_eye(e, {v, p, effects::non_neutral_mask(p), false, layers}, std::span(&quad, 1));
  }
  const cv::Mat img = test::bgr_clamped(comp.read_eye_buffer(1));  // BGR float
  const auto rgb_at = [&](int x, int y) {
    const cv::Vec3f b = img.at<cv::Vec3f>(y, x);
    return cv::Vec3f(b[2], b[1], b[0]);
  };
  EXPECT_EQ(rgb_at(2, 2), cv::Vec3f(0, 0, 0));         // vignetted video
  EXPECT_NEAR(rgb_at(15, 15)[2], 0.6f, 1e-3);          // first layer only
  EXPECT_NEAR(rgb_at(65, 65)[0], 0.9f, 1e-3);          // second layer only
  EXPECT_NEAR(rgb_at(35, 35)[0], 0.9f, 1e-3);          // overlap: the second drawn last
  EXPECT_NEAR(rgb_at(kW / 2, kH / 2)[1], 1.0f, 1e-3);  // the panel covers both
  EXPECT_NEAR(rgb_at(kW / 2, kH / 2)[0], 0.0f, 1e-3);
  // Once per eye, with that eye's view and the eye buffer's size.
  ASSERT_EQ(first.calls.size(), 2u);
  EXPECT_EQ(first.calls[0].eye, 0);
  EXPECT_EQ(first.calls[0].eye_x, -0.03);
  EXPECT_EQ(first.calls[1].eye_x, 0.03);
  EXPECT_EQ(first.calls[1].width, kW);
  bool timed = false;
  for (const StageTime& t : comp.stage_times()) timed = timed || t.stage == "right second";
  EXPECT_TRUE(timed);
}

}  // namespace
}  // namespace vdfx::xr
