/// @file
/// @brief Equirect sampling at the poles for `vdfx bench`: the CPU sampler with and without its
/// ripmap and OpenCV's remap (the CPU peer), and the GPU video layer with the base level only and
/// with its two mip level choices (peer: a plain textured copy), all against a supersampled
/// box-filtered reference of a view looking 80 degrees up at the synthetic 4K frame.
#include <epoxy/gl.h>

#include <map>
#include <memory>
#include <opencv2/imgproc.hpp>

#include "app/bench/gl_rows.h"
#include "app/bench/inputs.h"
#include "effects/equirect_sampler.h"
#include "effects/view_camera.h"
#include "effects/view_renderer.h"
#include "xr/render/effect_stack_gl.h"
#include "xr/render/video_layer.h"

namespace vdfx::app::bench {
namespace {

constexpr const char* kKnob = "sampling.poles";
const effects::Direction kLook{0.0, 80.0};
constexpr double kFov = 90.0;

int view_size(bool quick) {
  return quick ? 256 : 512;
}
int supersampling(bool quick) {
  return quick ? 12 : 16;
}

/// The synthetic frame as the CPU sampler takes it: RGB float in [0, 1].
const cv::Mat& frame_rgb() {
  static const cv::Mat m = [] {
    cv::Mat rgb;
    cv::cvtColor(synthetic_frame(), rgb, cv::COLOR_BGR2RGB);
    rgb.convertTo(rgb, CV_32FC3, 1.0 / 255.0);
    return rgb;
  }();
  return m;
}

const effects::EquirectSampler& sampler(effects::SampleFilter f) {
  static std::map<effects::SampleFilter, std::unique_ptr<effects::EquirectSampler>> cache;
  auto& s = cache[f];
  if (!s)
    s = std::make_unique<effects::EquirectSampler>(
        frame_rgb(), effects::SamplerOptions{f, effects::PoleRows::Clamp});
  return *s;
}

effects::ViewCamera camera(bool quick) {
  return effects::ViewCamera::from_horizontal_fov({kLook, 0.0}, kFov, view_size(quick),
                                                  view_size(quick));
}

/// Each pixel's average over k x k bilinear level-0 samples spread over its area (RGB).
const cv::Mat& reference(bool quick) {
  static std::map<bool, cv::Mat> cache;
  cv::Mat& ref = cache[quick];
  if (!ref.empty()) return ref;
  const effects::ViewCamera cam = camera(quick);
  const effects::EquirectSampler& s = sampler(effects::SampleFilter::Bilinear);
  const int n = view_size(quick), k = supersampling(quick);
  ref = cv::Mat(n, n, CV_32FC3);
  ref.forEach<cv::Vec3f>([&](cv::Vec3f& px, const int* pos) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int b = 0; b < k; ++b)
      for (int a = 0; a < k; ++a)
        sum += s.sample(cam.ray(pos[1] + (a + 0.5) / k, pos[0] + (b + 0.5) / k).normalized());
    sum /= k * k;
    px = cv::Vec3f(static_cast<float>(sum.x()), static_cast<float>(sum.y()),
                   static_cast<float>(sum.z()));
  });
  return ref;
}

/// OpenCV's remap with precomputed maps: the frame padded by one wrapped column on each side so
/// the seam interpolates across it, as the samplers do.
struct Remap {
  cv::Mat padded, map_x, map_y;
  explicit Remap(bool quick) {
    cv::copyMakeBorder(frame_rgb(), padded, 0, 0, 1, 1, cv::BORDER_WRAP);
    const effects::ViewCamera cam = camera(quick);
    const int n = view_size(quick);
    map_x.create(n, n, CV_32FC1);
    map_y.create(n, n, CV_32FC1);
    const double w = frame_rgb().cols, h = frame_rgb().rows;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const Eigen::Vector2d uv = effects::to_equirect_uv(effects::from_unit(cam.pixel_ray(x, y)));
        map_x.at<float>(y, x) = static_cast<float>(uv.x() * w - 0.5 + 1.0);
        map_y.at<float>(y, x) = static_cast<float>(uv.y() * h - 0.5);
      }
  }
  cv::Mat run() const {
    cv::Mat out;
    cv::remap(padded, out, map_x, map_y, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
    return out;
  }
};

