/// @file
/// @brief The GL grain layer: shader styles against the CPU reference (GLSL vs C++ noise), the
/// particles generated on the GPU where the CPU definition puts them in each eye, the refresh,
/// zero intensity.
#include "xr/render/grain_gl.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <iostream>

#include "effects/grain_render.h"
#include "effects/grain_shaders.h"
#include "gl_test_support.h"
#include "tests/golden_bgr.h"
#include "xr/render/compositor.h"
#include "xr/render/gl_texture.h"

namespace vdfx::xr {
namespace {

using test::GlTest;

constexpr int kW = 320, kH = 256;

RenderView eye_view(const effects::HeadPose& head, double offset_m) {
  RenderView v;
  v.orientation = head.orientation;
  v.position = head.position + head.orientation * Eigen::Vector3d(offset_m, 0, 0);
  v.tan_left = -1.1;
  v.tan_right = 0.9;
  v.tan_down = -0.8;
  v.tan_up = 0.7;
  return v;
}

effects::GrainFrame layer(effects::GrainStyle style, double intensity, double size,
                          const effects::HeadPose& head, double distance = 0.0) {
  effects::GrainEffect e;
  e.style = style;
  e.seed = 99;
  if (distance > 0)
    e.settings.set(style == effects::GrainStyle::Headset ? effects::GrainSetting::PlaneM
                                                         : effects::GrainSetting::SphereM,
                   distance);
  e.keyframes = {{{0, 0}, 0, {intensity, size}}};
  effects::GrainSet set({e}, {}, 30.0);
  auto frames = set.layout(head, 123'456'789, 0);
  EXPECT_EQ(frames.size(), 1u);
  return frames.at(0);
}

/// A sunrise crop as the eye image (BGR float), uploaded into an RGBA32F target.
cv::Mat background() {
  cv::Mat s = test::sunrise_float(), out;
  cv::resize(s(cv::Rect(s.cols / 4, s.rows / 4, s.cols / 2, s.rows / 2)), out, {kW, kH}, 0, 0,
             cv::INTER_AREA);
  return out;
}

/// Draws the layers over `bg` as the compositor does: the eye buffer bound, then the layer.
cv::Mat gpu_render(GrainGl& g, const cv::Mat& bg, const RenderView& v,
                   const std::vector<effects::GrainFrame>& layers) {
  GlTarget t(kW, kH, TexFormat::RGBA32F);
  t.texture().upload(bg);
  g.set_layers(layers);
  t.bind();
  g.draw(v, 0, kW, kH);
  return test::bgr_clamped(t.read_float());
}

cv::Mat cpu_render(const cv::Mat& bg, const RenderView& v, const effects::GrainFrame& f) {
  cv::Mat img = bg.clone();
  effects::composite_shader_grain(img, f, v.orientation, v.position, v.tangents());
  cv::min(cv::max(img, 0.0), 1.0, img);
  return img;
}

class GrainGlTest : public GlTest {};

TEST_F(GrainGlTest, ShaderStylesMatchTheCppReferenceWithinTwoLevels) {
  auto g = std::make_unique<GrainGl>();
  const cv::Mat bg = background();
  effects::HeadPose head;
  head.position = {0.2, 1.6, -0.3};
  head.orientation = view_rotation({35, 12}, 8);
  struct Case {
    effects::GrainStyle style;
    double intensity, size, distance, eye_offset;
  };
  // An off-centre crop of an eye at 800 px per tangent unit (a 4-mrad cell is 3.2 px, about a
  // headset's density): the grain is resolved, not band-limited away. Size 0.6 fades octave 2.
  for (const Case& c : {Case{effects::GrainStyle::Headset, 0.6, 1.0, 0.05, -0.0315},
                        Case{effects::GrainStyle::Headset, 1.0, 0.6, 0.5, 0.0315},
                        Case{effects::GrainStyle::Surface, 0.5, 1.0, 10.0, -0.0315},
                        Case{effects::GrainStyle::Surface, 1.0, 2.5, 2.0, 0.0315}}) {
    const effects::GrainFrame f = layer(c.style, c.intensity, c.size, head, c.distance);
    RenderView v = eye_view(head, c.eye_offset);
    v.tan_left = -0.22;
    v.tan_right = v.tan_left + kW / 800.0;
    v.tan_down = -0.14;
    v.tan_up = v.tan_down + kH / 800.0;
    const cv::Mat gpu = gpu_render(*g, bg, v, {f});
    const cv::Mat cpu = cpu_render(bg, v, f);
    const test::ErrorStats e = test::compare(gpu, cpu);
    const test::ErrorStats grain = test::compare(cpu, bg);
    SCOPED_TRACE(std::string(effects::grain_style_name(c.style)) + " intensity " +
                 std::to_string(c.intensity) + " size " + std::to_string(c.size));
    EXPECT_LE(e.max * 255.0, 2.0);
    EXPECT_LT(e.mean * 255.0, 0.05);
    EXPECT_GT(grain.mean * 255.0, 5.0);  // the layer is really there
    std::printf(
        "%s I %.1f size %.1f at %.2f m: GL vs C++ max %.3f/255 mean %.4f/255 (grain %.1f/255)\n",
        effects::grain_style_name(c.style).data(), c.intensity, c.size, c.distance, e.max * 255,
        e.mean * 255, grain.mean * 255);
  }
}

TEST_F(GrainGlTest, NoLayersDrawNothing) {
  auto g = std::make_unique<GrainGl>();
  const cv::Mat bg = background();
  const cv::Mat out = gpu_render(*g, bg, eye_view({}, 0), {});
  EXPECT_EQ(g->stats().shader_draws + g->stats().particle_draws, 0);
  EXPECT_EQ(test::compare(out, test::bgr_clamped(bg)).max, 0.0);
}

/// Alpha-weighted centroid of |out - bg| in a window around a point.
Eigen::Vector2d centroid(const cv::Mat& out, const cv::Mat& bg, const Eigen::Vector2d& at, int r,
                         double* mass = nullptr) {
  double sx = 0, sy = 0, s = 0;
  for (int y = int(at.y()) - r; y <= int(at.y()) + r; ++y)
    for (int x = int(at.x()) - r; x <= int(at.x()) + r; ++x) {
      if (x < 0 || y < 0 || x >= out.cols || y >= out.rows) continue;
      const double d = std::abs(out.at<cv::Vec3f>(y, x)[1] - bg.at<cv::Vec3f>(y, x)[1]);
      sx += d * (x + 0.5);
      sy += d * (y + 0.5);
      s += d;
    }
  if (mass) *mass = s;
  return {sx / s, sy / s};
}

/// A free cloud of `count` particles (seed 99) at one refresh, intensity 1, size 1.
effects::GrainFrame cloud_frame(const effects::HeadPose& head, int count, std::int64_t refresh) {
  effects::GrainFrame f;
  f.style = effects::GrainStyle::FreeCloud;
  f.params = {1.0, 1.0};
  f.head = head;
  f.refresh = refresh;
  f.particle_key = effects::grain_particle_key(99, refresh);
  f.settings.set(effects::GrainSetting::Count, count);
  return f;
}

/// Where the CPU definition's particle i projects in an eye (pixels), its distance from the eye,
/// or a negative distance behind it.
std::pair<Eigen::Vector2d, double> particle_pixel(const effects::GrainFrame& f, std::uint32_t i,
                                                  const RenderView& v) {
  const effects::GrainParticle q = effects::grain_particle(f.style, f.settings, f.particle_key, i);
  const Eigen::Vector3d e = v.orientation.transpose() * (f.head.position + q.centre - v.position);
  if (e.z() > -0.05) return {{0, 0}, -1.0};
  return {v.pixel_at({e.x() / -e.z(), e.y() / -e.z()}, kW, kH), e.norm()};
}

TEST_F(GrainGlTest, ParticlesLandWhereTheirPositionProjectsInEachEye) {
  // The GPU generates the particles from (key, index); each lands where the CPU definition
  // (effects::grain_particle) of that particle projects, in each eye and for two refreshes.
  auto g = std::make_unique<GrainGl>();
  effects::HeadPose head;
  head.position = {0.0, 1.6, 0.0};
  head.orientation = view_rotation({-20, 5}, 0);
  constexpr int kCount = 60;
  const cv::Mat bg(kH, kW, CV_32FC3, cv::Scalar(0.2, 0.2, 0.2));
  int checked = 0;
  for (std::int64_t refresh : {0, 1}) {
    const effects::GrainFrame f = cloud_frame(head, kCount, refresh);
    for (double offset : {-0.0315, 0.0315}) {
      const RenderView v = eye_view(head, offset);
      const cv::Mat out = gpu_render(*g, bg, v, {f});
      std::vector<std::pair<Eigen::Vector2d, double>> at;
      for (std::uint32_t i = 0; i < kCount; ++i) at.push_back(particle_pixel(f, i, v));
      for (std::uint32_t i = 0; i < kCount; ++i) {
        const auto [px, dist] = at[i];
        const effects::GrainParticle q =
            effects::grain_particle(f.style, f.settings, f.particle_key, i);
        // Visible, well inside the eye, not near-faded, with contrast, and alone in its window.
        bool alone = true;
        for (std::uint32_t k = 0; k < kCount; ++k)
          alone &= k == i || at[k].second < 0 || (at[k].first - px).norm() > 26.0;
        if (dist < 0.35 || px.x() < 14 || px.y() < 14 || px.x() > kW - 14 || px.y() > kH - 14 ||
            std::abs(2 * q.brightness - 1) * q.opacity < 0.2 || !alone)
          continue;
        double mass = 0;
        const Eigen::Vector2d c = centroid(out, bg, px, 12, &mass);
        EXPECT_GT(mass, 0.0) << i;
        EXPECT_LT((c - px).norm(), 0.25) << "particle " << i << " eye " << offset;
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 8);
  EXPECT_EQ(g->stats().particles_drawn, 4 * kCount);
}

TEST_F(GrainGlTest, ParticlesFollowTheRefreshAndZeroIntensityDrawsNothing) {
  auto g = std::make_unique<GrainGl>();
  effects::GrainEffect e;
  e.style = effects::GrainStyle::ObjectCloud;
  e.settings.set(effects::GrainSetting::Count, 20000);
  e.settings.set(effects::GrainSetting::SphereM, 1.0);  // near enough for pixel-sized grains
  e.keyframes = {{{0, 0}, 0, {0.8, 1.0}}};
  effects::GrainSet set({e}, {}, 30.0);
  const cv::Mat bg(kH, kW, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5));
  cv::Mat first;
  for (int n = 0; n < 4; ++n) {  // 0, 11.1, 22.2, 33.3 ms: refreshes 0, 0, 1, 1
    const auto frames = set.layout({}, n * 11'111'111, 0);
    const cv::Mat out = gpu_render(*g, bg, eye_view({}, -0.0315), frames);
    if (n == 0) first = out;
    if (n == 1) {
      EXPECT_EQ(test::compare(out, first).max, 0.0);  // same refresh: the same grains
    } else if (n == 2) {
      EXPECT_GT(test::compare(out, first).mean * 255, 0.05);  // the next refresh: new grains
    }
  }
  EXPECT_GT(test::compare(first, bg).mean * 255, 0.05);
  // A fresh layer with the same seed and refresh draws the same image (nothing is cached).
  GrainGl again;
  EXPECT_EQ(
      test::compare(gpu_render(again, bg, eye_view({}, -0.0315), set.layout({}, 0, 0)), first).max,
      0.0);
  effects::GrainEffect off = e;
  off.keyframes[0].params[0] = 0.0;
  effects::GrainSet none({off}, {}, 30.0);
  const auto before = g->stats();
  const cv::Mat out = gpu_render(*g, bg, eye_view({}, 0), none.layout({}, 0, 0));
  EXPECT_EQ(g->stats().particle_draws, before.particle_draws);
  EXPECT_EQ(test::compare(out, bg).max, 0.0);
}

}  // namespace
}  // namespace vdfx::xr

namespace vdfx::xr {
namespace {

/// The golden scene's eyes (generic90's pixel density, the sunrise, the head looking at the
/// trees), each 480 x 320 around the view centre, with `grains` (none: the plain eyes), 8-bit BGR;
/// `eyes` 1: the left eye only.
std::vector<cv::Mat> sunrise_eyes(const std::vector<effects::GrainEffect>& grains, int eyes = 2) {
  const double f =
      1440.0 / (std::tan(52.0 * effects::kDegToRad) + std::tan(47.0 * effects::kDegToRad));
  const int w = 480, h = 320;
  effects::HeadPose head;
  head.orientation = view_rotation({-30, 5}, 0);
  CompositorConfig cc;
  cc.eye_width = w;
  cc.eye_height = h;
  cc.eye_format = TexFormat::RGBA32F;
  cc.distortion.method = DistortionMethod::None;
  Compositor comp(cc);
  comp.set_video_frame(test::sunrise_float());
  effects::GrainSet set(grains, {}, 30.0);
  GrainGl grain;
  grain.set_layers(set.layout(head, 0, 0));
  const std::array<EyeLayer*, 1> layers{&grain};
  std::vector<cv::Mat> out;
  for (int k = 0; k < eyes; ++k) {
    RenderView v = eye_view(head, k == 0 ? -0.0315 : 0.0315);
    v.tan_left = -0.5 * w / f;
    v.tan_right = 0.5 * w / f;
    v.tan_down = -0.5 * h / f;
    v.tan_up = 0.5 * h / f;
    comp.render_eye(k, {v, {}, 0, false, layers});
    out.push_back(to_bgr8(comp.read_display(k)));
  }
  return out;
}

/// Golden screenshots: each style over the sunrise panorama, both eyes side by side, each a
/// 480 x 320 crop around the view centre at generic90's pixel density (612 px per tangent
/// unit), head looking at the trees. Settings as an author would pick them for a film-grain look
/// (docs/grain.md, "Looks"); the volumetric styles need many small particles for that.
TEST_F(GrainGlTest, GoldenScreenshotsOfEachStyleOnTheSunrise) {
  struct Look {
    effects::GrainStyle style;
    double intensity, size;
    std::vector<std::pair<effects::GrainSetting, double>> settings;
  };
  using S = effects::GrainSetting;
  for (const Look& look :
       {Look{effects::GrainStyle::Headset, 0.5, 1.0, {}},
        Look{effects::GrainStyle::Surface, 0.5, 1.0, {}},
        Look{effects::GrainStyle::ObjectCloud, 1.0, 1.0, {{S::SphereM, 2.0}, {S::Count, 1000000}}},
        Look{effects::GrainStyle::FreeCloud, 1.0, 1.0, {{S::Count, 600000}}}}) {
    effects::GrainEffect e;
    e.style = look.style;
    e.seed = 2024;
    for (const auto& [id, v] : look.settings) e.settings.set(id, v);
    e.keyframes = {{{0, 0}, 0, {look.intensity, look.size}}};
    const std::vector<cv::Mat> eyes = sunrise_eyes({e});
    cv::Mat both;
    cv::hconcat(eyes[0], eyes[1], both);
    const std::string r = test_images::compare_with_golden(
        both, "xr/render", "grain_" + std::string(effects::grain_style_name(look.style)), 8.0, 0.5);
    EXPECT_TRUE(r.empty()) << r;
  }
}

/// docs/grain.md, "Looks": at their defaults and intensity 0.6, size 1, each volumetric style
/// changes most of the view (the old defaults, 20 000 particles and a 10 m sphere, changed 1 %
/// and 13 % of it: a sparse dust), by a few 8-bit steps.
TEST_F(GrainGlTest, VolumetricDefaultsChangeMostOfTheView) {
  const cv::Mat plain = sunrise_eyes({}, 1)[0];
  for (const auto style : {effects::GrainStyle::ObjectCloud, effects::GrainStyle::FreeCloud}) {
    effects::GrainEffect e;
    e.style = style;
    e.seed = 11;
    e.settings = effects::GrainSettings(style);
    e.keyframes = {{{0, 0}, 0, {0.6, 1.0}}};
    cv::Mat diff;
    cv::absdiff(sunrise_eyes({e}, 1)[0], plain, diff);
    cv::Mat any;
    cv::transform(diff, any, cv::Matx13f(1, 1, 1));
    const double share = cv::countNonZero(any) / static_cast<double>(any.total());
    cv::Scalar mean, sd;
    cv::meanStdDev(diff.reshape(1), mean, sd);
    std::cout << effects::grain_style_name(style) << " defaults at intensity 0.6: " << share * 100
              << " % of the view changed, mean |change| " << mean[0] << " steps\n";
    EXPECT_GT(share, 0.5) << effects::grain_style_name(style);
    EXPECT_GT(mean[0], 1.0) << effects::grain_style_name(style);
  }
}

}  // namespace
}  // namespace vdfx::xr
