/// @file
/// @brief FrameLoop: window, session timing, input, decode, parameters, compositor, mirror.
#include "app/window/frame_loop.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <thread>

#include "app/window/frame_loop_stats.h"
#include "app/window/stabilized_view.h"
#include "effects/effect_shaders.h"
#include "io/image_write.h"
#include "io/input_error.h"
#include "io/video_source.h"
#include "xr/headset/session.h"
#include "xr/input/glfw/glfw_input_glue.h"
#include "xr/input/input_backend.h"
#include "xr/openxr/gl/openxr_runtime.h"
#include "xr/render/compositor.h"
#include "xr/render/flare_gl.h"
#include "xr/render/gl_context.h"
#include "xr/render/grain_gl.h"
#include "xr/render/param_grid.h"

namespace vdfx::app {

std::optional<xr::MirrorMode> mirror_for_key(xr::Key key) {
  switch (key) {
    case xr::Key::Num1: return xr::MirrorMode::Desktop;
    case xr::Key::Num2: return xr::MirrorMode::PreDistorted;
    case xr::Key::Num3: return xr::MirrorMode::ThroughTheLens;
    case xr::Key::Num4: return xr::MirrorMode::SingleEye;
    default: return std::nullopt;
  }
}

std::string frame_loop_keys_text() {
  return "  1                         window: desktop view (one undistorted view for a monitor)\n"
         "  2                         window: headset mirror, pre-distorted panels (as the "
         "displays show them)\n"
         "  3                         window: headset mirror, through the lens (as the wearer sees "
         "them)\n"
         "  4                         window: headset mirror, left eye, undistorted\n"
         "  5                         window: desktop view of stereo video, left / right eye\n"
         "  Escape                    quit (closing the window too)\n";
}

namespace {

using Clock = std::chrono::steady_clock;

/// While no frame is shown yet, each frame waits up to this long for the first one.
constexpr std::int64_t kLoadingWaitNs = 50'000'000;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

}  // namespace

struct FrameLoop::Impl {
  FrameLoopOptions o;
  xr::InputBackend& input;
  io::VideoSource& video;
  FrameClient& client;
  std::unique_ptr<xr::GlContext> gl;
  std::unique_ptr<xr::GlfwInputGlue> glue;
  std::unique_ptr<xr::Compositor> compositor;
  std::unique_ptr<xr::FlareGl> flare;  //!< the client's flares, drawn after the effects
  std::unique_ptr<xr::GrainGl> grain;  //!< the client's grain, drawn after the flares
  xr::MirrorMode mirror = xr::MirrorMode::Desktop;
  int desktop_eye = 0;               //!< the stereo video's eye the desktop view shows (key 5)
  std::optional<glm::dvec2> cursor;  //!< the last cursor position the window reported

  // What is on screen: the decoded frame, and the parameter grid baked for it (per-pixel mode).
  std::optional<io::VideoFrame> shown;
  bool uploaded_any = false;
  bool grid_valid = false;
  std::int64_t grid_frame = -1;
  std::uint64_t grid_revision = 0;
  int geometry_w = 0, geometry_h = 0;
  bool video_paused = false, video_loop = true;  //!< what the decoder was last told
  Clock::time_point last_stats, last_title;      //!< the last stats line and title update

  ~Impl() {
    // The session's swapchains are GL objects of this window's context: gone before it is.
    if (o.openxr) o.openxr->end_session();
  }

