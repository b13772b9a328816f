/// @file
/// @brief FrameLoop: window, session timing, input, decode, parameters, compositor, mirror.
#include "app/frame_loop.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#ifdef VDFX_WITH_GL
#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <iostream>
#include <optional>
#include <thread>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "app/frame_loop_stats.h"
#include "app/glfw_input_glue.h"
#include "effects/effect_shaders.h"
#include "io/image_write.h"
#include "io/input_error.h"
#include "io/video_source.h"
#include "xr/compositor.h"
#include "xr/gl_context.h"
#include "xr/input_backend.h"
#include "xr/param_grid.h"
#include "xr/session.h"
#endif

namespace vdfx::app {

std::string frame_loop_keys_text() {
  return "  1                         mirror: pre-distorted panels (both eyes, as the displays show them)\n"
         "  2                         mirror: through the lens (both eyes, as the wearer sees them)\n"
         "  3                         mirror: single eye (left eye buffer, undistorted)\n"
         "  Escape                    quit (closing the window too)\n";
}

#ifdef VDFX_WITH_GL

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

effects::Direction head_direction(const xr::InputState& in) {
  const glm::dvec3 f = xr::forward(in.head);
  return effects::from_unit(Eigen::Vector3d(f.x, f.y, f.z));
}

}  // namespace

struct FrameLoop::Impl {
  FrameLoopOptions o;
  xr::InputBackend& input;
  io::VideoSource& video;
  FrameClient& client;
  std::unique_ptr<xr::GlContext> gl;
  std::unique_ptr<GlfwInputGlue> glue;
  std::unique_ptr<xr::Compositor> compositor;
  xr::MirrorMode mirror = xr::MirrorMode::PreDistorted;

  // What is on screen: the decoded frame, and the parameter grid baked for it (per-pixel mode).
  std::optional<io::VideoFrame> shown;
  bool uploaded_any = false;
  bool grid_valid = false;
  std::int64_t grid_frame = -1;
  std::uint64_t grid_revision = 0;
  int geometry_w = 0, geometry_h = 0;

  Impl(FrameLoopOptions opts, xr::InputBackend& in, io::VideoSource& v, FrameClient& c)
      : o(std::move(opts)), input(in), video(v), client(c) {
    if (!(o.eye_scale > 0.0 && o.eye_scale <= 4.0))
      throw io::InputError("--scale must be in (0, 4], got " + std::to_string(o.eye_scale));
    xr::GlContextOptions g;
    g.width = o.window_width;
    g.height = o.window_height;
    g.visible = o.visible;
    g.vsync = o.vsync;
    g.title = "vdfx";
    gl = xr::GlContext::create(g);
    glue = std::make_unique<GlfwInputGlue>(gl->window());
    xr::CompositorConfig cc;
    const xr::EyeProfile& eye = o.profile.eye(xr::Eye::Left);
    cc.eye_width = std::max(8, static_cast<int>(std::lround(eye.width * o.eye_scale)));
    cc.eye_height = std::max(8, static_cast<int>(std::lround(eye.height * o.eye_scale)));
    cc.lens = effects::LensModel(o.profile.lens);
    cc.gpu_timing = o.stats;
    cc.blur = o.blur;
    compositor = std::make_unique<xr::Compositor>(cc);
    mirror = static_cast<xr::MirrorMode>(std::clamp(o.mirror_mode, 0, 2));
  }

  /// Uploads the shown frame as it is decoded.
  void upload(FrameLoopStats& stats) {
    const auto t0 = Clock::now();
    cv::Mat bgr;
    cv::cvtColor(shown->image, bgr, cv::COLOR_RGB2BGR);
    compositor->set_video_frame(bgr);
    stats.add_cpu("upload", ms_since(t0));
    uploaded_any = true;
  }

  /// Per-pixel mode: bakes the client's parameters on the grid for the shown frame and uploads
  /// it; the effect shader reads it per pixel (all six effects).
  void bake(std::int64_t frame, FrameLoopStats& stats) {
    const auto t0 = Clock::now();
    const xr::ParamGrid grid = xr::bake_param_grid(
        [&](const effects::Direction& d) { return client.params(d, frame); }, o.bake_width,
        o.bake_height);
    compositor->set_param_grid(grid);
    stats.add_cpu("bake", ms_since(t0));
    grid_valid = true;
    grid_frame = frame;
    grid_revision = client.params_revision();
  }

