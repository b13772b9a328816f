/// @file
/// @brief `vdfx play VIDEO --sidecar F [--hmd P] [--input ...] [--record REC] [--stats] ...`:
/// the player in the simulated headset's window (docs/player.md).
#include <cmath>
#include <iostream>

#include "app/cli/cli_util.h"
#include "app/cli/command_functions.h"
#include "app/cli/stop_signals.h"
#include "app/window/frame_loop_cli.h"
#include "app/window/player.h"
#include "io/input_error.h"
#include "io/sidecar.h"

namespace vdfx::app {
namespace {

void warn_mismatch(const io::Sidecar& s, const io::VideoProperties& v) {
  if (s.video.frames != v.frames || std::abs(s.video.fps - v.fps.value()) > 1e-6 * v.fps.value())
    std::cerr << "vdfx play: warning: the sidecar was authored for " << s.video.frames
              << " frames at " << s.video.fps << " fps; " << v.path.string() << " has " << v.frames
              << " frames at " << v.fps.value() << " fps (keyframe frames are used as they are)\n";
}

std::string play_help_footer() {
  return "\nPlayer keys:\n" + Player::keys_text() + "Window keys:\n" + frame_loop_keys_text() +
         "Simulated controllers (--input sim):\n" + xr::sim_bindings_text(xr::SimConfig{}) +
         "\nWith --input replay:REC the loop takes its times from the recording (no clock), runs "
         "as fast as it can and stops at the recording's end.\n";
}

}  // namespace

int cmd_play(const Args& args) {
  CLI::App cli("play a 360-degree video with its view-dependent effects in the simulated headset",
               "vdfx play");
  std::string video, sidecar_path;
  std::string mode = "view";
  bool no_loop = false;
  double seek_step = 5.0;
  LoopCli loop;
  cli.add_option("VIDEO", video, "video file, or a still image (a one-frame video)")->required();
  cli.add_option("--sidecar", sidecar_path, "the effects (.vdfx.json)")->required();
  cli.add_option("--mode", mode,
                 "view (view-dependent, the paper) or pixel (per-pixel baseline); "
                 "V switches while playing")
      ->capture_default_str()
      ->check(CLI::IsMember({"view", "pixel"}));
  cli.add_flag("--no-loop", no_loop, "stop on the last frame instead of looping");
  bool stabilize = false;
  cli.add_flag("--stabilize", stabilize,
               "show the world frame: the sidecar's camera motion undone (vdfx track camera "
               "records it), the horizon held still");
  cli.add_option("--seek-step", seek_step, "seconds per B / F seek")
      ->capture_default_str()
      ->check(finite_range(0.0, 3600.0));
  add_loop_options(cli, loop);
  cli.footer(play_help_footer());
  if (auto code = parse_cli(cli, args)) return *code;

  const StopSignals stop;  // a stop signal ends the loop after its frame (docs/cli.md)
  const io::Sidecar sidecar = io::read_sidecar(sidecar_path);
  if (stabilize && !sidecar.camera)
    throw io::InputError(sidecar_path +
                         ": --stabilize: the sidecar has no camera motion: run vdfx track camera");
  LoopSetup setup = prepare_loop(loop, video, !no_loop, {{"--sidecar", sidecar_path}});
  resolve_loop_layout(setup, loop, &sidecar.video, sidecar_path);
  warn_mismatch(sidecar, setup.video->properties());
  if (stabilize) setup.options.stabilize = effects::AnchorFrames::world(*sidecar.camera);
  PlayerOptions po;
  po.loop = !no_loop;
  po.seek_step_s = seek_step;
  po.mode = mode == "pixel" ? ParamMode::PerPixel : ParamMode::ViewDependent;
  Player player(sidecar, setup.video->properties(), po);
  FrameLoop frame_loop(setup.options, *setup.input, *setup.video, player);
  const FrameLoopResult result = frame_loop.run();
  report_loop("vdfx play", result);
  if (result.stopped)
    std::cerr << "vdfx play: " << stopped_by() << " after " << result.frames << " frames"
              << recording_note(loop) << "\n";
  return kExitOk;
}

}  // namespace vdfx::app