void cpu_case(Row& row, const Context& ctx, bool ripmap) {
  const effects::ViewCamera cam = camera(ctx.quick);
  const Remap remap(ctx.quick);
  const double t0 = now_s();
  const effects::EquirectSampler& s =
      sampler(ripmap ? effects::SampleFilter::AreaAware : effects::SampleFilter::Bilinear);
  if (ripmap) row.add("ripmap_build_s", now_s() - t0);  // once per frame, not in the view time
  cv::Mat out;
  const auto t = measure_pair({[&] { out = effects::sample_view(s, cam); }}, {[&] { remap.run(); }},
                              ctx.budget);
  row.time = t.subject;
  row.peer_time = t.peer;
  double mean = 0.0;
  row.error = steps_error(effects::sample_view(s, cam), reference(ctx.quick), &mean);
  row.add("mean_error", mean);
}

void remap_case(Row& row, const Context& ctx) {
  const Remap remap(ctx.quick);
  row.time = row.peer_time = measure({[&] { remap.run(); }}, ctx.budget);
  double mean = 0.0;
  row.error = steps_error(remap.run(), reference(ctx.quick), &mean);
  row.add("mean_error", mean);
}

void gl_case(Row& row, const Context& ctx, xr::LodMode lod) {
  const int n = view_size(ctx.quick);
  xr::VideoLayerGl video;
  video.set_frame(synthetic_frame());
  const xr::RenderView view = xr::RenderView::look_at(kLook, 0.0, kFov, n, n);
  const xr::GlTarget target(n, n, xr::TexFormat::RGBA32F), copy(n, n, xr::TexFormat::RGBA16F);
  xr::EffectStackGl copier;
  const auto t = measure_pair(gl_timed([&] { video.render(target, view, lod); }),
                              gl_timed([&] { copier.apply(target.texture(), copy, {}, 0, view); }),
                              ctx.budget);
  row.time = t.subject;
  row.peer_time = t.peer;
  row.peer = "plain textured copy of the view";
  video.render(target, view, lod);
  cv::Mat rgb;
  cv::cvtColor(target.read_float(), rgb, cv::COLOR_BGRA2RGB);
  double mean = 0.0;
  row.error = steps_error(rgb, reference(ctx.quick), &mean);
  row.add("mean_error", mean);
}

}  // namespace

void add_sampling_knobs(Registry& r, bool quick) {
  const std::string n = std::to_string(view_size(quick));
  r.knob({kKnob,
          "equirect sampling looking 80 deg up (" + n + "x" + n +
              " view, 90 deg FOV, synthetic 3840x1920 frame)",
          "view", "8-bit steps",
          "box filter over each pixel (" + std::to_string(supersampling(quick)) + "x" +
              std::to_string(supersampling(quick)) + " bilinear samples)",
          "OpenCV remap, bilinear, precomputed maps", PlotError::Rms, false});
  r.add(kKnob, "CPU bilinear", [](Row& row, const Context& ctx) { cpu_case(row, ctx, false); });
  r.add(kKnob, "CPU ripmap", [](Row& row, const Context& ctx) { cpu_case(row, ctx, true); });
  r.add(kKnob, "OpenCV remap", remap_case);
  r.add_gl(kKnob, "GL base level",
           [](Row& row, const Context& ctx) { gl_case(row, ctx, xr::LodMode::Base); });
  r.add_gl(kKnob, "GL analytic LOD",
           [](Row& row, const Context& ctx) { gl_case(row, ctx, xr::LodMode::Analytic); });
  r.add_gl(kKnob, "GL derivatives LOD",
           [](Row& row, const Context& ctx) { gl_case(row, ctx, xr::LodMode::Derivatives); });
}

}  // namespace vdfx::app::bench