  void handle_loop_key(const xr::DesktopEvent& e, bool& quit) {
    const auto* k = std::get_if<xr::KeyEvent>(&e);
    if (!k || !k->pressed) return;
    switch (k->key) {
      case xr::Key::Num1: mirror = xr::MirrorMode::PreDistorted; break;
      case xr::Key::Num2: mirror = xr::MirrorMode::ThroughTheLens; break;
      case xr::Key::Num3: mirror = xr::MirrorMode::SingleEye; break;
      case xr::Key::Escape: quit = true; break;
      default: break;
    }
  }

  void write_screenshot() {
    int w = 0, h = 0;
    gl->framebuffer_size(&w, &h);
    if (!o.visible || w <= 0 || h <= 0) {
      w = o.window_width;
      h = o.window_height;
    }
    xr::GlTarget target(w, h, xr::TexFormat::RGBA8);
    compositor->draw_mirror(mirror, &target, w, h);
    const cv::Mat bgr = xr::to_bgr8(target.read_float());
    io::write_png(o.screenshot, bgr);
  }

  FrameLoopResult run() {
    FrameLoopResult result;
    FrameLoopStats stats;
    std::ostream& out = o.stats_out ? *o.stats_out : std::cout;
    const std::vector<std::int64_t> timeline = input.timeline();
    const bool replay = !timeline.empty();
    const auto wall0 = Clock::now();
    auto last_stats = wall0, last_title = wall0;
    const auto now_ns = [&] {
      return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - wall0).count();
    };