  Impl(FrameLoopOptions opts, xr::InputBackend& in, io::VideoSource& v, FrameClient& c)
      : o(std::move(opts)), input(in), video(v), client(c) {
    // The command line checks its option; another caller passing this is a bug.
    if (!(o.eye_scale > 0.0 && o.eye_scale <= 4.0))
      throw std::invalid_argument("FrameLoop: eye_scale must be in (0, 4], got " +
                                  std::to_string(o.eye_scale));
    xr::GlContextOptions g;
    g.width = o.window_width;
    g.height = o.window_height;
    g.visible = o.visible;
    // With a headset, xrWaitFrame paces the loop: the mirror must not wait for the monitor too.
    g.vsync = o.vsync && !o.openxr;
    g.resizable = o.resizable;
    g.title = "vdfx";
    gl = xr::GlContext::create(g);
    glue = std::make_unique<xr::GlfwInputGlue>(gl->window());
    xr::CompositorConfig cc;
    const xr::EyeProfile& eye = o.profile.eye(xr::Eye::Left);
    const auto scaled = [&](int px) {
      return std::max(8, static_cast<int>(std::lround(px * o.eye_scale)));
    };
    cc.eye_width = scaled(eye.width);
    cc.eye_height = scaled(eye.height);
    cc.lens = effects::LensModel(o.profile.lens);
    if (o.openxr) {
      // The runtime's recommended size, its swapchains, and no lens: the runtime distorts.
      const xr::OpenXrViewInfo& v = o.openxr->info().views.at(0);
      o.openxr->start_session(gl->window(), scaled(v.recommended_width),
                              scaled(v.recommended_height));
      cc.eye_width = o.openxr->swapchains().eye_width;
      cc.eye_height = o.openxr->swapchains().eye_height;
      cc.distortion.method = xr::DistortionMethod::None;
      o.mirror = xr::MirrorMode::SingleEye;
    }
    cc.gpu_timing = o.stats;
    cc.blur = o.blur;
    compositor = std::make_unique<xr::Compositor>(cc);
    compositor->set_video_layout(o.video_layout);
    flare = std::make_unique<xr::FlareGl>();
    grain = std::make_unique<xr::GrainGl>();
    mirror = o.mirror;
  }

  /// What the window shows now, for turning cursor positions into rays.
  xr::MirrorGeometry mirror_geometry(int width, int height) const {
    const xr::CompositorConfig& c = compositor->config();
    return xr::MirrorGeometry::from_profile(o.profile, mirror, c.eye_width, c.eye_height, width,
                                            height, o.desktop_hfov_deg);
  }

  /// A cursor position with the ray through what is drawn under it.
  xr::MouseMoveEvent cursor_event(double x, double y, int width, int height) const {
    xr::MouseMoveEvent m{x, y};
    m.ray = xr::mirror_ray(mirror_geometry(width, height), x, y);
    m.over_view = m.ray.has_value();
    return m;
  }

  /// Uploads the shown frame as it is decoded.
  void upload(FrameLoopStats& stats) {
    const auto t0 = Clock::now();
    compositor->set_video_frame(shown->picture);  // as decoded: the GPU converts Y'CbCr
    stats.add_cpu("upload", ms_since(t0));
    uploaded_any = true;
  }

  /// Per-pixel mode: bakes the client's parameters on the grid for the shown frame and uploads
  /// it; the effect shader reads it per pixel (all six effects).
  void bake(std::int64_t frame, FrameLoopStats& stats) {
    const auto t0 = Clock::now();
    const xr::ParamGrid grid =
        xr::bake_param_grid(client.params_at(frame), o.bake_width, o.bake_height);
    compositor->set_param_grid(grid);
    stats.add_cpu("bake", ms_since(t0));
    grid_valid = true;
    grid_frame = frame;
    grid_revision = client.params_revision();
  }

  /// Loop keys; returns whether the mirror changed.
  bool handle_loop_key(const xr::DesktopEvent& e, bool& quit) {
    const auto* k = std::get_if<xr::KeyEvent>(&e);
    if (!k || !k->pressed) return false;
    if (k->key == xr::Key::Escape) quit = true;
    if (k->key == xr::Key::Num5 && o.video_layout.stereo()) {
      desktop_eye = 1 - desktop_eye;
      compositor->set_desktop_eye(desktop_eye);
      return true;
    }
    const auto m = mirror_for_key(k->key);
    if (!m || *m == mirror) return false;
    mirror = *m;
    return true;
  }

  /// No first frame yet: an input error once the start time-out has passed (or the decoder has
  /// given up), naming the video.
  void check_start_timeout(Clock::time_point wall0) const {
    const io::VideoStats st = video.stats();
    const bool gave_up = st.ended_early && st.decoded == 0;
    if (!gave_up && Clock::now() - wall0 < o.start_timeout) return;
    std::string why =
        gave_up
            ? "the decoder found no frame (" + std::to_string(st.decode_errors) + " failed)"
            : "no frame was decoded within " +
                  std::to_string(
                      std::chrono::duration_cast<std::chrono::seconds>(o.start_timeout).count()) +
                  " s";
    throw io::InputError(video.properties().path.string() + ": cannot show the video: " + why);
  }

