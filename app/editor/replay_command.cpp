/// @file
/// @brief `vdfx replay REC --video V [--sidecar-in F] --sidecar-out F [--frames DIR]`.
#include <iostream>

#include "app/cli/cli_util.h"
#include "app/cli/command_functions.h"
#include "app/cli/layout_options.h"
#include "app/editor/replay.h"

namespace vdfx::app {

int cmd_replay(const Args& args) {
  CLI::App cli{"replay a recorded editing session headless, deterministically, as fast as it goes",
               "vdfx replay"};
  ReplayOptions o;
  std::string rec, video, in, out, frames;
  cli.add_option("recording", rec, "the recorded session (.vdrec.jsonl)")->required();
  cli.add_option("--video", video, "the video or panorama it was recorded on")->required();
  cli.add_option(
      "--sidecar-in", in,
      "start from this sidecar (default: --sidecar-out when it exists, else no effects)");
  cli.add_option("--sidecar-out", out, "write the resulting sidecar here")->required();
  cli.add_flag("--force", o.force,
               "replace an existing --sidecar-out (without it, the session is replayed onto it)");
  cli.add_option("--frames", frames, "write a few mirror-like PNG frames to this folder");
  add_layout_options(cli, o.layout);
  if (const auto code = parse_cli(cli, args)) return *code;
  o.recording = rec;
  o.video = video;
  if (!in.empty()) o.sidecar_in = in;
  o.sidecar_out = out;
  if (!frames.empty()) o.frames_dir = frames;
  const ReplayResult r = run_replay(o);
  for (const auto& m : r.messages) std::cerr << "vdfx replay: " << m << "\n";
  std::size_t keys = 0;
  for (const auto& e : r.sidecar.effects) keys += e.keyframes.size();
  std::cout << "replayed " << r.samples << " samples: " << r.sidecar.effects.size() << " effects, "
            << keys << " keyframes -> " << out << "\n";
  for (const auto& p : r.images) std::cout << "wrote " << p.string() << "\n";
  return kExitOk;
}

}  // namespace vdfx::app
