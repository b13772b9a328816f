/// @file
/// @brief `vdfx edit [VIDEO] [--sidecar F] [--recover yes|no] [loop options]`: the in-headset
/// editor in the simulated headset's window (docs/editor.md, "In the window"). The loop is
/// app/window/frame_loop.h; the per-frame logic is EditorClient around app/editor/editor.h's
/// Editor.
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <iostream>
#include <string>

#include "app/cli/cli_util.h"
#include "app/cli/command_functions.h"
#include "app/cli/stop_signals.h"
#include "app/editor/edit_access.h"
#include "app/window/editor_client.h"
#include "app/window/frame_loop_cli.h"
#include "io/input_error.h"
#include "io/recording.h"
#include "io/sidecar.h"

namespace vdfx::app {
namespace {

/// Thumbnails across the timeline strip.
constexpr int kTimelineThumbnails = 10;

namespace fs = std::filesystem;

/// `vdfx edit`'s default --scale (the player keeps kDefaultEyeScale).
constexpr double kEditDefaultEyeScale = 0.5;

fs::path demo_sidecar() {
  return fs::path(VDFX_SOURCE_DIR) / "app" / "demo" / "interior.vdfx.json";
}

// The sidecar's video path, relative to the sidecar's folder when relative.
fs::path sidecar_video(const fs::path& sidecar_path, const io::Sidecar& s) {
  fs::path p = s.video.path;
  return p.is_absolute() ? p : sidecar_path.parent_path() / p;
}

// The desktop layout puts both panels in front of the head (the sim's mouse reaches them); sim
// recordings were made with it, so their replays need it too.

/// A line typed on the terminal, or nothing when a stop signal came first: Ctrl-C at the prompt
/// ends the command (std::getline would read on through it, the handler's read being restarted).
std::optional<std::string> read_answer() {
  std::string line;
  while (!stop_requested()) {
    pollfd p{STDIN_FILENO, POLLIN, 0};
    const int ready = ::poll(&p, 1, 100);  // a signal may not interrupt it: look every 0.1 s
    if (ready < 0 && errno != EINTR) return line;
    if (ready <= 0) continue;
    char c = 0;
    const ssize_t n = ::read(STDIN_FILENO, &c, 1);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0 || c == '\n') return line;
    line += c;
  }
  return std::nullopt;
}

// Offers an unclean exit's recovery copy. Returns the file to load instead of the sidecar.
std::optional<fs::path> handle_recovery(const fs::path& sidecar_path, const std::string& recover) {
  const auto offer = find_recovery(sidecar_path);
  if (!offer) return std::nullopt;
  std::cerr << "vdfx edit: " << offer->message << "\n";
  bool yes = recover == "yes";
  if (recover == "ask") {
    if (isatty(STDIN_FILENO)) {
      std::cerr << "vdfx edit: load the recovery copy " << offer->path.string() << "? [y/N] "
                << std::flush;
      const std::optional<std::string> answer = read_answer();
      if (!answer)
        throw Stopped("nothing opened; the recovery copy " + offer->path.string() +
                      " is still there (--recover yes loads it)");
      yes = !answer->empty() && ((*answer)[0] == 'y' || (*answer)[0] == 'Y');
    } else {
      std::cerr << "vdfx edit: not interactive: not recovered (--recover yes loads it)\n";
    }
  }
  if (yes) return offer->path;  // "recovered" is said once it has been read (cmd_edit)
  // Not taken: this session's autosave would overwrite it and its clean exit remove it, so it is
  // set aside, never deleted.
  fs::path kept = offer->path;
  kept += ".declined";
  std::error_code ec;
  fs::rename(offer->path, kept, ec);
  if (ec) {
    std::cerr << "vdfx edit: cannot set the recovery copy aside (" << ec.message() << ")\n";
  } else {
    std::cerr << "vdfx edit: recovery copy set aside as " << kept.string()
              << "; to recover it later: mv " << kept.string() << " " << offer->path.string()
              << " and run with --recover yes\n";
  }
  return std::nullopt;
}

bool is_replay(const LoopCli& loop) {
  return loop.input.rfind("replay:", 0) == 0;
}

std::string edit_help_footer() {
  return "\nEditor controls (OpenXR actions):\n" + EditorClient::controls_text() +
         "Window keys:\n" + frame_loop_keys_text() + "Simulated controllers (--input sim):\n" +
         xr::sim_bindings_text(xr::SimConfig{}) +
         "\nNo VIDEO and no --sidecar: the bundled demo (app/demo/interior.vdfx.json), edited "
         "without "
         "saving (copy it and pass --sidecar COPY to keep edits). VIDEO without --sidecar edits "
         "VIDEO's NAME.vdfx.json next to it; a --sidecar that does not exist yet is created for "
         "VIDEO. "
         "Every change is saved at once (plus a NAME.vdfx.json.autosave recovery copy, removed on "
         "a "
         "clean exit; one left by a crash is offered at the next start: --recover).\n"
         "With --input replay:REC the loop takes its times from the recording and stops at its "
         "end.\n";
}

/// The sidecar `vdfx edit` works on: which file, read from it (or its recovery copy), and the
/// video it belongs to.
struct EditDocument {
  bool demo = false;    //!< the bundled demo: edited, never saved
  bool exists = false;  //!< false: a new sidecar for the video, created once it is open
  fs::path sidecar_path;
  io::Sidecar sidecar;
  fs::path video;
  std::optional<EditAccess> access;  //!< the sidecar's lock for the whole session (not the demo)
};

EditDocument open_document(const std::string& video, const std::string& sidecar_arg,
                           const std::string& recover, const std::string& access) {
  EditDocument d;
  d.demo = video.empty() && sidecar_arg.empty();
  if (d.demo) {
    d.sidecar_path = demo_sidecar();
  } else if (!sidecar_arg.empty()) {
    d.sidecar_path = sidecar_arg;
  } else {
    d.sidecar_path =
        fs::path(video).parent_path() / (fs::path(video).stem().string() + ".vdfx.json");
  }
  d.exists = fs::exists(d.sidecar_path);
  if (!d.exists && video.empty())
    throw io::InputError(d.sidecar_path.string() +
                         ": no such sidecar (give VIDEO to start a new one)");
  if (!d.demo)
    d.access.emplace(open_for_editing(d.sidecar_path, parse_edit_access(access), std::cerr));
  std::optional<fs::path> load_from;  // (a read-only session leaves the owner's autosave alone)
  if (d.exists && !d.demo && d.access->read_only_note.empty())
    load_from = handle_recovery(d.sidecar_path, recover);
  if (d.exists) d.sidecar = io::read_sidecar(load_from ? *load_from : d.sidecar_path);
  if (load_from) std::cerr << "vdfx edit: recovered " << load_from->string() << "\n";
  d.video = video.empty() ? sidecar_video(d.sidecar_path, d.sidecar) : fs::path(video);
  return d;
}

/// The editor's panel layout and saving: the sim (and replays of sessions recorded with it) get
/// the Desktop layout in the window's view; a replay keeps the view it was recorded in, a live
/// window's panels follow its size. Replays are exact: every solve and minimap finishes before
/// the frame that shows it; live, the minimap is computed on a worker so that playing a large
/// set never stalls a frame.
EditorOptions editor_options(const LoopCli& loop, const LoopSetup& setup, const EditDocument& d) {
  EditorOptions eo;
  const bool desktop =
      (loop.input == "sim" && loop.runtime == "sim") || setup.recorded_desktop.has_value();
  eo.layout = desktop ? PanelLayout::Desktop : PanelLayout::Hands;
  if (setup.recorded_desktop)
    eo.viewport = {setup.recorded_desktop->width, setup.recorded_desktop->height,
                   setup.recorded_desktop->hfov_deg};
  else
    eo.viewport = {setup.options.window_width, setup.options.window_height,
                   setup.options.desktop_hfov_deg};
  if (!d.demo) eo.autosave_path = d.access->save_to, eo.read_only_note = d.access->read_only_note;
  eo.visuals.async = !is_replay(loop);
  eo.video = d.video;
  eo.async_suggestions = !is_replay(loop);
  return eo;
}

/// Runs the editor in the frame loop until the window closes (or the replay ends), then saves.
int edit_in_loop(EditDocument& d, const LoopCli& loop, LoopSetup& setup) {
  const EditorOptions eo = editor_options(loop, setup, d);
  DocumentOptions dopts;
  if (is_replay(loop)) dopts.keyframes.async = false;
  Editor editor(std::move(d.sidecar), dopts, eo);
  EditorClient client(
      editor, create_gl_panel_textures(),
      /*follow_window=*/eo.layout == PanelLayout::Desktop && !setup.recorded_desktop);
  if (!setup.video->properties().is_still) {
    auto thumbs = std::make_unique<ThumbnailWorker>(d.video, kTimelineThumbnails, cv::Size(192, 96),
                                                    setup.options.video_layout);
    // A replay must look the same every run: its thumbnails are there from the first frame.
    if (is_replay(loop)) thumbs->wait(std::chrono::seconds(60));
    client.set_thumbnails(std::move(thumbs));
  }
  FrameLoop frame_loop(setup.options, *setup.input, *setup.video, client);
  FrameLoopResult result;
  try {
    result = frame_loop.run();
  } catch (...) {
    client.release_textures();
    throw;
  }
  client.release_textures();
  report_loop("vdfx edit", result);
  if (!editor.finish()) {
    std::cerr << "vdfx edit: " << editor.autosave_status() << "\n";
    return kExitBadInput;  // the sidecar could not be written (e.g. a read-only folder)
  }
  if (result.stopped)
    std::cerr << "vdfx edit: " << stopped_by() << ": "
              << (d.demo ? "the bundled demo, not saved" : editor.autosave_status())
              << recording_note(loop) << "\n";
  else if (!d.demo)
    std::cerr << "vdfx edit: " << editor.autosave_status() << "\n";
  return kExitOk;
}

}  // namespace

