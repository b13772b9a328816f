/// @file
/// @brief An existing --sidecar-out is an author's work (io/sidecar_target.h), through the real
/// executable for every command that writes a sidecar (`suggest`, `replay`): without
/// --sidecar-in it is added to, a different --sidecar-in never replaces it without --force, the
/// same file may be both, and a file that is not a sidecar is kept unless --force.
#include <gtest/gtest.h>

#include <filesystem>

#include "command_test_util.h"
#include "io/sidecar.h"
#include "tests/support/test_paths.h"

namespace vdfx::app::testing {
namespace {

namespace fs = std::filesystem;
using test_files::slurp;

/// The author's work as the editor leaves it: one contrast effect with two keyframes.
std::string contrast_sidecar() {
  return R"({"format": "vdfx.sidecar", "version": 1,
  "video": {"path": "pano.png", "fps": 30.0, "frames": 1, "width": 256, "height": 128},
  "interpolation": {"exponent": 1.0, "time_scale": 1.0},
  "effects": [
    {"type": "contrast", "keyframes": [
      {"azimuth_deg": 20.0, "altitude_deg": 0.0, "frame": 0, "params": {"amount": 1.5}},
      {"azimuth_deg": -70.0, "altitude_deg": 5.0, "frame": 0, "params": {"amount": 0.7}}]}]})";
}

const effects::EffectTrack* track(const io::Sidecar& s, effects::EffectType type) {
  for (const auto& t : s.effects)
    if (t.type == type) return &t;
  return nullptr;
}

/// The commands that write a sidecar, each as "everything before --sidecar-out" in `dir`.
struct Writer {
  const char* name;
  std::string (*args)(const fs::path& dir);
  const char* onto_exposure;  //!< what it needs to add to a sidecar with exposure keyframes
};

const Writer kWriters[] = {
    {"suggest",
     [](const fs::path& dir) {
       return "suggest exposure " + (dir / "pano.png").string() + " --strength 0.8";
     },
     " --merge"},
    {"replay",
     [](const fs::path& dir) {
       return "replay " + (dir / "rec.vdrec.jsonl").string() + " --video " +
              (dir / "pano.png").string();
     },
     ""},
};

fs::path setup() {
  const fs::path dir = test_dir();
  write_test_panorama(dir);
  write_short_recording(dir / "rec.vdrec.jsonl");
  write_text(dir / "clip.vdfx.json", contrast_sidecar());
  write_text(dir / "other.vdfx.json", exposure_sidecar());
  return dir;
}

TEST(SidecarOut, SuggestAddsToTheAuthorsSidecarAsTheReadmeRunsIt) {
  const fs::path dir = setup();
  const fs::path out = dir / "clip.vdfx.json";
  const CommandResult r =
      run_vdfx_headless(kWriters[0].args(dir) + " --sidecar-out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(
      r.output.find("added to the existing " + out.string() + " (it had 1 effect, 2 keyframes)"),
      std::string::npos)
      << r.output;
  const io::Sidecar s = io::read_sidecar(out);
  const auto* contrast = track(s, effects::EffectType::Contrast);
  ASSERT_NE(contrast, nullptr);
  EXPECT_EQ(contrast->keyframes.size(), 2u);
  const auto* exposure = track(s, effects::EffectType::Exposure);
  ASSERT_NE(exposure, nullptr);
  EXPECT_GT(exposure->keyframes.size(), 0u);
}

