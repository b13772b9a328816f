/// @file
/// @brief The compositor pipeline: quads after effects, spaces, mirror modes, offscreen render.
#include <gtest/gtest.h>

#include "effects/effect_shaders.h"
#include "effects/equirect_sampler.h"
#include "effects/view_camera.h"
#include "effects/view_renderer.h"
#include "gl_test_support.h"
#include "xr/render/compositor.h"

namespace vdfx::xr {
namespace {

using effects::EffectType;
using test::GlTest;

constexpr int kW = 160, kH = 160;

class CompositorGlTest : public GlTest {};

GlTexture solid_texture(cv::Scalar bgra) {
  GlTexture t(8, 8, TexFormat::RGBA8);
  t.upload(cv::Mat(8, 8, CV_8UC4, bgra));
  return t;
}

CompositorConfig small_config(DistortionMethod m) {
  CompositorConfig c;
  c.eye_width = kW;
  c.eye_height = kH;
  c.distortion.method = m;
  effects::LensParams lp;
  lp.c1 = 0.2;
  lp.c2 = 0.1;
  c.lens = effects::LensModel(lp);
  c.gpu_timing = true;
  return c;
}

TEST_F(CompositorGlTest, QuadLayersComeAfterTheEffectsAndFollowTheirSpace) {
  Compositor comp(small_config(DistortionMethod::None));
  comp.set_video_frame(test::sunrise_float());
  // A vignette that blacks out everything beyond 1 degree: the video is black, a quad is not.
  effects::StackParams p;
  p.vignette_radius_deg = 0.5;
  p.vignette_falloff_deg = 0.5;
  p.exposure_stops = 2.0;
  const GlTexture panel_tex = solid_texture({230, 153, 51, 255});  // BGRA of (0.2, 0.6, 0.9)
  QuadLayer quad;
  quad.space = ReferenceSpace::View;
  quad.pose.position = {0.3, 0, -1};  // right of the centre, off the vignette's lit spot
  quad.size_m = {0.2, 0.2};
  quad.texture = panel_tex.id();
  Pose head;
  head.orientation = glm::angleAxis(M_PI / 2, glm::dvec3(0, 1, 0));
  const double a = std::atan(0.8) * effects::kRadToDeg;  // tangents +-0.8
  EyeView ev;
  ev.pose = head;
  ev.fov = {-a, a, a, -a};
  const RenderView eye = render_view(ev);
  comp.render_eye(0, {eye, p, effects::non_neutral_mask(p)}, std::span(&quad, 1), head);
  cv::Mat img = test::bgr_clamped(comp.read_eye_buffer(0));
  // The quad centre projects to tangent (0.3, 0): pixel x = (0.3 + 0.8) / 1.6 * W.
  ASSERT_EQ(
      cv::countNonZero(
          img(cv::Rect(static_cast<int>(1.0 / 1.6 * kW), kH / 2 - 8, 20, 16)).clone().reshape(1) >
          0.01f),
      20 * 16 * 3);
  const cv::Vec3f q = img.at<cv::Vec3f>(kH / 2, static_cast<int>(1.1 / 1.6 * kW));
  EXPECT_NEAR(q[0], 0.9, 1.0 / 255);
  EXPECT_NEAR(q[1], 0.6, 1.0 / 255);
  EXPECT_NEAR(q[2], 0.2, 1.0 / 255);
  EXPECT_EQ(img.at<cv::Vec3f>(10, 10), cv::Vec3f(0, 0, 0));  // the vignetted video
  // The same quad in LOCAL space stays where it was put (ahead of LOCAL -z) while the head
  // looks 90 degrees left: it leaves the view.
  quad.space = ReferenceSpace::Local;
  comp.render_eye(0, {eye, p, effects::non_neutral_mask(p)}, std::span(&quad, 1), head);
  img = test::bgr_clamped(comp.read_eye_buffer(0));
  const cv::Rect where_it_was(static_cast<int>(1.0 / 1.6 * kW), kH / 2 - 8, 20, 16);
  EXPECT_EQ(cv::countNonZero(img(where_it_was).clone().reshape(1) > 0.01f), 0);
  const std::vector<StageTime> times = comp.stage_times();
  ASSERT_GE(times.size(), 8u);
  EXPECT_EQ(times[0].stage, "left video");
  for (const StageTime& s : times) EXPECT_GE(s.ms, 0.0) << s.stage;
}

TEST_F(CompositorGlTest, MirrorModesShowPanelsTheWearersViewAndOneEye) {
  Compositor comp(small_config(DistortionMethod::Mesh));
  comp.set_video_frame(test::sunrise_float());
  effects::StackParams p;
  p.saturation = 1.5;
  std::array<RenderView, 2> eyes = {RenderView::look_at({10, 0}, 0, 90, kW, kH),
                                    RenderView::look_at({14, 0}, 0, 90, kW, kH)};
  for (int e = 0; e < 2; ++e) comp.render_eye(e, {eyes[e], p, effects::non_neutral_mask(p)});
  GlTarget mirror(2 * kW, kH, TexFormat::RGBA16F);
  comp.draw_mirror(MirrorMode::PreDistorted, &mirror, 2 * kW, kH);
  const cv::Mat m = mirror.read_float();
  EXPECT_LE(test::compare(m(cv::Rect(0, 0, kW, kH)), comp.read_display(0)).max, 1e-3);
  EXPECT_LE(test::compare(m(cv::Rect(kW, 0, kW, kH)), comp.read_display(1)).max, 1e-3);
  // Through the lens: the wearer sees the undistorted eye buffer again (centre region).
  comp.draw_mirror(MirrorMode::ThroughTheLens, &mirror, 2 * kW, kH);
  const cv::Rect centre(kW / 4, kH / 4, kW / 2, kH / 2);
  const cv::Mat seen = mirror.read_float()(cv::Rect(0, 0, kW, kH));
  const test::ErrorStats e = test::compare(test::bgr_clamped(seen)(centre),
                                           test::bgr_clamped(comp.read_eye_buffer(0))(centre));
  EXPECT_LT(e.mean, 1.5 / 255);
  EXPECT_GT(test::compare(comp.read_display(0)(centre), comp.read_eye_buffer(0)(centre)).mean,
            2.0 / 255);
  GlTarget single(kW, kH, TexFormat::RGBA16F);
  comp.draw_mirror(MirrorMode::SingleEye, &single, kW, kH);
  EXPECT_LE(test::compare(single.read_float(), comp.read_eye_buffer(0)).max, 1e-3);
  comp.stage_times();
}

TEST_F(CompositorGlTest, OffscreenRenderIsTheUndistortedEffectedViewIn8Bit) {
  const cv::Mat eq = test::sunrise_float();
  effects::StackParams p;
  p.exposure_stops = 1.0;
  const RenderView v = RenderView::look_at({-40, 10}, 5, 70, 120, 90);
  const cv::Mat img = render_view_gpu(eq, v, 120, 90, p, effects::non_neutral_mask(p));
  ASSERT_EQ(img.type(), CV_8UC3);
  ASSERT_EQ(img.size(), cv::Size(120, 90));
  const cv::Mat plain = render_view_gpu(eq, v, 120, 90, {}, 0);
  // Doubling brightens every unclipped pixel to twice its value (within 8-bit rounding).
  int checked = 0;
  for (int y = 0; y < 90; ++y)
    for (int x = 0; x < 120; ++x)
      for (int c = 0; c < 3; ++c) {
        const int a = plain.at<cv::Vec3b>(y, x)[c], b = img.at<cv::Vec3b>(y, x)[c];
        if (a < 120) {
          EXPECT_NEAR(b, 2 * a, 2) << x << "," << y;
          ++checked;
        }
      }
  EXPECT_GT(checked, 1000);
}

TEST_F(CompositorGlTest, WholeEyeMatchesTheCpuViewRendererIncludingTheBlurredBorder) {
  // effects::render_view blurs a view sampled with a margin of one kernel radius, so the blur
  // never meets an image border; the compositor renders the video layer with the same margin.
  const cv::Mat eq = test::sunrise_float();
  cv::Mat eq_rgb;
  cv::cvtColor(eq, eq_rgb, cv::COLOR_BGR2RGB);
  const effects::EquirectSampler sampler(
      eq_rgb, {effects::SampleFilter::Bilinear, effects::PoleRows::Clamp});
  const int w = 200, h = 150;  // 4 px/degree: magnified everywhere, so both read level 0
  const effects::ViewPose pose{{35, 5}, 10};
  const effects::ViewCamera cam = effects::ViewCamera::from_horizontal_fov(pose, 50, w, h);
  RenderView v = RenderView::look_at(pose.look, pose.roll_deg, 50, w, h);
  CompositorConfig c = small_config(DistortionMethod::None);
  c.eye_width = w;
  c.eye_height = h;
  Compositor comp(c);
  comp.set_video_frame(eq);
  effects::StackParams p;
  p.blur_sigma_deg = 1.5;
  p.exposure_stops = 0.4;
  p.vignette_radius_deg = 15;
  p.vignette_falloff_deg = 20;
  comp.render_eye(0, {v, p, effects::non_neutral_mask(p)});
  comp.stage_times();
  cv::Mat ref;
  cv::cvtColor(effects::render_view(sampler, cam, p), ref, cv::COLOR_RGB2BGR);
  cv::min(cv::max(ref, 0.0), 1.0, ref);
  const test::ErrorStats e = test::compare(test::bgr_clamped(comp.read_eye_buffer(0)), ref);
  const cv::Rect border_band(0, 0, 8, h);
  const test::ErrorStats edge =
      test::compare(test::bgr_clamped(comp.read_eye_buffer(0))(border_band), ref(border_band));
  std::printf(
      "[ eye      ] GPU eye vs effects::render_view: max %.3f/255 mean %.4f/255 "
      "(left 8 columns: max %.3f/255)\n",
      e.max * 255, e.mean * 255, edge.max * 255);
  EXPECT_LE(e.max, 2.0 / 255);
  EXPECT_LE(edge.max, 2.0 / 255);
}

}  // namespace
}  // namespace vdfx::xr
