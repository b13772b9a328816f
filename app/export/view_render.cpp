#include "app/export/view_render.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "app/cli/command_registry.h"
#include "app/cli/finite_params.h"
#include "app/cli/layout_options.h"
#include "app/cli/size_limits.h"
#include "effects/distortion_mesh.h"
#include "effects/effect_shaders.h"
#include "effects/flare_render.h"
#include "effects/flare_set_cv.h"
#include "effects/grain_render.h"
#include "effects/stack_interpolator.h"
#include "effects/view_camera.h"
#include "io/excerpt.h"
#include "io/eye_picture.h"
#include "io/frame_decoder.h"
#include "io/image_write.h"
#include "io/input_error.h"
#include "io/output_path.h"
#include "io/sidecar_sets.h"
#include "xr/headset/eye_views.h"
#include "xr/headset/render_view.h"
#include "xr/render/compositor.h"
#include "xr/render/effect_stack_gl.h"
#include "xr/render/flare_gl.h"
#include "xr/render/gl_context.h"
#include "xr/render/grain_gl.h"
#include "xr/render/param_grid.h"

namespace vdfx::app {

io::Picture load_equirect_picture(const std::filesystem::path& input, std::int64_t frame,
                                  io::VideoProperties* properties) {
  io::DecoderOptions options;
  options.format = io::PixelFormat::RgbF32;
  auto decoder = io::open_frame_decoder(input, options);
  if (properties) *properties = decoder->properties();
  const std::int64_t frames = decoder->properties().frames;
  if (frame < 0 || frame >= frames)
    throw io::InputError(input.string() + ": frame " + std::to_string(frame) +
                         " does not exist (the file has " + std::to_string(frames) + " frame" +
                         (frames == 1 ? "" : "s") + ")");
  try {
    decoder->seek(frame);
  } catch (const std::exception& e) {
    throw io::InputError(input.string() + ": cannot seek to frame " + std::to_string(frame) + ": " +
                         e.what());
  }
  io::Picture picture;
  if (decoder->read_picture(picture) != io::DecodeStatus::Ok || picture.empty())
    throw io::InputError(input.string() + ": frame " + std::to_string(frame) +
                         " could not be decoded");
  return picture;
}

cv::Mat load_equirect_frame(const std::filesystem::path& input, std::int64_t frame,
                            const effects::StereoLayout& layout) {
  return io::to_rgb_by_eye(load_equirect_picture(input, frame), layout, io::PixelFormat::RgbF32);
}

xr::DistortionSettings parse_distortion(const std::string& text) {
  xr::DistortionSettings s;
  if (text == "none") {
    s.method = xr::DistortionMethod::None;
  } else if (text == "pixel") {
    s.method = xr::DistortionMethod::Pixel;
  } else if (text.starts_with("mesh:")) {
    s.method = xr::DistortionMethod::Mesh;
    const std::string n = text.substr(5);
    int value = 0;
    const auto [ptr, ec] = std::from_chars(n.data(), n.data() + n.size(), value);
    if (n.empty() || ec != std::errc() || ptr != n.data() + n.size() || value < 2 || value > 257)
      throw std::invalid_argument("'" + io::excerpt(text, 40) +
                                  "': N must be a whole number in 2..257");
    s.mesh_n = value;
  } else {
    throw std::invalid_argument("'" + io::excerpt(text, 40) + "': expected none, pixel or mesh:N");
  }
  return s;
}

cv::Mat predistort_cpu(const cv::Mat& eye_rgb, const effects::EyeLens& eye,
                       const xr::DistortionSettings& settings) {
  if (settings.method == xr::DistortionMethod::None) return eye_rgb.clone();
  std::optional<effects::DistortionMesh> mesh;
  if (settings.method == xr::DistortionMethod::Mesh)
    mesh = effects::build_distortion_mesh(eye, settings.mesh_n, settings.correct_lca);
  // One remap per channel: maps hold source pixel positions (OpenCV: pixel centres at integers);
  // invalid samples point far outside so the constant black border fills them.
  const float kOff = -1.0e6f;
  std::array<cv::Mat, 3> map_x, map_y;
  for (int c = 0; c < 3; ++c) {
    map_x[c].create(eye.height, eye.width, CV_32F);
    map_y[c].create(eye.height, eye.width, CV_32F);
  }
  const int src_w = eye_rgb.cols, src_h = eye_rgb.rows;
  cv::parallel_for_(cv::Range(0, eye.height), [&](const cv::Range& rows) {
    for (int j = rows.start; j < rows.end; ++j) {
      for (int i = 0; i < eye.width; ++i) {
        const Eigen::Vector2d px(i + 0.5, j + 0.5);
        const effects::ChannelSamples s =
            mesh ? effects::sample_mesh(*mesh, px)
                 : effects::panel_source_uv(eye, px, settings.correct_lca);
        for (int c = 0; c < 3; ++c) {
          const bool ok = s.valid[c];
          map_x[c].at<float>(j, i) = ok ? float(s.uv[c].x() * src_w - 0.5) : kOff;
          map_y[c].at<float>(j, i) = ok ? float(s.uv[c].y() * src_h - 0.5) : kOff;
        }
      }
    }
  });
  std::vector<cv::Mat> channels(3), out(3);
  cv::split(eye_rgb, channels);
  for (int c = 0; c < 3; ++c)
    cv::remap(channels[c], out[c], map_x[c], map_y[c], cv::INTER_LINEAR, cv::BORDER_CONSTANT,
              cv::Scalar(0));
  cv::Mat merged;
  cv::merge(out, merged);
  return merged;
}

namespace {

// One HMD eye: its view (the CPU path takes RenderView::camera(), the same rays) and lens.
struct EyeSetup {
  xr::RenderView view;
  effects::EyeLens lens;
};

EyeSetup eye_setup(const RenderRequest& r) {
  const xr::HmdProfile& profile = *r.hmd;
  const xr::EyeProfile& ep = profile.eye(r.eye);
  const int w = r.width > 0 ? r.width : ep.width;
  const int h = r.height > 0 ? r.height : ep.height;
  const effects::TanRect t = ep.fov.tangents();
  effects::EyeLens lens = profile.eye_lens(r.eye);
  lens.width = w;
  lens.height = h;
  xr::RenderView view;
  view.orientation = xr::view_rotation(r.look, r.roll_deg);
  view.tan_left = t.left;
  view.tan_right = t.right;
  view.tan_down = t.down;
  view.tan_up = t.up;
  return {view, lens};
}

/// Which part of each frame the view samples (docs/stereo.md).
struct EyeImage {
  effects::StereoLayout layout;
  effects::EyeIndex index = effects::EyeIndex::Left;
};

/// The sidecar's flares for a head pose at `frame` (docs/flare.md). An auto light is measured in
/// `equirect` and in the frames before it that its fit uses, so a lone frame gets the light
/// playback shows.
std::vector<effects::FlareLayout> view_flares(const std::filesystem::path& input,
                                              const io::Sidecar& sidecar, const cv::Mat& equirect,
                                              const effects::HeadPose& head, std::int64_t frame,
                                              const EyeImage& eye) {
  if (sidecar.flares.empty()) return {};
  effects::FlareSet flares = io::flare_set_of(sidecar);
  if (flares.uses_auto_light()) {
    for (std::int64_t f = std::max<std::int64_t>(0, frame - flares.auto_light_window()); f < frame;
         ++f)
      effects::observe_frame(
          flares, f,
          effects::eye_image(load_equirect_frame(input, f, eye.layout), eye.layout, eye.index));
    effects::observe_frame(flares, frame, equirect);
  }
  return flares.layouts(head, frame);
}

/// The sidecar's grain layers for a head pose at `frame`, at the request's display time (by
/// default the frame's own start, so a frame always shows the same grain: docs/grain.md).
std::vector<effects::GrainFrame> view_grains(const io::Sidecar& sidecar,
                                             const effects::HeadPose& head,
                                             const RenderRequest& r) {
  if (sidecar.grains.empty()) return {};
  effects::GrainSet grains = io::grain_set_of(sidecar);
  const std::int64_t t =
      r.display_time_ns.value_or(effects::frame_display_time_ns(r.frame, sidecar.video.fps));
  return grains.layout(head, t, r.frame);
}

}  // namespace

std::optional<std::size_t> first_gpu_only_grain(const io::Sidecar& sidecar) {
  for (std::size_t i = 0; i < sidecar.grains.size(); ++i)
    if (effects::is_volumetric(sidecar.grains[i].style)) return i;
  return std::nullopt;
}

namespace {

/// What the CPU and the GPU paths share: the frame, the parameters at the view centre (and the
/// checked evaluation per direction), the camera and the world-space layers.
struct ViewScene {
  cv::Mat frame;     //!< the whole frame (both eyes of stereo video)
  cv::Mat equirect;  //!< the eye's image (the whole frame for mono video)
  EyeImage eye_image;
  std::function<effects::StackParams(const effects::Direction&)> evaluate;
  effects::StackParams view_params;
  std::optional<EyeSetup> eye;
  int w = 0, h = 0;
  xr::RenderView view;
  std::vector<effects::FlareLayout> flares;
  std::vector<effects::GrainFrame> grains;
};

ViewScene view_scene(const std::filesystem::path& input, const io::Sidecar& sidecar,
                     const effects::StackInterpolator& stack, const RenderRequest& r,
                     cv::Mat equirect, const EyeImage& eye) {
  ViewScene s;
  s.equirect = std::move(equirect);
  s.eye_image = eye;
  // Every evaluation goes through this check: view mode once, per-pixel mode per cell or pixel.
  // One frame: the anchored effects' centres are turned for it once (effects::StackAtFrame).
  s.evaluate = [at = std::make_shared<const effects::StackAtFrame>(stack, r.frame),
                &r](const effects::Direction& d) {
    effects::StackParams p = at->evaluate(d);
    require_finite(p, r.sidecar_name, d, r.frame);
    return p;
  };
  s.view_params = s.evaluate(r.look);
  if (r.hmd) s.eye = eye_setup(r);
  s.w = s.eye ? s.eye->lens.width : r.width;
  s.h = s.eye ? s.eye->lens.height : r.height;
  s.view = s.eye ? s.eye->view : xr::RenderView::look_at(r.look, r.roll_deg, r.hfov_deg, s.w, s.h);
  // The head sits at the origin looking at the view; an HMD eye is half the IPD to its side
  // (the video ignores that, flares do not: docs/flare.md, "Stereo").
  const effects::HeadPose head{Eigen::Vector3d::Zero(), xr::view_rotation(r.look, r.roll_deg)};
  if (s.eye)
    s.view.position =
        head.orientation *
        Eigen::Vector3d((r.eye == xr::Eye::Left ? -0.5 : 0.5) * r.hmd->ipd_m, 0.0, 0.0);
  s.flares = view_flares(input, sidecar, s.equirect, head, r.frame, eye);
  s.grains = view_grains(sidecar, head, r);
  return s;
}

/// Sizes beyond what this GL implementation takes are refused before any texture exists (they
/// were GL errors, reported as internal).
void check_gpu_sizes(const std::filesystem::path& input, const cv::Mat& equirect,
                     const xr::GlContext& context, const RenderRequest& r) {
  const int max_side = context.max_image_side();
  if (equirect.cols > max_side || equirect.rows > max_side)
    throw io::InputError(input.string() + ": the frame is " + std::to_string(equirect.cols) + "x" +
                         std::to_string(equirect.rows) + "; this GL implementation (" +
                         context.renderer() + ") takes at most " + std::to_string(max_side) +
                         " pixels per side (render without --gpu)");
  if (r.bake_width > max_side || r.bake_height > max_side)
    throw UsageError("--bake " + std::to_string(r.bake_width) + "x" +
                     std::to_string(r.bake_height) + ": this GL implementation takes at most " +
                     std::to_string(max_side) + " per side");
}

/// The blurred area (the view and the blur's margin) must fit the GL implementation and the
/// GPU render limit.
void check_gpu_area(int w, int h, int margin, int max_side) {
  const std::int64_t area_w = w + 2 * margin, area_h = h + 2 * margin;
  if (area_w > max_side || area_h > max_side || area_w * area_h > kGpuRenderLimit.max_pixels)
    throw UsageError(
        "--size " + std::to_string(w) + "x" + std::to_string(h) + ": with the blur's margin of " +
        std::to_string(margin) + " pixels the GPU renders " + std::to_string(area_w) + "x" +
        std::to_string(area_h) + "; it takes at most " + std::to_string(max_side) +
        " per side (this GL implementation) and " + std::to_string(kGpuRenderLimit.max_pixels) +
        " pixels (" + kGpuRenderLimit.example + ") in all");
}

/// Through the GL compositor (offscreen); 8-bit RGB.
cv::Mat render_gpu(const std::filesystem::path& input, const ViewScene& s, const RenderRequest& r) {
  auto context = xr::GlContext::create({});
  check_gpu_sizes(input, s.frame, *context, r);
  cv::Mat bgr_in;
  cv::cvtColor(s.frame, bgr_in, cv::COLOR_RGB2BGR);
  xr::GpuViewOptions options;
  options.layout = s.eye_image.layout;  // the compositor cuts the eye's image itself
  // (Mono keeps slot 0 for either HMD eye, as before: the eye's view and lens say which eye.)
  options.eye = s.eye_image.layout.stereo() && s.eye_image.index == effects::EyeIndex::Right;
  options.distortion = r.distortion;
  if (s.eye) options.lens = s.eye->lens.lens;
  options.blur = r.blur;
  xr::FlareGl flare_layer;
  flare_layer.set_layouts(s.flares);
  xr::GrainGl grain_layer;
  grain_layer.set_layers(s.grains);
  const std::array<xr::EyeLayer*, 2> layers{&flare_layer, &grain_layer};
  options.layers = layers;
  unsigned mask = effects::non_neutral_mask(s.view_params);
  std::optional<xr::ParamGrid> grid;
  if (r.mode == effects::RenderMode::Pixel) {
    // Per-pixel mode: the parameters baked on an equirect grid, read along each pixel's ray;
    // an effect neutral in every cell is not compiled in.
    grid = xr::bake_param_grid(s.evaluate, r.bake_width, r.bake_height);
    mask = 0;
    for (const effects::StackParams& p : grid->cells) mask |= effects::non_neutral_mask(p);
    options.param_grid = &*grid;
  }
  effects::StackParams widest = s.view_params;
  if (grid) widest.blur_sigma_deg = grid->max_blur_sigma_deg();
  check_gpu_area(s.w, s.h, xr::blur_margin(widest, mask, s.view, s.w, s.h),
                 context->max_image_side());
  const cv::Mat bgr = xr::render_view_gpu(bgr_in, s.view, s.w, s.h, s.view_params, mask, options);
  cv::Mat rgb;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  return rgb;
}

/// The CPU reference: RGB float, unclamped.
cv::Mat render_cpu(const ViewScene& s, const RenderRequest& r) {
  const effects::ViewCamera camera = s.view.camera(s.w, s.h);
  const effects::EquirectSampler sampler(s.equirect,
                                         effects::sampler_options_for(s.eye_image.layout));
  cv::Mat rendered;
  if (r.mode == effects::RenderMode::View) {
    rendered = effects::render_view(sampler, camera, s.view_params);
  } else {
    const effects::ParamsAt at = s.evaluate;
    rendered = effects::render_view(sampler, camera, at, effects::RenderMode::Pixel);
  }
  effects::add_flares(rendered, camera, s.view.position, s.flares);
  for (const effects::GrainFrame& g : s.grains) {
    if (effects::is_volumetric(g.style))
      throw std::invalid_argument("grain style " + std::string(effects::grain_style_name(g.style)) +
                                  " renders on the GPU only (--gpu)");
    effects::composite_shader_grain(rendered, g, s.view.orientation, s.view.position,
                                    s.view.tangents());
  }
  if (s.eye && r.distortion.method != xr::DistortionMethod::None)
    rendered = predistort_cpu(rendered, s.eye->lens, r.distortion);
  return rendered;
}

}  // namespace

namespace {

/// The frame's layout (command line, stream tags, sidecar) and the eye the request shows.
EyeImage eye_image_of(const io::VideoProperties& video, const io::Sidecar& sidecar,
                      const RenderRequest& r) {
  EyeImage eye;
  eye.layout = shown_layout(video, r.layout, &sidecar.video, r.sidecar_name);
  if (r.eye_given && !r.hmd && !eye.layout.stereo())
    throw UsageError("--eye: needs --hmd or a stereo video (" + video.path.string() +
                     " is mono; --layout says otherwise)");
  eye.index = r.eye == xr::Eye::Right ? effects::EyeIndex::Right : effects::EyeIndex::Left;
  return eye;
}

}  // namespace

cv::Mat render_request(const std::filesystem::path& input, const io::Sidecar& sidecar,
                       const RenderRequest& r) {
  io::VideoProperties video;
  const io::Picture picture = load_equirect_picture(input, r.frame, &video);
  const EyeImage eye = eye_image_of(video, sidecar, r);
  // Each eye's image converted from its own planes (no chroma from the other eye's half).
  const cv::Mat frame = io::to_rgb_by_eye(picture, eye.layout, io::PixelFormat::RgbF32);
  const effects::StackInterpolator stack = io::stack_of(sidecar);
  ViewScene scene =
      view_scene(input, sidecar, stack, r, effects::eye_image(frame, eye.layout, eye.index), eye);
  scene.frame = frame;
  if (r.gpu) return render_gpu(input, scene, r);
  return effects::to_rgb8(render_cpu(scene, r));
}

cv::Size render_to_png(const std::filesystem::path& input,
                       const std::filesystem::path& sidecar_path, const RenderRequest& request,
                       const std::filesystem::path& out) {
  // Before any work: an --out that would destroy an input, or a device, is refused up front.
  std::vector<io::NamedInput> inputs = {{"INPUT", input}, {"--sidecar", sidecar_path}};
  if (request.hmd) inputs.push_back({"--hmd", request.hmd->source});
  io::check_output_is_not_input("--out", out, inputs);
  io::resolve_output_path(out);
  const io::Sidecar sidecar = io::read_sidecar(sidecar_path);
  if (const auto g = first_gpu_only_grain(sidecar); g && !request.gpu)
    throw UsageError(sidecar_path.string() + ": grain #" + std::to_string(*g + 1) + " (" +
                     std::string(effects::grain_style_name(sidecar.grains[*g].style)) +
                     ") is volumetric and renders on the GPU only: add --gpu");
  const cv::Mat rgb8 = render_request(input, sidecar, request);
  cv::Mat bgr;
  cv::cvtColor(rgb8, bgr, cv::COLOR_RGB2BGR);
  io::write_png(out, bgr);
  return rgb8.size();
}

}  // namespace vdfx::app
