/// @file
/// @brief `vdfx edit [VIDEO] [--sidecar F] [--hmd P] [--input ...] [--record REC]`: the in-headset
/// editor's window. The loop is app/frame_loop.h; the per-frame logic is a FrameClient. Until the
/// editor's client is plugged in (make_edit_client), it plays the sidecar like `vdfx play`.
#include <filesystem>
#include <iostream>

#include "app/cli_util.h"
#include "app/commands.h"
#include "app/frame_loop_cli.h"
#include "app/player.h"
#include "io/sidecar.h"

namespace vdfx::app {
namespace {

std::filesystem::path demo_sidecar() {
  return std::filesystem::path(VDFX_SOURCE_DIR) / "app" / "demo" / "sunrise.vdfx.json";
}

// The sidecar's video path, relative to the sidecar's folder when relative.
std::filesystem::path sidecar_video(const std::filesystem::path& sidecar_path,
                                    const io::Sidecar& s) {
  std::filesystem::path p = s.video.path;
  return p.is_absolute() ? p : sidecar_path.parent_path() / p;
}

}  // namespace

int cmd_edit(const Args& args) {
  CLI::App cli("author view-dependent effects in the simulated headset (no VIDEO: the demo)",
               "vdfx edit");
  std::string video, sidecar_path;
  LoopCli loop;
  cli.add_option("VIDEO", video, "video file or still image; default: the sidecar's video");
  cli.add_option("--sidecar", sidecar_path, "effects file (.vdfx.json); default: the bundled demo");
  add_loop_options(cli, loop);
  cli.footer("\nUntil the editor is wired in, this plays the sidecar (keys as `vdfx play`).\n");
  if (auto code = parse_cli(cli, args)) return *code;

  const std::filesystem::path sc = sidecar_path.empty() ? demo_sidecar() : std::filesystem::path(sidecar_path);
  const io::Sidecar sidecar = io::read_sidecar(sc);
  const std::filesystem::path v = video.empty() ? sidecar_video(sc, sidecar) : std::filesystem::path(video);
  LoopSetup setup = prepare_loop(loop, v, true);
  Player client(sidecar, setup.video->properties());
  FrameLoop frame_loop(setup.options, *setup.input, *setup.video, client);
  report_loop("vdfx edit", frame_loop.run());
  return kExitOk;
}

}  // namespace vdfx::app