TEST(SidecarOut, ReplayIsReplayedOntoAnExistingSidecarOut) {
  const fs::path dir = setup();
  const fs::path out = dir / "clip.vdfx.json";
  const io::Sidecar before = io::read_sidecar(out);
  const CommandResult r =
      run_vdfx_headless(kWriters[1].args(dir) + " --sidecar-out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("added to the existing"), std::string::npos) << r.output;
  const io::Sidecar after = io::read_sidecar(out);
  ASSERT_NE(track(after, effects::EffectType::Contrast), nullptr);
  EXPECT_EQ(track(after, effects::EffectType::Contrast)->keyframes,
            track(before, effects::EffectType::Contrast)->keyframes);
}

TEST(SidecarOut, AnotherSidecarInReplacesAnExistingOutOnlyWithForce) {
  for (const Writer& w : kWriters) {
    SCOPED_TRACE(w.name);
    const fs::path dir = setup();
    const fs::path out = dir / "clip.vdfx.json";
    const std::string kept = slurp(out);
    const std::string line = w.args(dir) + " --sidecar-in " + (dir / "other.vdfx.json").string() +
                             " --sidecar-out " + out.string() + w.onto_exposure;
    const CommandResult refused = run_vdfx_headless(line);
    EXPECT_EQ(refused.exit_code, 1) << refused.output;
    EXPECT_NE(refused.output.find("--sidecar-out " + out.string() +
                                  ": the file exists and would be replaced by --sidecar-in"),
              std::string::npos)
        << refused.output;
    EXPECT_NE(refused.output.find("--force"), std::string::npos) << refused.output;
    EXPECT_EQ(slurp(out), kept);
    EXPECT_FALSE(fs::exists(dir / "clip.vdfx.json.lock"));

    const CommandResult forced = run_vdfx_headless(line + " --force");
    ASSERT_EQ(forced.exit_code, 0) << forced.output;
    EXPECT_NE(forced.output.find("replaced " + out.string() + " (--force)"), std::string::npos)
        << forced.output;
    const io::Sidecar s = io::read_sidecar(out);
    EXPECT_EQ(track(s, effects::EffectType::Contrast), nullptr);  // replaced, as asked
    EXPECT_NE(track(s, effects::EffectType::Exposure), nullptr);
  }
}

TEST(SidecarOut, TheSameFileAsInAndOutIsUpdatedInPlace) {
  for (const Writer& w : kWriters) {
    SCOPED_TRACE(w.name);
    const fs::path dir = setup();
    const fs::path out = dir / "clip.vdfx.json";
    const CommandResult r = run_vdfx_headless(w.args(dir) + " --sidecar-in " + out.string() +
                                              " --sidecar-out " + out.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const io::Sidecar s = io::read_sidecar(out);
    ASSERT_NE(track(s, effects::EffectType::Contrast), nullptr);
    EXPECT_EQ(track(s, effects::EffectType::Contrast)->keyframes.size(), 2u);
  }
}

TEST(SidecarOut, AFileThatIsNotASidecarIsKeptUnlessForced) {
  for (const Writer& w : kWriters) {
    SCOPED_TRACE(w.name);
    const fs::path dir = setup();
    const fs::path out = dir / "notes.txt";
    write_text(out, "shot list: take 2 is the good one\n");
    const CommandResult r = run_vdfx_headless(w.args(dir) + " --sidecar-out " + out.string());
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("--sidecar-out " + out.string() +
                            " exists and is not a sidecar vdfx can add to; pass --force"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(slurp(out), "shot list: take 2 is the good one\n");
    const CommandResult forced =
        run_vdfx_headless(w.args(dir) + " --sidecar-out " + out.string() + " --force");
    ASSERT_EQ(forced.exit_code, 0) << forced.output;
    EXPECT_NO_THROW(io::read_sidecar(out));
  }
}

/// A sidecar made for a 1024x512, 90-frame clip, and what each command that takes a video and a
/// sidecar says when given the 256x128 still instead: a warning naming both and each difference
/// (docs/cli.md), the command still done.
TEST(SidecarOut, EveryCommandThatTakesBothSaysWhenTheVideoIsAnother) {
  const fs::path dir = setup();
  std::string other = exposure_sidecar();
  const std::string still = "\"frames\": 1, \"width\": 256, \"height\": 128";
  other.replace(other.find(still), still.size(),
                "\"frames\": 90, \"width\": 1024, \"height\": 512");
  write_text(dir / "made_for_another.vdfx.json", other);
  const std::string pano = (dir / "pano.png").string();
  const std::string s = (dir / "made_for_another.vdfx.json").string();
  const std::string lines[] = {
      "render " + pano + " --sidecar " + s + " --view 0,0 --fov 90 --size 64x48 --out " +
          (dir / "v.png").string(),
      "export " + pano + " --sidecar " + s + " --baked " + (dir / "b.mp4").string(),
      "suggest exposure " + pano + " --sidecar-in " + s + " --sidecar-out " +
          (dir / "sg.vdfx.json").string() + " --merge",
      "replay " + (dir / "rec.vdrec.jsonl").string() + " --video " + pano + " --sidecar-in " + s +
          " --sidecar-out " + (dir / "r.vdfx.json").string(),
  };
  for (const std::string& line : lines) {
    SCOPED_TRACE(line);
    const CommandResult r = run_vdfx_headless(line);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("warning: " + pano + " is not the video " + s +
                            " was made for (its video section): 1 frame where the sidecar has "
                            "90; 256x128 where the sidecar has 1024x512"),
              std::string::npos)
        << r.output;
  }
  // The sidecar made for it: not a word.
  const CommandResult same =
      run_vdfx_headless("render " + pano + " --sidecar " + (dir / "other.vdfx.json").string() +
                        " --view 0,0 --fov 90 --size 64x48 --out " + (dir / "w.png").string());
  EXPECT_EQ(same.exit_code, 0) << same.output;
  EXPECT_EQ(same.output.find("warning"), std::string::npos) << same.output;
}

}  // namespace
}  // namespace vdfx::app::testing