int cmd_edit(const Args& args) {
  CLI::App cli("author view-dependent effects in the simulated headset (no VIDEO: the demo)",
               "vdfx edit");
  std::string video, sidecar_arg, recover = "ask", access = "auto";
  LoopCli loop;
  // Panel text must be legible in the mirror: at the player's 0.25 the timeline's small text
  // blurs into a few eye pixels per glyph; 0.5 reads (docs/editor.md).
  loop.scale = kEditDefaultEyeScale;
  cli.add_option("VIDEO", video, "video file or still image; default: the sidecar's video");
  cli.add_option("--sidecar", sidecar_arg,
                 "effects file (.vdfx.json) to edit, created when missing; default: VIDEO's "
                 "NAME.vdfx.json, or the bundled demo without VIDEO");
  cli.add_option(
         "--recover", recover,
         "an autosave left by a crash: yes loads it, no sets it aside (NAME.autosave.declined); "
         "default: ask on a terminal, else no")
      ->capture_default_str()
      ->check(CLI::IsMember({"ask", "yes", "no"}));
  cli.add_option("--access", access,
                 "when another editor has the sidecar open: auto opens read-only (edits saved to "
                 "a copy beside it), write exits 1, read-only never writes the sidecar")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "write", "read-only"}));
  add_loop_options(cli, loop);
  cli.footer(edit_help_footer());
  if (auto code = parse_cli(cli, args)) return *code;

  // From here a stop signal ends the session as Escape does, everything saved and the lock
  // released (docs/cli.md, "Stopping a command").
  const StopSignals stop;
  EditDocument doc = open_document(video, sidecar_arg, recover, access);
  LoopSetup setup = prepare_loop(loop, doc.video, true, {{"--sidecar", doc.sidecar_path}});
  if (!doc.exists) {
    const io::VideoProperties& p = setup.video->properties();
    doc.sidecar = io::new_sidecar({fs::absolute(doc.video).string(), p.fps.value(),
                                   std::max<std::int64_t>(1, p.frames), p.width, p.height});
    std::cerr << "vdfx edit: new sidecar " << doc.sidecar_path.string() << " for "
              << doc.video.string() << "\n";
  }
  resolve_loop_layout(setup, loop, &doc.sidecar.video, doc.sidecar_path);
  io::record_layout(doc.sidecar.video, setup.options.video_layout);
  if (doc.demo)
    std::cerr << "vdfx edit: the bundled demo, not saved (copy " << doc.sidecar_path.string()
              << " and pass --sidecar COPY to keep edits)\n";
  return edit_in_loop(doc, loop, setup);
}

}  // namespace vdfx::app
