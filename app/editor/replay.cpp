/// @file
/// @brief run_replay: recording -> replay backend -> Editor -> sidecar (+ PNG frames).
#include "app/editor/replay.h"

#include <algorithm>
#include <cstdio>
#include <opencv2/imgproc.hpp>

#include "app/editor/editor.h"
#include "app/editor/editor_layers.h"
#include "effects/equirect_sampler.h"
#include "effects/flare_render.h"
#include "effects/flare_set_cv.h"
#include "effects/grain_render.h"
#include "effects/view_renderer.h"
#include "io/file_lock.h"
#include "io/frame_decoder.h"
#include "io/image_write.h"
#include "io/input_error.h"
#include "io/output_path.h"
#include "io/recording.h"
#include "io/sidecar_target.h"
#include "io/video_match.h"
#include "ui/interaction.h"
#include "xr/headset/render_view.h"
#include "xr/input/input_backend.h"

namespace vdfx::app {

namespace fs = std::filesystem;

namespace {

/// Bilinear sample of a premultiplied RGBA8 image at continuous pixel position (x, y).
cv::Vec4f sample_bilinear(const cv::Mat& img, double x, double y) {
  const double fx = std::clamp(x - 0.5, 0.0, img.cols - 1.0);
  const double fy = std::clamp(y - 0.5, 0.0, img.rows - 1.0);
  const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
  const int x1 = std::min(x0 + 1, img.cols - 1), y1 = std::min(y0 + 1, img.rows - 1);
  const double ax = fx - x0, ay = fy - y0;
  cv::Vec4f out;
  for (int c = 0; c < 4; ++c) {
    const double top = img.at<cv::Vec4b>(y0, x0)[c] * (1 - ax) + img.at<cv::Vec4b>(y0, x1)[c] * ax;
    const double bot = img.at<cv::Vec4b>(y1, x0)[c] * (1 - ax) + img.at<cv::Vec4b>(y1, x1)[c] * ax;
    out[c] = static_cast<float>(top * (1 - ay) + bot * ay);
  }
  return out;
}

/// On-screen width of the panel in output pixels (0 when it cannot be projected).
double screen_width(const effects::ViewCamera& camera, const glm::dvec3& eye, const ui::Panel& p,
                    cv::Size tex) {
  const auto at = [&](double x) -> std::optional<Eigen::Vector2d> {
    const glm::dvec3 w = p.world_of_pixel({x, tex.height * 0.5}) - eye;
    return camera.project(Eigen::Vector3d(w.x, w.y, w.z));
  };
  const auto a = at(0.0), b = at(tex.width);
  return a && b ? (*a - *b).norm() : 0.0;
}

}  // namespace

void overlay_panels(cv::Mat& rgb8, const effects::ViewCamera& camera, const glm::dvec3& eye,
                    const std::vector<ui::Panel*>& panels) {
  for (ui::Panel* p : panels) {
    if (!p->visible()) continue;
    // Panels render at about 4000 px/m, far finer than a small frame: shrink the texture to its
    // on-screen size with an area filter first, then sample bilinearly, so text stays smooth
    // instead of aliasing.
    const cv::Mat& full = p->texture();
    const double on_screen = screen_width(camera, eye, *p, full.size());
    const double scale = on_screen > 1.0 ? std::min(1.0, on_screen / full.cols) : 1.0;
    cv::Mat tex = full;
    if (scale < 1.0) cv::resize(full, tex, cv::Size(), scale, scale, cv::INTER_AREA);
    for (int j = 0; j < rgb8.rows; ++j) {
      auto* row = rgb8.ptr<cv::Vec3b>(j);
      for (int i = 0; i < rgb8.cols; ++i) {
        const Eigen::Vector3d d = camera.pixel_ray(i, j);
        const auto hit = ui::intersect_panel_plane(*p, {eye, {d.x(), d.y(), d.z()}});
        if (!hit || !hit->front || !hit->inside) continue;
        const cv::Vec4f s = sample_bilinear(tex, hit->pixel.x * tex.cols / full.cols,
                                            hit->pixel.y * tex.rows / full.rows);
        for (int c = 0; c < 3; ++c)  // premultiplied "over"
          row[i][c] = cv::saturate_cast<uchar>(s[c] + row[i][c] * (255.0f - s[3]) / 255.0f);
      }
    }
  }
}

namespace {

/// The editor's layout for a recording: the sim's were made with the desktop layout (panels in
/// front of the head), in the view their header names (older ones: 1280 x 720 at 90 degrees).
EditorOptions editor_options_for(const io::RecordingHeader& header) {
  EditorOptions eo;
  if (header.desktop || header.hmd == "sim") {
    eo.layout = PanelLayout::Desktop;
    const io::RecordedDesktopView v =
        header.desktop.value_or(io::RecordedDesktopView{1280, 720, 90.0});
    eo.viewport = {v.width, v.height, v.hfov_deg};
  } else {
    eo.layout = PanelLayout::Hands;
  }
  return eo;
}

/// Video frame `frame` as RGB float (a still: its only frame).
cv::Mat decode_frame(io::FrameDecoder& decoder, const fs::path& video, std::int64_t frame) {
  decoder.seek(decoder.properties().is_still ? 0 : frame);
  cv::Mat image;
  if (decoder.read(image) != io::DecodeStatus::Ok)
    throw io::InputError(video.string() + ": frame " + std::to_string(frame) +
                         " could not be decoded");
  if (image.type() != CV_32FC3) image.convertTo(image, CV_32FC3, 1.0 / 255.0);
  return image;
}

/// What the editor's window shows at display time t_ns, on the CPU, as 8-bit BGR: the head view
/// with the editor's parameters, then the flares and shader grain as the window draws them (laid
/// out from the head, which looks along the view as the camera does), then the panels.
cv::Mat render_replay_frame(Editor& editor, EditorLayers& layers, const cv::Mat& image,
                            const effects::StereoLayout& layout, std::int64_t frame,
                            std::int64_t t_ns, const ReplayOptions& o, ReplayResult& result) {
  effects::EquirectSampler sampler(image, effects::sampler_options_for(layout));
  const auto camera = effects::ViewCamera::from_horizontal_fov({editor.view_direction(), 0.0},
                                                               o.hfov_deg, o.width, o.height);
  cv::Mat rendered = effects::render_view(sampler, camera, editor.current_params());
  const xr::RenderView view =
      xr::RenderView::look_at(editor.view_direction(), 0.0, o.hfov_deg, o.width, o.height);
  const glm::dvec3 p = editor.input().head.position;
  const effects::HeadPose head{Eigen::Vector3d(p.x, p.y, p.z), view.orientation};
  layers.update(editor);
  if (layers.flares().uses_auto_light()) effects::observe_frame(layers.flares(), frame, image);
  effects::add_flares(rendered, camera, head.position, layers.flares().layouts(head, frame));
  for (const effects::GrainFrame& g : layers.grains().layout(head, t_ns, frame)) {
    if (!effects::is_volumetric(g.style)) {
      effects::composite_shader_grain(rendered, g, view.orientation, head.position,
                                      view.tangents());
      continue;
    }
    const std::string note = "grain style " + std::string(effects::grain_style_name(g.style)) +
                             " is drawn on the GPU only: not in the replay's frames";
    if (std::find(result.messages.begin(), result.messages.end(), note) == result.messages.end())
      result.messages.push_back(note);
  }
  cv::Mat rgb8 = effects::to_rgb8(rendered);
  overlay_panels(rgb8, camera, editor.input().head.position, editor.panels());
  cv::Mat bgr;
  cv::cvtColor(rgb8, bgr, cv::COLOR_RGB2BGR);
  return bgr;
}

/// The layout the editor shows (docs/stereo.md), recorded in `sidecar` as `vdfx edit` records
/// it; a stereo-shaped untagged frame's hint joins the messages.
effects::StereoLayout replay_layout(const io::VideoProperties& props, const ReplayOptions& o,
                                    const std::optional<fs::path>& base, io::Sidecar& sidecar,
                                    ReplayResult& result) {
  std::string hint;
  const effects::StereoLayout layout =
      io::resolve_video_layout(props, o.layout, &sidecar.video, base.value_or(fs::path()), &hint);
  if (!hint.empty()) result.messages.push_back(props.path.string() + ": " + hint);
  if (base)
    if (std::string w = io::video_mismatch(props, sidecar.video, *base); !w.empty())
      result.messages.push_back("warning: " + w);
  io::record_layout(sidecar.video, layout);
  return layout;
}

/// The files an output must never replace, --sidecar-out checked against them and against an
/// editor holding it (io::resolve_sidecar_target), before any work.
std::vector<io::NamedInput> checked_inputs(const ReplayOptions& o, io::SidecarTarget& target) {
  std::vector<io::NamedInput> inputs = {{"recording", o.recording}, {"--video", o.video}};
  target = io::resolve_sidecar_target({o.sidecar_in, o.sidecar_out, o.force}, inputs, o.log_prefix);
  if (target.base) inputs.push_back({"--sidecar-in", *target.base});
  return inputs;
}

/// The timeline samples after which a --frames image is taken, evenly over the timeline (none
/// without --frames); the folder is made.
std::vector<std::size_t> shot_samples(const ReplayOptions& o, std::size_t samples) {
  std::vector<std::size_t> shots;
  if (!o.frames_dir || samples == 0) return shots;
  std::error_code ec;
  fs::create_directories(*o.frames_dir, ec);
  if (ec || !fs::is_directory(*o.frames_dir))
    throw io::InputError("--frames " + o.frames_dir->string() + ": cannot create the folder" +
                         (ec ? " (" + ec.message() + ")" : " (a file of that name exists)"));
  const int n = std::max(1, o.frame_images);
  for (int k = 1; k <= n; ++k)
    shots.push_back((samples - 1) * static_cast<std::size_t>(k) / static_cast<std::size_t>(n));
  return shots;
}

/// What a replay renders its --frames from: the video, its layout and the files not to replace.
struct ShotSource {
  io::FrameDecoder& decoder;
  effects::StereoLayout layout;
  const std::vector<io::NamedInput>& inputs;
};

/// --frames image number `index`: the editor's frame at display time t_ns (the desktop view's
/// eye: the left one of stereo video), written and listed in `result`.
void write_shot(Editor& editor, EditorLayers& layers, const ShotSource& src, std::size_t index,
                std::int64_t t_ns, const ReplayOptions& o, ReplayResult& result) {
  const std::int64_t last = std::max<std::int64_t>(0, src.decoder.properties().frames - 1);
  const std::int64_t frame = std::clamp<std::int64_t>(editor.frame(), 0, last);
  const cv::Mat image = effects::eye_image(decode_frame(src.decoder, o.video, frame), src.layout,
                                           effects::EyeIndex::Left);
  const cv::Mat bgr =
      render_replay_frame(editor, layers, image, src.layout, frame, t_ns, o, result);
  char name[64];
  std::snprintf(name, sizeof name, "replay_%03zu.png", index);
  const fs::path out = *o.frames_dir / name;
  io::check_output_is_not_input("--frames", out, src.inputs);
  io::write_png(out, bgr, io::OutputName::Generated);
  result.images.push_back(out);
}

}  // namespace

ReplayResult run_replay(const ReplayOptions& o) {
  ReplayResult result;
  io::SidecarTarget target;
  const std::vector<io::NamedInput> inputs = checked_inputs(o, target);
  io::Recording rec = io::read_recording(o.recording);
  for (const auto& w : rec.warnings) result.messages.push_back(w);

  io::DecoderOptions dec_opts;
  dec_opts.format = io::PixelFormat::RgbF32;
  auto decoder = io::open_frame_decoder(o.video, dec_opts);
  const auto& props = decoder->properties();
  io::Sidecar sidecar = io::read_sidecar_base(
      target,
      io::new_sidecar({o.video.string(), props.fps.value(), std::max<std::int64_t>(1, props.frames),
                       props.width, props.height}));
  const std::string note = io::sidecar_target_note(target, o.sidecar_out, sidecar);
  if (!note.empty()) result.messages.push_back(note);
  const ShotSource src{*decoder, replay_layout(props, o, target.base, sidecar, result), inputs};
  EditorOptions eo = editor_options_for(rec.header);
  eo.video = o.video;
  eo.async_suggestions = false;  // a suggestion lands in the update that asked for it
  Editor editor(sidecar, DocumentOptions{{.async = false}}, eo);

  auto backend = xr::create_replay_backend(std::move(rec), {});
  const auto timeline = backend->timeline();
  const std::vector<std::size_t> shots = shot_samples(o, timeline.size());
  std::size_t next_shot = 0;
  EditorLayers layers;  // the document's flares and grain, drawn into the frames
  for (std::size_t i = 0; i < timeline.size(); ++i) {
    editor.update(backend->poll(timeline[i]), timeline[i]);
    for (; next_shot < shots.size() && shots[next_shot] == i; ++next_shot)
      write_shot(editor, layers, src, next_shot, timeline[i], o, result);
  }
  result.samples = timeline.size();
  result.sidecar = editor.document().sidecar();
  io::write_sidecar(o.sidecar_out, result.sidecar);
  return result;
}

}  // namespace vdfx::app
