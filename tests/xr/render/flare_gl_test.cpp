/// @file
/// @brief The flare layer on the GPU: against the CPU reference per style (2/255 max), geometry
/// measured in rendered eye images at the generic and the off-centre profile (glare at the
/// light's projection, rings collinear with it and the view centre, ring disparity equal to that
/// of a point on the 5 cm plane), and golden screenshots of both styles on the sunrise panorama.
#include "xr/render/flare_gl.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <glm/gtc/quaternion.hpp>
#include <iostream>

#include "effects/equirect_sampler.h"
#include "effects/flare_render.h"
#include "effects/view_renderer.h"
#include "gl_test_support.h"
#include "tests/golden_bgr.h"
#include "tests/image_centroid.h"
#include "xr/headset/eye_views.h"
#include "xr/headset/session.h"
#include "xr/render/compositor.h"

namespace vdfx::xr {
namespace {

using effects::Direction;
using effects::FlareLayout;
using effects::FlareStyle;

Pose head_at(const Direction& look, double roll_deg = 0.0) {
  Pose p;
  p.position = {0.0, 1.6, 0.0};
  p.orientation = glm::quat_cast(camera_rotation(look, roll_deg));
  return p;
}

effects::HeadPose head_pose(const Pose& p) {
  return {position_of(p), rotation_of(p)};
}

FlareLayout layout(FlareStyle style, const Pose& head, const Direction& light, int rings = 6,
                   double intensity = 1.0) {
  effects::FlareSettings s = effects::default_flare_settings(style);
  s.rings = rings;
  auto l = effects::layout_flare(style, s, head_pose(head), effects::to_unit(light), intensity);
  if (!l) throw std::runtime_error("test layout adds nothing");
  return *l;
}

/// One profile's eyes at `scale` of their resolution, each as the compositor sees it.
struct Rig {
  HmdProfile profile;
  int w = 0, h = 0;
  std::array<RenderView, 2> views;
  Rig(const std::string& name, const Pose& head, double scale = 1.0)
      : profile(load_hmd_profile(name)) {
    const auto ev = locate_eye_views(head, profile);
    w = static_cast<int>(std::lround(ev[0].width * scale));
    h = static_cast<int>(std::lround(ev[0].height * scale));
    for (int e = 0; e < 2; ++e)
      views[static_cast<std::size_t>(e)] = render_view(ev[static_cast<std::size_t>(e)]);
  }
};

/// Both eyes through the compositor (RGBA32F, no distortion): the video (black when empty) with
/// the given flares. Returns RGB float images.
std::array<cv::Mat, 2> render_gl(const Rig& rig, const std::vector<FlareLayout>& layouts,
                                 const cv::Mat& video_bgr = {}) {
  CompositorConfig c;
  c.eye_width = rig.w;
  c.eye_height = rig.h;
  c.eye_format = TexFormat::RGBA32F;
  c.distortion.method = DistortionMethod::None;
  Compositor comp(c);
  comp.set_video_frame(video_bgr.empty() ? cv::Mat(32, 64, CV_32FC3, cv::Scalar::all(0))
                                         : video_bgr);
  FlareGl flare;
  flare.set_layouts(layouts);
  std::array<EyeLayer*, 1> layers{&flare};
  std::array<cv::Mat, 2> out;
  for (int e = 0; e < 2; ++e) {
    comp.render_eye(e, {rig.views[static_cast<std::size_t>(e)], {}, 0, false, layers});
    cv::cvtColor(comp.read_eye_buffer(e), out[static_cast<std::size_t>(e)], cv::COLOR_BGRA2RGB);
  }
  return out;
}

/// Sum of the channels.
cv::Mat energy(const cv::Mat& rgb) {
  cv::Mat e;
  cv::transform(rgb, e, cv::Matx13f(1, 1, 1));
  return e;
}

/// The glare's centroid: its core above half its peak.
Eigen::Vector2d glare_centroid(const cv::Mat& rgb) {
  return test_images::half_max_centroid(energy(rgb));
}

/// Pixel of a world point seen by an eye (nullopt behind it).
std::optional<Eigen::Vector2d> pixel_of(const Rig& rig, int eye, const Eigen::Vector3d& p) {
  const RenderView& v = rig.views[static_cast<std::size_t>(eye)];
  return v.camera(rig.w, rig.h).project(p - v.position);
}

/// True when the element's whole support projects inside the eye's image.
bool fully_visible(const Rig& rig, int eye, const FlareLayout& l, const effects::FlareElement& el) {
  const double r = effects::element_support(el) * el.radius;
  for (int k = 0; k < 16; ++k) {
    const double a = k * effects::kPi / 8;
    const auto px =
        pixel_of(rig, eye, el.centre + r * (std::cos(a) * l.axis_u + std::sin(a) * l.axis_v));
    if (!px || px->x() < 1 || px->y() < 1 || px->x() > rig.w - 1 || px->y() > rig.h - 1)
      return false;
  }
  return true;
}

double distance_to_line(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                        const Eigen::Vector2d& b) {
  const Eigen::Vector2d u = (b - a).normalized();
  const Eigen::Vector2d d = p - a;
  return std::abs(d.x() * u.y() - d.y() * u.x());
}

FlareLayout only_element(const FlareLayout& l, std::size_t i) {
  FlareLayout one = l;
  one.elements = {l.elements[i]};
  return one;
}

class FlareGlTest : public test::GlTest {};

TEST_F(FlareGlTest, MatchesTheCpuReferencePerStyleWithinTwoLevels) {
  const cv::Mat video_bgr = test::sunrise_float();
  cv::Mat video_rgb;
  cv::cvtColor(video_bgr, video_rgb, cv::COLOR_BGR2RGB);
  const effects::EquirectSampler sampler(
      video_rgb, {effects::SampleFilter::Bilinear, effects::PoleRows::Clamp});
  const Pose head = head_at({30.0, 3.0}, 5.0);
  const Rig rig("generic90", head, 0.5);
  for (const FlareStyle style : {FlareStyle::Directional, FlareStyle::Headset}) {
    const std::vector<FlareLayout> flares{layout(style, head, {35.9, 6.2}, 6, 1.5)};
    for (const bool with_video : {false, true}) {
      const auto gl = render_gl(rig, flares, with_video ? video_bgr : cv::Mat());
      for (int e = 0; e < 2; ++e) {
        const RenderView& v = rig.views[static_cast<std::size_t>(e)];
        const effects::ViewCamera cam = v.camera(rig.w, rig.h);
        cv::Mat cpu = with_video ? effects::render_view(sampler, cam, effects::StackParams{})
                                 : cv::Mat(rig.h, rig.w, CV_32FC3, cv::Scalar::all(0));
        effects::add_flares(cpu, cam, v.position, flares);
        cv::Mat a = gl[static_cast<std::size_t>(e)].clone(), b = cpu;
        cv::min(cv::max(a, 0.0), 1.0, a);
        cv::min(cv::max(b, 0.0), 1.0, b);
        const test::ErrorStats err = test::compare(a, b);
        std::cout << effects::flare_style_name(style) << (with_video ? " + video" : " alone")
                  << ", eye " << e << ": max " << err.max * 255 << "/255, mean " << err.mean * 255
                  << "/255\n";
        EXPECT_LE(err.max * 255, 2.0) << effects::flare_style_name(style) << " eye " << e;
        // The flare is really there (a test of nothing would pass too).
        if (!with_video) {
          double peak = 0;
          cv::minMaxLoc(energy(gl[static_cast<std::size_t>(e)]), nullptr, &peak);
          EXPECT_GT(peak, 1.0);
        }
      }
    }
  }
}

/// Glare and ring geometry of one flare in one eye's rendered image; returns the number of rings
/// measured (those fully inside the image).
int check_geometry(const Rig& rig, int eye, const FlareLayout& l,
                   const Eigen::Vector3d& glare_target_dir) {
  const std::string where = rig.profile.name + " " +
                            std::string(effects::flare_style_name(l.style)) + " eye " +
                            std::to_string(eye);
  // The glare alone (core and halo): its core's centroid at the target's projection.
  FlareLayout glare = l;
  glare.elements.resize(2);
  const Eigen::Vector2d g = glare_centroid(render_gl(rig, {glare})[static_cast<std::size_t>(eye)]);
  const RenderView& v = rig.views[static_cast<std::size_t>(eye)];
  const auto expected = v.camera(rig.w, rig.h).project(glare_target_dir);
  EXPECT_TRUE(expected) << where;
  if (!expected) return 0;
  const double glare_err = (g - *expected).norm();
  EXPECT_LT(glare_err, 1.0) << where << ": glare at " << g.transpose() << ", expected "
                            << expected->transpose();
  // Each ring alone: its centroid on the line through the glare and the view centre (B).
  const auto b = pixel_of(rig, eye, l.view_point);
  EXPECT_TRUE(b) << where;
  int measured = 0;
  double worst = 0.0;
  for (std::size_t i = 2; i < l.elements.size(); ++i) {
    if (!fully_visible(rig, eye, l, l.elements[i])) continue;
    const Eigen::Vector2d c = test_images::weighted_centroid(
        energy(render_gl(rig, {only_element(l, i)})[static_cast<std::size_t>(eye)]));
    const double off = distance_to_line(c, g, *b);
    worst = std::max(worst, off);
    EXPECT_LT(off, 1.0) << where << " ring " << i - 2;
    ++measured;
  }
  std::cout << where << ": glare " << glare_err << " px from the light's projection, rings ("
            << measured << ") at most " << worst << " px off the line\n";
  return measured;
}

TEST_F(FlareGlTest, DirectionalGlareAtTheLightRingsOnItsLinePerEyeAndProfile) {
  for (const std::string profile : {"generic90", "offcentre"}) {
    const Pose head = head_at({10.0, 5.0}, 4.0);
    const Rig rig(profile, head);
    const Direction light{16.0, 12.0};
    const FlareLayout l = layout(FlareStyle::Directional, head, light);
    for (int e = 0; e < 2; ++e)
      EXPECT_GE(check_geometry(rig, e, l, effects::to_unit(light)), 5) << profile << " eye " << e;
  }
}

TEST_F(FlareGlTest, HeadsetGlareAtThePlanePointRingsOnItsLinePerEyeAndProfile) {
  // generic90: the 5 cm plane is seen about 32 degrees off-centre in each eye; the light above the
  // gaze keeps the flare's line vertical, so its rings stay inside both eyes' images.
  {
    const Pose head = head_at({0.0, 0.0});
    const Rig rig("generic90", head);
    const FlareLayout l = layout(FlareStyle::Headset, head, {2.0, 9.0});
    for (int e = 0; e < 2; ++e) {
      const Eigen::Vector3d c = l.light_point - rig.views[static_cast<std::size_t>(e)].position;
      EXPECT_GE(check_geometry(rig, e, l, c), 4) << "generic90 eye " << e;
    }
  }
  // offcentre: no point of a 5 cm plane is inside both eyes' FOV (docs/flare.md, "Stereo"), so
  // each eye gets a light on its own side of the gaze.
  {
    const Pose head = head_at({0.0, 0.0});
    const Rig rig("offcentre", head);
    for (int e = 0; e < 2; ++e) {
      const FlareLayout l = layout(FlareStyle::Headset, head, {e == 0 ? -12.0 : 12.0, 2.0});
      const Eigen::Vector3d c = l.light_point - rig.views[static_cast<std::size_t>(e)].position;
      EXPECT_GE(check_geometry(rig, e, l, c), 1) << "offcentre eye " << e;
    }
  }
}

TEST_F(FlareGlTest, HeadsetRingDisparityIsThatOfAPointOnTheFiveCentimetrePlane) {
  const Pose head = head_at({0.0, 0.0});
  const Rig rig("generic90", head);
  const FlareLayout l = layout(FlareStyle::Headset, head, {2.0, 9.0});
  ASSERT_EQ(l.plane_distance, 0.05);
  int measured = 0;
  for (std::size_t i = 2; i < l.elements.size(); ++i) {
    if (!fully_visible(rig, 0, l, l.elements[i]) || !fully_visible(rig, 1, l, l.elements[i]))
      continue;
    const auto images = render_gl(rig, {only_element(l, i)});
    const Eigen::Vector2d left = test_images::weighted_centroid(energy(images[0])),
                          right = test_images::weighted_centroid(energy(images[1]));
    const Eigen::Vector2d expected =
        *pixel_of(rig, 0, l.elements[i].centre) - *pixel_of(rig, 1, l.elements[i].centre);
    const Eigen::Vector2d measured_disparity = left - right;
    std::cout << "ring " << i - 2 << ": disparity " << measured_disparity.x() << " px (plane point "
              << expected.x() << " px)\n";
    EXPECT_LT((measured_disparity - expected).norm(), 1.0) << "ring " << i - 2;
    // Hundreds of pixels: the 5 cm plane's disparity, nowhere near the video's (0).
    EXPECT_GT(std::abs(measured_disparity.x()), 300.0);
    ++measured;
  }
  EXPECT_GE(measured, 4);
  // The directional flare at 100 m: sub-pixel disparity, like the light itself.
  const FlareLayout far = layout(FlareStyle::Directional, head, {2.0, 9.0});
  const auto images = render_gl(rig, {only_element(far, 0)});
  EXPECT_LT(std::abs((glare_centroid(images[0]) - glare_centroid(images[1])).x() -
                     (*pixel_of(rig, 0, far.light_point) - *pixel_of(rig, 1, far.light_point)).x()),
            1.0);
}

TEST_F(FlareGlTest, GoldenScreenshotsOfBothStylesOnTheSunrise) {
  // Both eyes side by side, the band around the horizon, 10 degrees off the sun (36, 6) so the
  // rings splay from it through the view centre.
  const Pose head = head_at({27.0, 1.0});
  const Rig rig("generic90", head, 0.4);
  for (const FlareStyle style : {FlareStyle::Directional, FlareStyle::Headset}) {
    const auto eyes =
        render_gl(rig, {layout(style, head, {35.9, 6.2}, 6, 1.0)}, test::sunrise_float());
    cv::Mat both;
    cv::hconcat(eyes[0], eyes[1], both);
    both = both(cv::Rect(0, both.rows * 5 / 16, both.cols, both.rows * 3 / 8))
               .clone();  // the horizon band
    cv::min(cv::max(both, 0.0), 1.0, both);
    cv::Mat bgr8;
    cv::cvtColor(both, both, cv::COLOR_RGB2BGR);
    both.convertTo(bgr8, CV_8UC3, 255.0);
    const std::string r = test_images::compare_with_golden(
        bgr8, "xr/render", "flare_" + std::string(effects::flare_style_name(style)), 8.0, 0.5);
    EXPECT_TRUE(r.empty()) << r;
  }
}

}  // namespace
}  // namespace vdfx::xr
