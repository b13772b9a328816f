/// @file
/// @brief Shared options and setup of the windowed commands.
#include "app/window/frame_loop_cli.h"

#include <iostream>
#include <limits>

#include "app/cli/cli_util.h"
#include "app/cli/command_registry.h"
#include "app/cli/layout_options.h"
#include "io/input_error.h"
#include "xr/headset/hmd_profile.h"
#include "xr/openxr/gl/openxr_runtime.h"

namespace vdfx::app {
namespace {
std::string size_problem(const std::string& text, const char* option, const SizeLimit& limit) {
  try {
    parse_size(text, option, limit);
    return {};
  } catch (const CLI::ValidationError& e) {
    return e.what();
  }
}
std::string window_problem(const std::string& text) {
  return size_problem(text, "--window", kOutputSizeLimit);
}
std::string bake_problem(const std::string& text) {
  return size_problem(text, "--bake", kBakeSizeLimit);
}

// --record and --screenshot must not destroy an input, and must be regular files (or new).
void check_loop_outputs(const LoopCli& o, const std::filesystem::path& video_path,
                        const std::string& profile_source,
                        const std::vector<io::NamedInput>& other_inputs) {
  std::vector<io::NamedInput> inputs = other_inputs;
  inputs.push_back({"VIDEO", video_path});
  inputs.push_back({"--hmd", profile_source});
  if (o.input.rfind("replay:", 0) == 0) inputs.push_back({"--input replay:", o.input.substr(7)});
  for (const auto& [role, path] :
       {std::pair{"--record", o.record}, {"--screenshot", o.screenshot}}) {
    if (path.empty()) continue;
    io::check_output_is_not_input(role, path, inputs);
    io::resolve_output_path(path);
  }
}

// --runtime openxr: the runtime (its errors before any window opens), its controllers as the
// input, recorded with --record, the eyes at its recommended size (--scale 1 unless given).
void prepare_openxr(const LoopCli& o, const std::filesystem::path& video_path, LoopSetup& s) {
  if (o.input != "sim")
    throw UsageError("--input " + o.input +
                     ": with --runtime openxr the input is the headset's controllers (replay a "
                     "headset recording in the sim: --runtime sim --input replay:REC)");
  for (const CLI::Option* opt : o.sim_only)
    if (opt->count() > 0)
      throw UsageError(opt->get_name() +
                       " does nothing with --runtime openxr: the runtime gives the views and "
                       "paces the frames, and the window mirrors the left eye (docs/openxr.md)");
  FrameLoopOptions& f = s.options;
  f.openxr = xr::OpenXrRuntime::create();
  if (o.scale_option && o.scale_option->count() == 0) f.eye_scale = 1.0;
  f.mirror = xr::MirrorMode::SingleEye;
  s.input = f.openxr->create_input_backend();
  if (o.record.empty()) return;
  io::RecordingHeader h;
  h.hmd = "openxr";  // no sim profile: a replay uses the Hands layout, as the headset did
  h.video = video_path.string();
  const xr::OpenXrSystemInfo& info = f.openxr->info();
  h.note = "vdfx --runtime openxr: " + info.runtime_name + " " + info.runtime_version + ", " +
           info.system_name;
  s.input = xr::create_recording_backend(std::move(s.input), o.record, h);
}

}  // namespace

void add_loop_options(CLI::App& cli, LoopCli& o) {
  cli.add_option("--runtime", o.runtime,
                 "sim (the simulated headset in the window) or openxr (a headset through the "
                 "active OpenXR runtime: Monado, WiVRn, SteamVR; docs/openxr.md)")
      ->capture_default_str()
      ->check(CLI::IsMember({"sim", "openxr"}));
  o.sim_only.push_back(
      cli.add_option("--hmd", o.hmd, "headset profile name or file (vdfx hmd list)")
          ->capture_default_str());
  cli.add_option("--input", o.input, "sim | hid[:SEL,...] | replay:REC.vdrec.jsonl")
      ->capture_default_str();
  cli.add_option("--record", o.record, "record the input to this .vdrec.jsonl file");
  cli.add_flag("--stats", o.stats,
               "GPU time per stage (video, effects, distortion): medians, "
               "printed every 2 s and at exit");
  o.scale_option = cli.add_option("--scale", o.scale,
                                  "eye buffers at this fraction of the profile's resolution (1 = "
                                  "full; the default keeps llvmpipe interactive; with --runtime "
                                  "openxr: of the runtime's recommended size, default 1)")
                       ->capture_default_str()
                       ->check(finite_range(0.01, 4.0));
  cli.add_option("--frames,--exit-after-frames", o.frames, "stop after N frames")
      ->check(whole_range(0, std::numeric_limits<std::int64_t>::max()));
  cli.add_option("--screenshot", o.screenshot, "write the mirror of the last frame to this PNG");
  o.sim_only.push_back(
      cli.add_option(
             "--mirror", o.mirror,
             "what the window shows: desktop (one undistorted view for a monitor), pre "
             "(headset mirror: pre-distorted panels), lens (through the lens), eye (left eye, "
             "undistorted); auto: desktop for the sim and its recordings, else pre. Keys 1-4 "
             "switch while running")
          ->capture_default_str()
          ->check(CLI::IsMember({"auto", "desktop", "pre", "lens", "eye"})));
  o.sim_only.push_back(
      cli.add_option("--look", o.look,
                     "the right-button drag (--input sim): drag turns the image with the mouse "
                     "as desktop 360 players do (drag left: the view turns right), mouselook as "
                     "a game's camera (drag left: turns left); the key I switches while running")
          ->capture_default_str()
          ->check(CLI::IsMember({"drag", "mouselook"})));
  o.sim_only.push_back(
      cli.add_option("--fov", o.fov, "horizontal field of view of the desktop view, degrees")
          ->capture_default_str()
          ->check(finite_range(20.0, 160.0)));
  cli.add_option("--window", o.window, "window size WxH")
      ->capture_default_str()
      ->check(window_problem);
  cli.add_flag("--hidden", o.hidden, "no visible window (offscreen; --screenshot still works)");
  o.sim_only.push_back(
      cli.add_flag("--no-vsync", o.no_vsync, "do not wait for the display's vsync (live input)"));
  cli.add_option("--decode-timeout", o.decode_timeout_ms,
                 "ms a frame may wait for the decoder (0: never wait, show the previous frame)")
      ->capture_default_str()
      ->check(finite_range(0.0, 10000.0));
  cli.add_option("--bake", o.bake, "per-pixel mode's parameter grid WxH (speed/error knob)")
      ->capture_default_str()
      ->check(bake_problem);
  cli.add_option("--blur", o.blur,
                 "GPU blur: pyramid (halvings + small residual blur, the live default) or exact "
                 "(full-resolution separable Gaussian, as vdfx render --gpu)")
      ->capture_default_str()
      ->check(CLI::IsMember({"exact", "pyramid"}));
  add_layout_options(cli, o.layout);
}

void resolve_loop_layout(LoopSetup& s, const LoopCli& o, const io::VideoInfo* sidecar,
                         const std::filesystem::path& sidecar_path) {
  s.options.video_layout = shown_layout(s.video->properties(), o.layout, sidecar, sidecar_path);
}

LoopSetup prepare_loop(const LoopCli& o, const std::filesystem::path& video_path, bool loop_video,
                       const std::vector<io::NamedInput>& other_inputs) {
  LoopSetup s;
  FrameLoopOptions& f = s.options;
  f.profile = xr::load_hmd_profile(o.hmd);
  check_loop_outputs(o, video_path, f.profile.source, other_inputs);
  const ImageSize window = parse_size(o.window, "--window", kOutputSizeLimit);
  const ImageSize bake = parse_size(o.bake, "--bake", kBakeSizeLimit);
  f.window_width = window.width;
  f.window_height = window.height;
  f.bake_width = bake.width;
  f.bake_height = bake.height;
  f.blur = xr::blur_method_from_name(o.blur).value_or(xr::BlurMethod::Pyramid);
  f.eye_scale = o.scale;
  f.max_frames = o.frames;
  f.screenshot = o.screenshot;
  f.stats = o.stats;
  f.visible = !o.hidden;
  f.vsync = !o.no_vsync;
  f.desktop_hfov_deg = o.fov;
  f.decode_timeout = std::chrono::nanoseconds(static_cast<std::int64_t>(o.decode_timeout_ms * 1e6));

  io::VideoSourceOptions vo;
  vo.loop = loop_video;
  s.video = io::VideoSource::open(video_path, vo);
  if (o.runtime == "openxr") {
    prepare_openxr(o, video_path, s);
    return s;
  }

  // Which view the window opens on: the desktop view for the sim (a monitor and a mouse) and for
  // replays of sessions recorded in it, a headset mirror otherwise.
  const std::string replay_prefix = "replay:";
  bool desktop_input = o.input == "sim";
  if (o.input.rfind(replay_prefix, 0) == 0) {
    const io::RecordingHeader h = io::read_recording(o.input.substr(replay_prefix.size())).header;
    if (h.desktop)
      s.recorded_desktop = h.desktop;
    else if (h.hmd == "sim")
      s.recorded_desktop = io::RecordedDesktopView{1280, 720, 90.0};  // before the extension
    desktop_input = s.recorded_desktop.has_value();
  }
  f.mirror = o.mirror == "auto"
                 ? (desktop_input ? xr::MirrorMode::Desktop : xr::MirrorMode::PreDistorted)
                 : *xr::mirror_mode_from_name(o.mirror);

  xr::InputBackendOptions io_opts;
  io_opts.sim.window_width = window.width;
  io_opts.sim.window_height = window.height;
  io_opts.sim.hfov_deg = o.fov;
  io_opts.sim.look = xr::parse_look_mode(o.look).value_or(xr::LookMode::Drag);
  try {
    s.input = xr::create_input_backend(o.input, io_opts);
  } catch (const io::InputError& e) {
    throw io::InputError("--input: " + std::string(e.what()));  // xr/ names no options
  }
  if (!o.record.empty()) {
    io::RecordingHeader h;
    h.hmd = f.profile.name;
    h.video = video_path.string();
    h.note = "vdfx " + o.input;
    // The sim's panels are laid out for the window: the replay needs its size and FOV (the
    // window is then not resizable while recording, docs/input.md).
    if (o.input == "sim") h.desktop = io::RecordedDesktopView{window.width, window.height, o.fov};
    f.resizable = o.input != "sim";
    s.input = xr::create_recording_backend(std::move(s.input), o.record, h);
  }
  return s;
}

void report_loop(const char* command, const FrameLoopResult& r) {
  std::cerr << command << ": " << r.frames << " frames in " << r.wall_s << " s ("
            << (r.wall_s > 0 ? r.frames / r.wall_s : 0.0) << " frames/s), " << r.late_frames
            << " late (video frame not decoded in time; the previous one stayed on screen)\n";
  if (!r.end_reason.empty()) std::cerr << command << ": " << r.end_reason << "\n";
}

}  // namespace vdfx::app
