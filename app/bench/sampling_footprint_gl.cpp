/// @file
/// @brief `vdfx bench` knob sampling.footprint: views that shrink the panorama, each pixel the
/// synthetic 4K frame filtered over its footprint (effects/pixel_footprint.h) with at most N taps
/// along the major axis, on the CPU and the GPU, beside point sampling (CPU) and the GPU's
/// previous isotropic mipmapping, against the supersampled truth (the view at 8x the size,
/// area-averaged down).
#include <cmath>
#include <map>
#include <memory>
#include <opencv2/imgproc.hpp>

#include "app/bench/gl_rows.h"
#include "app/bench/inputs.h"
#include "effects/equirect_sampler.h"
#include "effects/view_renderer.h"
#include "xr/render/video_layer.h"

namespace vdfx::app::bench {
namespace {

constexpr const char* kKnob = "sampling.footprint";
constexpr int kTruthScale = 8;

/// The views of the issue that shrink a panorama most: straight down with a wide field of view,
/// and 60 degrees down with a normal one.
struct ShrinkView {
  const char* name;
  effects::Direction look;
  double fov;
};
const ShrinkView kViews[] = {{"nadir, 120 deg", {0, -90}, 120}, {"down 60, 60 deg", {0, -60}, 60}};

cv::Size view_size(bool quick) {
  return quick ? cv::Size(160, 120) : cv::Size(320, 240);
}

xr::RenderView render_view(const ShrinkView& v, bool quick) {
  return xr::RenderView::look_at(v.look, 0.0, v.fov, view_size(quick).width,
                                 view_size(quick).height);
}
effects::ViewCamera camera(const ShrinkView& v, bool quick) {
  return render_view(v, quick).camera(view_size(quick).width, view_size(quick).height);
}

/// The CPU samplers: point sampling, and one footprint sampler at a time (its mip chain of the 4K
/// frame is 120 MB; rows of one N follow each other). *build_s: the chain's build time, when built.
const effects::EquirectSampler& sampler(effects::SampleFilter filter, double max_anisotropy,
                                        double* build_s = nullptr) {
  static std::unique_ptr<effects::EquirectSampler> point, footprint;
  auto& s = filter == effects::SampleFilter::Bilinear ? point : footprint;
  if (!s || s->options().max_anisotropy != max_anisotropy) {
    s.reset();
    const double t0 = now_s();
    s = std::make_unique<effects::EquirectSampler>(
        synthetic_frame_rgb(),
        effects::SamplerOptions{filter, effects::PoleRows::Clamp, 360, max_anisotropy});
    if (build_s) *build_s = now_s() - t0;
  }
  return *s;
}

/// The truth: each pixel the mean of 8 x 8 level-0 bilinear samples over its square.
const cv::Mat& truth(const ShrinkView& v, bool quick) {
  static std::map<std::pair<const ShrinkView*, bool>, cv::Mat> cache;
  cv::Mat& t = cache[{&v, quick}];
  if (!t.empty()) return t;
  t = supersampled_view(sampler(effects::SampleFilter::Bilinear, 1.0), camera(v, quick),
                        kTruthScale);
  return t;
}

/// Mean taps per pixel of the footprint filter at `max_anisotropy` over the view.
double mean_taps(const ShrinkView& v, bool quick, double max_anisotropy) {
  const effects::ViewCamera cam = camera(v, quick);
  const Eigen::Matrix3d& rot = cam.camera_to_world();
  const Eigen::Vector3d ex = rot.col(0) / cam.fx(), ey = -rot.col(1) / cam.fy();
  const double w = synthetic_frame_rgb().cols, h = synthetic_frame_rgb().rows;
  double sum = 0.0;
  for (int j = 0; j < cam.height(); ++j)
    for (int i = 0; i < cam.width(); ++i) {
      const Eigen::Vector2d t = cam.tangent(i + 0.5, j + 0.5);
      const Eigen::Vector3d d = rot * Eigen::Vector3d(t.x(), t.y(), -1.0);
      const effects::FootprintTaps taps =
          effects::footprint_taps(effects::equirect_jacobian(d, ex, ey, {w, h}), max_anisotropy, w);
      sum += 2 * taps.half_count + 1;
    }
  return sum / (cam.width() * cam.height());
}

void set_error(Row& row, const cv::Mat& rgb, const ShrinkView& v, bool quick) {
  double mean = 0.0;
  row.error = steps_error(rgb, truth(v, quick), &mean);
  row.add("mean_error", mean);
  row.series = v.name;
}

/// CPU: point sampling (N = 0) or the footprint filter with at most N taps' stretch.
void cpu_case(Row& row, const Context& ctx, const ShrinkView& v, double n) {
  const effects::ViewCamera cam = camera(v, ctx.quick);
  double build_s = kNaN;
  const effects::EquirectSampler& point = sampler(effects::SampleFilter::Bilinear, 1.0);
  const effects::EquirectSampler& s =
      n > 0 ? sampler(effects::SampleFilter::Footprint, n, &build_s) : point;
  cv::Mat out;
  const auto t = measure_pair({[&] { out = effects::sample_view(s, cam); }},
                              {[&] { effects::sample_view(point, cam); }}, ctx.budget);
  row.time = t.subject;
  row.peer_time = t.peer;
  row.peer = "CPU point sampling (bilinear at the pixel centre)";
  if (n > 0) {
    if (std::isfinite(build_s)) row.add("mip_chain_build_s", build_s);
    row.add("mean_taps", mean_taps(v, ctx.quick, n));
  }
  set_error(row, out, v, ctx.quick);
}

/// GPU: the video layer in `mode` (footprint with at most N taps' stretch), timed beside the
/// previous default, the isotropic mip level of textureGrad.
void gl_case(Row& row, const Context& ctx, const ShrinkView& v, xr::LodMode mode, double n) {
  const cv::Size size = view_size(ctx.quick);
  xr::VideoLayerGl video;
  video.set_frame(synthetic_frame());
  if (n > 0) video.set_max_anisotropy(n);
  xr::VideoLayerGl old;
  old.set_frame(synthetic_frame());
  const xr::RenderView view = render_view(v, ctx.quick);
  const xr::GlTarget target(size.width, size.height, xr::TexFormat::RGBA32F);
  const xr::GlTarget peer(size.width, size.height, xr::TexFormat::RGBA32F);
  const auto t =
      measure_pair(gl_timed([&] { video.render(target, view, mode); }),
                   gl_timed([&] { old.render(peer, view, xr::LodMode::Analytic); }), ctx.budget);
  row.time = t.subject;
  row.peer_time = t.peer;
  row.peer = "GPU isotropic mip level (textureGrad, analytic Jacobian: the previous default)";
  video.render(target, view, mode);
  cv::Mat rgb;
  cv::cvtColor(target.read_float(), rgb, cv::COLOR_BGRA2RGB);
  if (mode == xr::LodMode::Footprint) row.add("mean_taps", mean_taps(v, ctx.quick, n));
  set_error(row, rgb, v, ctx.quick);
}

std::string n_setting(const char* side, double n) {
  return std::string(side) + " footprint N=" + std::to_string(static_cast<int>(n));
}

}  // namespace

void add_sampling_footprint_knobs(Registry& r, bool quick) {
  const cv::Size s = view_size(quick);
  r.knob({kKnob,
          "views that shrink the panorama (" + std::to_string(s.width) + "x" +
              std::to_string(s.height) +
              ", synthetic 3840x1920 frame): at most N taps along each pixel's footprint",
          "view", "8-bit steps",
          "the view at " + std::to_string(kTruthScale) +
              "x the size, area-averaged down (bilinear samples)",
          "CPU point sampling (CPU rows); the GPU's previous isotropic mip level (GL rows)",
          PlotError::Rms, false});
  const std::vector<double> cpu_n = quick ? std::vector<double>{16} : std::vector<double>{1, 4, 16};
  const std::vector<double> gl_n =
      quick ? std::vector<double>{1, 16} : std::vector<double>{1, 2, 4, 8, 16, 32};
  for (const ShrinkView& v : kViews) {
    if (quick && &v != &kViews[0]) continue;
    const std::string at = std::string(" (") + v.name + ")";
    r.add(kKnob, "CPU point" + at, [&v](Row& row, const Context& c) { cpu_case(row, c, v, 0); });
    for (double n : cpu_n)
      r.add(kKnob, n_setting("CPU", n) + at,
            [&v, n](Row& row, const Context& c) { cpu_case(row, c, v, n); });
    r.add_gl(kKnob, "GL isotropic mip" + at,
             [&v](Row& row, const Context& c) { gl_case(row, c, v, xr::LodMode::Analytic, 0); });
    for (double n : gl_n)
      r.add_gl(kKnob, n_setting("GL", n) + at, [&v, n](Row& row, const Context& c) {
        gl_case(row, c, v, xr::LodMode::Footprint, n);
      });
  }
}

}  // namespace vdfx::app::bench