  /// What both eyes show at display time t (the frame's input, the client's update, the video
  /// frame, parameters, flares, grain and panels), the same for either headset backend.
  struct Content {
    xr::InputState in;
    FrameInfo info;
    FrameRecord rec;
    effects::StackParams params;
    unsigned mask = 0;
    bool per_pixel = false;
    std::vector<xr::QuadLayer> quads;
    std::int64_t param_frame = 0;  //!< the video frame the parameters are for
  };
  Content frame_content(std::int64_t n, std::int64_t t, Clock::time_point wall0,
                        FrameLoopStats& stats, FrameLoopResult& result) {
    Content c;
    c.in = input.poll(t);
    if (!c.in.head_tracked) c.in.head = xr::neutral_input_state(t).head;
    FrameInfo& info = c.info;
    info.loop_frame = n;
    info.display_time_ns = t;
    info.head_forward = xr::forward_direction(c.in.head);
    info.shown_video_frame = shown ? shown->index : -1;
    client.update(c.in, t, info);

    // Video: never block (timeout 0 unless asked); a frame not ready keeps the previous one.
    // Until the first frame is decoded the view is a dark field and the client shows
    // "loading"; each frame then waits a little for it, so loading is not slowed by spinning.
    if (info.video_paused != video_paused) video.set_paused(video_paused = info.video_paused);
    if (info.video_loop != video_loop) video.set_loop(video_loop = info.video_loop);
    const auto loading_wait = std::chrono::nanoseconds(shown ? 0 : kLoadingWaitNs);
    auto f = video.frame_at(info.video_frame, std::max(o.decode_timeout, loading_wait));
    if (!shown && !f) check_start_timeout(wall0);
    bool changed = false;
    if (f && (!shown || f->index != shown->index)) {
      shown = std::move(f);
      changed = true;
    }
    c.rec = {t, info.video_frame, shown ? shown->index : -1, false};
    c.rec.late = c.rec.shown_frame != c.rec.requested_frame;
    if (c.rec.late) ++result.late_frames;
    if (shown && (changed || !uploaded_any)) upload(stats);

    // Parameters: view mode once per frame at the head's forward direction, the same for both
    // eyes; per-pixel mode a grid, re-baked when the frame or the parameters change.
    const std::int64_t param_frame = shown ? shown->index : info.video_frame;
    c.param_frame = param_frame;
    if (!o.stabilize.identity()) {  // the world frame shown: the head as the video frame sees it
      c.in.head = video_frame_pose(c.in.head, o.stabilize, param_frame);
      info.head_forward = xr::forward_direction(c.in.head);
    }
    c.mask = client.unaltered() ? 0u : client.active_effects();
    c.per_pixel = c.mask && client.param_mode() == ParamMode::PerPixel;
    if (c.per_pixel) {
      if (!grid_valid || grid_frame != param_frame || grid_revision != client.params_revision())
        bake(param_frame, stats);
    } else if (c.mask) {
      const auto params_t0 = Clock::now();
      c.params = client.params(info.head_forward, param_frame);
      stats.add_cpu("params", ms_since(params_t0));
    }

    // Flares: laid out once per frame from the head pose, drawn into both eyes.
    const auto flares_t0 = Clock::now();
    flare->set_layouts(client.unaltered() ? std::vector<effects::FlareLayout>{}
                                          : client.flares(c.in.head, param_frame,
                                                          shown ? &shown->picture : nullptr));
    stats.add_cpu("flares", ms_since(flares_t0));
    // Grain: laid out once per frame (pattern from the display time), drawn into both eyes.
    const auto grains_t0 = Clock::now();
    grain->set_layers(client.unaltered() ? std::vector<effects::GrainFrame>{}
                                         : client.grains(c.in.head, t, param_frame));
    stats.add_cpu("grains", ms_since(grains_t0));
    c.quads = client.quads();
    return c;
  }

