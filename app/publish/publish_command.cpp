/// @file
/// @brief `vdfx publish VIDEO --sidecar F --out DIR [--title T] [--transcode h264|vp9]
/// [--layout L] [--coverage C]`: a static web page that plays the video (mono, stereo or VR180)
/// with the sidecar's view-dependent effects (docs/publish.md). The command parses;
/// app/publish/publish_request.h does the work.
#include <iostream>
#include <string>

#include "app/cli/cli_util.h"
#include "app/cli/command_functions.h"
#include "app/cli/layout_options.h"
#include "app/publish/publish_request.h"

namespace vdfx::app {
namespace {

struct PublishTexts {
  std::string video, sidecar, out, transcode;
};

void add_publish_options(CLI::App& cli, PublishRequest& r, PublishTexts& t) {
  cli.add_option("VIDEO", t.video, "the equirect video")->required();
  cli.add_option("--sidecar", t.sidecar, "the effects (.vdfx.json)")->required();
  cli.add_option("--out", t.out, "the folder to write (replaced whole if publish wrote it)")
      ->required();
  cli.add_option("--title", r.title, "the page's title (default: the video's file name)");
  cli.add_option("--transcode", t.transcode,
                 "re-encode the video (no effects) for browsers: h264 or vp9")
      ->check(CLI::IsMember({"h264", "vp9"}));
  add_layout_options(cli, r.layout);
}

PublishRequest publish_request(PublishRequest r, const PublishTexts& t) {
  r.video = t.video;
  r.sidecar = t.sidecar;
  r.out = t.out;
  if (t.transcode == "h264") r.transcode = Transcode::H264;
  if (t.transcode == "vp9") r.transcode = Transcode::Vp9;
  return r;
}

}  // namespace

int cmd_publish(const Args& args) {
  CLI::App cli{
      "Writes a static web page (WebGL2, WebXR) into DIR that plays VIDEO with the\n"
      "sidecar's view-dependent effects, evaluated by vdfx's own code compiled to\n"
      "WebAssembly. Serve the folder (python3 -m http.server) and open it in a browser;\n"
      "WebXR needs https or localhost.",
      "vdfx publish"};
  PublishRequest options;
  PublishTexts texts;
  add_publish_options(cli, options, texts);
  if (auto code = parse_cli(cli, args)) return *code;
  const PublishResult r = run_publish(publish_request(options, texts));
  for (const std::string& e : r.left_out)
    std::cerr << "vdfx publish: note: the page does not draw " << e
              << " (volumetric grain: vdfx's GPU renderer only)\n";
  if (!r.warning.empty()) std::cerr << "vdfx publish: warning: " << r.warning << "\n";
  std::cout << r.out.string() << ": " << r.files.size() << " files, video "
            << (r.transcoded ? "transcoded to " : "") << r.video_codec;
  if (r.layout.stereo() || r.layout.coverage_deg != 360)
    std::cout << ", " << effects::stereo_mode_name(r.layout.mode) << " " << r.layout.coverage_deg;
  std::cout << "\n";
  return kExitOk;
}

}  // namespace vdfx::app