    xr::Session session(o.profile);
    session.poll_event(0);
    session.begin(replay ? timeline.front() : now_ns());
    bool video_paused = false, video_loop = video.loop();
    bool quit = false;
    for (std::int64_t n = 0; !quit; ++n) {
      if (o.max_frames >= 0 && n >= o.max_frames) break;
      if (replay && n >= static_cast<std::int64_t>(timeline.size())) break;
      if (gl->should_close()) break;
      const auto frame_t0 = Clock::now();

      // Events: window, then script; the backend first (sim bindings), then loop and client.
      gl->poll_events();
      std::vector<xr::DesktopEvent> events = glue->drain();
      if (o.script) {
        auto more = o.script(n);
        events.insert(events.end(), more.begin(), more.end());
      }
      int fbw = 0, fbh = 0;
      gl->framebuffer_size(&fbw, &fbh);
      if (fbw != geometry_w || fbh != geometry_h) {
        // The sim's aim ray: approximate the window as a pinhole with the left eye's width.
        const xr::FovDeg& f = o.profile.eye(xr::Eye::Left).fov;
        events.insert(events.begin(), xr::ViewGeometryEvent{fbw, fbh, f.angle_right - f.angle_left});
        geometry_w = fbw;
        geometry_h = fbh;
      }
      for (const auto& e : events) {
        input.push_event(e);
        handle_loop_key(e, quit);
        client.on_desktop_event(e);
      }

      // Time: the recording's in replay, else the session's prediction.
      const xr::FrameState fs = session.wait_frame(replay ? timeline[n] - 1 : now_ns());
      if (!replay && o.vsync && fs.wait_ns > 0)
        std::this_thread::sleep_for(std::chrono::nanoseconds(fs.wait_ns));
      session.begin_frame();
      const std::int64_t t = replay ? timeline[n] : fs.predicted_display_time_ns;

      xr::InputState in = input.poll(t);
      if (!in.head_tracked) in.head = xr::neutral_input_state(t).head;
      FrameInfo info;
      info.loop_frame = n;
      info.display_time_ns = t;
      info.head_forward = head_direction(in);
      info.shown_video_frame = shown ? shown->index : -1;
      client.update(in, t, info);
      if (info.request_exit) quit = true;

      // Video: never block (timeout 0 unless asked); a frame not ready keeps the previous one.
      if (info.video_paused != video_paused) video.set_paused(video_paused = info.video_paused);
      if (info.video_loop != video_loop) video.set_loop(video_loop = info.video_loop);
      auto f = video.frame_at(info.video_frame, o.decode_timeout);
      bool changed = false;
      if (f && (!shown || f->index != shown->index)) {
        shown = std::move(f);
        changed = true;
      }
      FrameRecord rec{t, info.video_frame, shown ? shown->index : -1, false};
      rec.late = rec.shown_frame != rec.requested_frame;
      if (rec.late) ++result.late_frames;
      if (shown && (changed || !uploaded_any)) upload(stats);

      // Parameters: view mode once per frame at the head's forward direction, the same for both
      // eyes; per-pixel mode a grid, re-baked when the frame or the parameters change.
      const std::int64_t param_frame = shown ? shown->index : info.video_frame;
      const unsigned mask = client.unaltered() ? 0u : client.active_effects();
      const bool per_pixel = mask && client.param_mode() == ParamMode::PerPixel;
      effects::StackParams params;
      if (per_pixel) {
        if (!grid_valid || grid_frame != param_frame || grid_revision != client.params_revision())
          bake(param_frame, stats);
      } else if (mask) {
        const auto params_t0 = Clock::now();
        params = client.params(info.head_forward, param_frame);
        stats.add_cpu("params", ms_since(params_t0));
      }

      const std::vector<xr::QuadLayer> quads = client.quads();
      const auto views = session.locate_views(in.head, xr::ReferenceSpace::Local);
      for (int e = 0; e < 2; ++e)
        compositor->render_eye(e, {xr::render_view(views[e]), params, mask, per_pixel}, quads,
                               in.head);
      if (o.on_frame) o.on_frame(*compositor, n);
      compositor->draw_mirror(mirror, nullptr, fbw, fbh);
      const bool last = quit || (o.max_frames >= 0 && n + 1 >= o.max_frames) ||
                        (replay && n + 1 >= static_cast<std::int64_t>(timeline.size()));
      if (last && !o.screenshot.empty()) write_screenshot();
      gl->swap_buffers();
      session.end_frame(fs.predicted_display_time_ns, quads);

      ++result.frames;
      if (o.keep_records) result.records.push_back(rec);
      if (o.stats) stats.add_gpu(compositor->stage_times());
      stats.add_cpu("frame", ms_since(frame_t0));
      if (o.stats && std::chrono::duration<double>(Clock::now() - last_stats).count() >=
                         o.stats_period_s) {
        last_stats = Clock::now();
        out << "stats: frame " << n << ", late " << result.late_frames << ": "
            << FrameLoopStats::format(stats.take_window()) << "\n";
      }
      if (std::chrono::duration<double>(Clock::now() - last_title).count() >= 0.5) {
        last_title = Clock::now();
        const std::string title = "vdfx  " + client.status_line();
        glfwSetWindowTitle(gl->window(), title.c_str());
      }
    }
    if (session.state() != xr::SessionState::Idle) {
      session.request_exit(0);
      session.end(0);
    }
    result.wall_s = std::chrono::duration<double>(Clock::now() - wall0).count();
    result.medians = stats.total();
    if (o.stats) {
      out << "stats (medians over " << result.frames << " frames, " << result.late_frames
          << " late, " << (result.wall_s > 0 ? result.frames / result.wall_s : 0.0)
          << " frames/s; GPU stages summed over both eyes): "
          << FrameLoopStats::format(result.medians) << "\n";
    }
    return result;
  }
};

FrameLoop::FrameLoop(FrameLoopOptions options, xr::InputBackend& input, io::VideoSource& video,
                     FrameClient& client)
    : impl_(std::make_unique<Impl>(std::move(options), input, video, client)) {}
FrameLoop::~FrameLoop() = default;
FrameLoopResult FrameLoop::run() { return impl_->run(); }

#else  // no OpenGL in this build

struct FrameLoop::Impl {};
FrameLoop::FrameLoop(FrameLoopOptions, xr::InputBackend&, io::VideoSource&, FrameClient&) {
  throw std::runtime_error("this vdfx was built without OpenGL (VDFX_WITH_GL=OFF): no window");
}
FrameLoop::~FrameLoop() = default;
FrameLoopResult FrameLoop::run() { return {}; }

#endif

}  // namespace vdfx::app