  void write_screenshot(int w, int h) {
    xr::GlTarget target(w, h, xr::TexFormat::RGBA8);
    compositor->draw_mirror(mirror, &target, w, h);
    const cv::Mat bgr = xr::to_bgr8(target.read_float());
    io::write_png(o.screenshot, bgr);
  }

  /// After each frame: the periodic stats line (--stats) and the window title.
  void report_progress(std::int64_t n, const FrameLoopResult& result, FrameLoopStats& stats) {
    if (o.stats &&
        std::chrono::duration<double>(Clock::now() - last_stats).count() >= o.stats_period_s) {
      last_stats = Clock::now();
      stats_stream() << "stats: frame " << n << ", late " << result.late_frames << ": "
                     << FrameLoopStats::format(stats.take_window()) << "\n";
    }
    if (std::chrono::duration<double>(Clock::now() - last_title).count() >= 0.5) {
      last_title = Clock::now();
      const std::string title = "vdfx  " + client.status_line();
      glfwSetWindowTitle(gl->window(), title.c_str());
    }
  }

  std::ostream& stats_stream() const { return o.stats_out ? *o.stats_out : std::cout; }

  bool stop_asked() const { return o.stop && o.stop->load(); }

  /// The run's totals, and their line with --stats.
  void finish(FrameLoopResult& result, FrameLoopStats& stats, Clock::time_point wall0) {
    result.wall_s = std::chrono::duration<double>(Clock::now() - wall0).count();
    result.medians = stats.total();
    if (o.stats) {
      stats_stream() << "stats (medians over " << result.frames << " frames, " << result.late_frames
                     << " late, " << (result.wall_s > 0 ? result.frames / result.wall_s : 0.0)
                     << " frames/s; GPU stages summed over both eyes): "
                     << FrameLoopStats::format(result.medians) << "\n";
    }
  }

  /// The size to render this frame: the window's framebuffer; a hidden window (tests,
  /// screenshots) renders at the size asked for, and so does a minimised one.
  std::pair<int, int> render_size() const {
    int fbw = 0, fbh = 0;
    gl->framebuffer_size(&fbw, &fbh);
    if (!o.visible || fbw <= 0 || fbh <= 0) fbw = o.window_width, fbh = o.window_height;
    return {fbw, fbh};
  }

  /// The frame's desktop events (polled before), the window's then the script's (a size change
  /// first), each mouse move with its ray through what the mirror shows (re-aimed when a loop key
  /// changes the mirror): to the input backend first (sim bindings), then to the client. Escape
  /// sets `quit`.
  void route_events(std::int64_t n, int fbw, int fbh, bool& quit) {
    std::vector<xr::DesktopEvent> events = glue->drain();
    if (o.script) {
      auto more = o.script(n);
      events.insert(events.end(), more.begin(), more.end());
    }
    bool geometry_changed = false;
    if (fbw != geometry_w || fbh != geometry_h) {
      events.insert(events.begin(), xr::ViewGeometryEvent{fbw, fbh, o.desktop_hfov_deg});
      geometry_w = fbw;
      geometry_h = fbh;
      geometry_changed = true;
    }
    std::vector<xr::DesktopEvent> routed;
    for (auto& e : events) {
      if (auto* m = std::get_if<xr::MouseMoveEvent>(&e)) {
        if (!m->ray) *m = cursor_event(m->x, m->y, fbw, fbh);
        cursor = glm::dvec2(m->x, m->y);
      }
      routed.push_back(e);
      if (handle_loop_key(e, quit)) geometry_changed = true;
      if (geometry_changed && cursor) {
        // The same cursor now points through another mirror: re-aim without moving.
        routed.push_back(cursor_event(cursor->x, cursor->y, fbw, fbh));
        geometry_changed = false;
      }
    }
    if (geometry_changed && cursor) routed.push_back(cursor_event(cursor->x, cursor->y, fbw, fbh));
    for (const auto& e : routed) {
      input.push_event(e);
      client.on_desktop_event(e);
    }
  }

  /// The frame's content through the compositor: the desktop view at the window's size, or both
  /// eyes from the session's views.
  void render_content(const Content& c, xr::Session& session, int fbw, int fbh) {
    const std::array<xr::EyeLayer*, 2> layers{flare.get(), grain.get()};
    if (mirror == xr::MirrorMode::Desktop) {
      const xr::RenderView view = xr::desktop_view(c.in.head, o.desktop_hfov_deg, fbw, fbh);
      compositor->render_desktop({view, c.params, c.mask, c.per_pixel, layers}, fbw, fbh,
                                 o.desktop_video_scale, c.quads, c.in.head);
    } else {
      const auto views = session.locate_views(c.in.head, xr::ReferenceSpace::Local);
      for (int e = 0; e < 2; ++e)
        compositor->render_eye(e,
                               {xr::render_view(views[e]), c.params, c.mask, c.per_pixel, layers},
                               c.quads, c.in.head);
    }
  }

  FrameLoopResult run() {
    if (o.openxr) return run_openxr();
    FrameLoopResult result;
    FrameLoopStats stats;
    const std::vector<std::int64_t> timeline = input.timeline();
    const bool replay = !timeline.empty();
    const auto frames = static_cast<std::int64_t>(timeline.size());
    const auto wall0 = Clock::now();
    last_stats = last_title = wall0;
    const auto now_ns = [&] {
      return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - wall0).count();
    };

    xr::Session session(o.profile);
    session.poll_event(0);
    session.begin(replay ? timeline.front() : now_ns());
    video_loop = video.loop();
    bool quit = false;
    for (std::int64_t n = 0; !quit; ++n) {
      if ((o.max_frames >= 0 && n >= o.max_frames) || (replay && n >= frames)) break;
      if (gl->should_close()) break;
      if (stop_asked()) {
        result.stopped = true;
        break;
      }
      const auto frame_t0 = Clock::now();
      gl->poll_events();  // first: a resize it delivers is this frame's size
      const auto [fbw, fbh] = render_size();
      route_events(n, fbw, fbh, quit);

      // Time: the recording's in replay, else the session's prediction.
      const xr::FrameState fs = session.wait_frame(replay ? timeline[n] - 1 : now_ns());
      if (!replay && o.vsync && fs.wait_ns > 0)
        std::this_thread::sleep_for(std::chrono::nanoseconds(fs.wait_ns));
      session.begin_frame();
      const std::int64_t t = replay ? timeline[n] : fs.predicted_display_time_ns;

      const Content c = frame_content(n, t, wall0, stats, result);
      if (c.info.request_exit) quit = true;
      render_content(c, session, fbw, fbh);
      if (o.on_frame) o.on_frame(*compositor, n);
      compositor->draw_mirror(mirror, nullptr, fbw, fbh);
      const bool last =
          quit || (o.max_frames >= 0 && n + 1 >= o.max_frames) || (replay && n + 1 >= frames);
      if (last && !o.screenshot.empty()) write_screenshot(fbw, fbh);
      gl->swap_buffers();
      session.end_frame(fs.predicted_display_time_ns, c.quads);

      ++result.frames;
      if (o.keep_records) result.records.push_back(c.rec);
      if (o.stats) stats.add_gpu(compositor->stage_times());
      stats.add_cpu("frame", ms_since(frame_t0));
      report_progress(n, result, stats);
    }
    if (session.state() != xr::SessionState::Idle) {
      session.request_exit(0);
      session.end(0);
    }
    finish(result, stats, wall0);
    return result;
  }

  // ---- --runtime openxr (docs/openxr.md)

  /// The window's events in a headset session: Escape or closing the window leave; the input
  /// backend and the client see them as in the sim (the OpenXR backend takes no desktop input).
  /// Returns whether to leave.
  bool openxr_window_events(std::int64_t n) {
    gl->poll_events();
    std::vector<xr::DesktopEvent> events = glue->drain();
    if (o.script) {
      auto more = o.script(n);
      events.insert(events.end(), more.begin(), more.end());
    }
    bool quit = gl->should_close();
    for (const auto& e : events) {
      input.push_event(e);
      client.on_desktop_event(e);
      const auto* k = std::get_if<xr::KeyEvent>(&e);
      if (k && k->pressed && k->key == xr::Key::Escape) quit = true;
    }
    return quit;
  }

  /// Both eyes into the runtime's swapchains (no quads, no lens), the panels as quad layers,
  /// and the panels drawn over the left eye for the mirror.
  void render_openxr(xr::OpenXrRuntime& rt, const Content& c) {
    const std::array<xr::EyeLayer*, 2> layers{flare.get(), grain.get()};
    std::array<xr::EyeView, 2> views = rt.locate_views();
    for (xr::EyeView& v : views) v.pose = video_frame_pose(v.pose, o.stabilize, c.param_frame);
    for (int e = 0; e < 2; ++e) {
      compositor->render_eye_buffer(
          e, {xr::render_view(views[e]), c.params, c.mask, c.per_pixel, layers});
      rt.submit_eye(e, compositor->eye_buffer(e).texture());
    }
    rt.submit_quads(c.quads);
    compositor->draw_quads(0, c.quads, c.in.head);
  }

  /// The window: the left eye as submitted, with the panels.
  void present_mirror(int& fbw, int& fbh) {
    gl->framebuffer_size(&fbw, &fbh);
    if (!o.visible || fbw <= 0 || fbh <= 0) fbw = o.window_width, fbh = o.window_height;
    compositor->draw_mirror(mirror, nullptr, fbw, fbh);
    gl->swap_buffers();
  }

  /// The headset's loop: the runtime's lifecycle decides when frames run, xrWaitFrame is the
  /// clock (its predicted display time drives the video, the grain and the input), and a
  /// request to leave (Escape, the window closed, --frames, the client) goes through the
  /// runtime's states to EXITING. "frame" (--stats, vdfx bench) is the CPU time from xrWaitFrame's
  /// return to xrEndFrame's.
  FrameLoopResult run_openxr() {
    xr::OpenXrRuntime& rt = *o.openxr;
    FrameLoopResult result;
    FrameLoopStats stats;
    const auto wall0 = Clock::now();
    last_stats = last_title = wall0;
    video_loop = video.loop();
    int fbw = o.window_width, fbh = o.window_height;
    try {
      openxr_frames(rt, result, stats, wall0, fbw, fbh);
    } catch (const xr::OpenXrSessionLost&) {
      rt.session_lost();  // the headset went away mid-frame: leave as on LOSS_PENDING
    }
    if (!o.screenshot.empty() && result.frames > 0) write_screenshot(fbw, fbh);
    result.end_reason = rt.lifecycle().reason();
    finish(result, stats, wall0);
    return result;
  }

  /// run_openxr's frames, until the lifecycle leaves.
  void openxr_frames(xr::OpenXrRuntime& rt, FrameLoopResult& result, FrameLoopStats& stats,
                     Clock::time_point wall0, int& fbw, int& fbh) {
    bool quit = false;
    for (std::int64_t n = 0;;) {
      quit = openxr_window_events(n) || quit;
      if (stop_asked() && !result.stopped) quit = result.stopped = true;
      if (quit || (o.max_frames >= 0 && n >= o.max_frames)) rt.request_exit();
      rt.poll_events();
      if (rt.lifecycle().leaving()) break;
      if (!rt.lifecycle().running()) {  // IDLE: waiting for the runtime to make it READY
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        continue;
      }
      const xr::OpenXrFrame f = rt.begin_frame();
      const auto frame_t0 = Clock::now();
      Content c = frame_content(n, f.time_ns, wall0, stats, result);
      if (c.info.request_exit) quit = true;
      if (c.info.haptic_pulse) rt.haptic_pulse(*c.info.haptic_pulse);
      if (f.should_render) render_openxr(rt, c);
      if (o.on_frame) o.on_frame(*compositor, n);
      rt.end_frame();
      stats.add_cpu("frame", ms_since(frame_t0));
      if (o.stats) stats.add_gpu(compositor->stage_times());
      if (o.keep_records) result.records.push_back(c.rec);
      ++result.frames;
      present_mirror(fbw, fbh);
      report_progress(n++, result, stats);
    }
  }
};

FrameLoop::FrameLoop(FrameLoopOptions options, xr::InputBackend& input, io::VideoSource& video,
                     FrameClient& client)
    : impl_(std::make_unique<Impl>(std::move(options), input, video, client)) {}
FrameLoop::~FrameLoop() = default;
FrameLoopResult FrameLoop::run() {
  return impl_->run();
}

}  // namespace vdfx::app
