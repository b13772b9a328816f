/// @file
/// @brief Issue 11 through the real executable, one test per class of bad input: the exit code
/// of the contract (1 input, 2 usage, never 3 for the user's mistake), a message that names the
/// file or option and the place, and no hang (every run has a time limit).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <tuple>

#include "command_test_util.h"
#include "tests/media_clips.h"
#include "tests/support/test_paths.h"

namespace vdfx::app::testing {
namespace {

namespace fs = std::filesystem;

CommandResult run(const std::string& args) {
  return run_vdfx_headless(args);
}

fs::path setup() {
  return panorama_and_sidecar();
}

struct Row {
  std::string args;
  int exit_code;
  std::string says;
};

void expect_rows(const std::vector<Row>& rows) {
  for (const Row& row : rows) {
    const CommandResult r = run(row.args);
    EXPECT_EQ(r.exit_code, row.exit_code) << row.args << "\n" << r.output.substr(0, 2000);
    EXPECT_NE(r.output.find(row.says), std::string::npos) << row.args << "\n"
                                                          << r.output.substr(0, 2000);
  }
}

TEST(BadInput, PipesDevicesAndHugeFilesAreRefusedNotWaitedOn) {
  const fs::path dir = setup();
  for (const char* name : {"pipe.vdfx.json", "pipe.png", "pipe.vdrec.jsonl", "pipe.json"})
    ASSERT_EQ(::mkfifo((dir / name).c_str(), 0600), 0);
  std::ofstream(dir / "huge.vdfx.json") << "{";
  fs::resize_file(dir / "huge.vdfx.json", std::uintmax_t{8} << 30);  // a hole: no disk used
  const std::string s = (dir / "s.vdfx.json").string(), pano = (dir / "pano.png").string();
  const std::string view = " --view 0,0 --fov 90 --size 16x8 --out " + (dir / "o.png").string();
  expect_rows({
      {"validate /dev/zero", 1, "/dev/zero: (document): is a character device"},
      {"validate " + (dir / "pipe.vdfx.json").string(), 1, "is a named pipe (FIFO)"},
      {"validate " + (dir / "huge.vdfx.json").string(), 1, "is 8 GiB, more than the 256 MiB"},
      {"render " + (dir / "pipe.png").string() + " --sidecar " + s + view, 1,
       "pipe.png: is a named pipe"},
      {"render " + pano + " --sidecar " + (dir / "pipe.vdfx.json").string() + view, 1,
       "pipe.vdfx.json: (document): is a named pipe"},
      {"replay " + (dir / "pipe.vdrec.jsonl").string() + " --video " + pano + " --sidecar-out " +
           (dir / "o.vdfx.json").string(),
       1, "pipe.vdrec.jsonl: is a named pipe"},
      {"hmd show " + (dir / "pipe.json").string(), 1, "pipe.json: is a named pipe"},
  });
}

TEST(BadInput, SizesBeyondTheirLimitsAreRefusedBeforeAllocating) {
  const fs::path dir = setup();
  cv::imwrite((dir / "wide.png").string(), cv::Mat(2, 20000, CV_8UC3, cv::Scalar(0, 0, 255)));
  const std::string common = "render " + (dir / "pano.png").string() + " --sidecar " +
                             (dir / "s.vdfx.json").string() + " --view 0,0 --fov 90 ";
  const std::string out = " --out " + (dir / "o.png").string();
  expect_rows({
      // Options: exit 2, with the limit (were 24 GB, 8.5 GB and GL errors).
      {common + "--size 64x32 --gpu --mode pixel --bake 16384x16384" + out, 2,
       "--bake: '16384x16384': each side must be at most 4096"},
      {common + "--size 16384x16384" + out, 2, "more than the 67108864 allowed (8192x8192)"},
      {common + "--size 100000x1" + out, 2, "each side must be at most 16384"},
      // An input frame: exit 1, naming the file (was a GL error on the GPU path).
      {"render " + (dir / "wide.png").string() + " --sidecar " + (dir / "s.vdfx.json").string() +
           " --view 0,0 --fov 90 --size 16x8" + out,
       1, "wide.png: the image is 20000x2; vdfx takes frames of at most 16384 pixels per side"},
  });
}

TEST(BadInput, AFileWhoseMathsWouldNotBeFiniteDoesNotValidate) {
  // fps 1e-200 validated; eval then printed null and render wrote a black image, exit 0.
  const fs::path dir = setup();
  std::string text = exposure_sidecar();
  text.replace(text.find("\"fps\": 30.0"), 11, "\"fps\": 1e-200");
  text.replace(text.find("\"frames\": 1"), 11, "\"frames\": 2");
  write_text(dir / "nan.vdfx.json", text);
  const std::string s = (dir / "nan.vdfx.json").string();
  expect_rows({
      {"validate " + s, 1,
       "nan.vdfx.json: /video/fps: one frame is 24 / fps * time_scale = 2.4e+201"},
      {"eval " + s + " --at 0,0,1", 1, "/video/fps"},
      {"render " + (dir / "pano.png").string() + " --sidecar " + s +
           " --view 0,0 --fov 90 --size 16x8 --out " + (dir / "o.png").string(),
       1, "/video/fps"},
  });
}

TEST(BadInput, KeyframesBeyondTheSolversLimitAreAnInputError) {
  // 100k keyframes in one effect validated, then eval ended in std::bad_alloc (exit 3). Local
  // interpolation splits an effect in time, but not keyframes that all share one frame.
  const fs::path dir = setup();
  std::string keys;
  for (int i = 0; i < 5000; ++i)
    keys += std::string(i ? "," : "") + R"({"azimuth_deg": )" + std::to_string(i % 359 - 179) +
            R"(, "altitude_deg": 0, "frame": 0, "params": {"stops": 0}})";
  std::string text = exposure_sidecar();
  const std::size_t at = text.find("\"keyframes\": [") + 14;
  text.replace(at, text.find("]}", at) - at, keys);
  write_text(dir / "many.vdfx.json", text);
  expect_rows({{"eval " + (dir / "many.vdfx.json").string() + " --at 0,0,0", 1,
                "many.vdfx.json: /effects/0/keyframes: 5000 keyframes at frame 0 fall into one "
                "window"}});
}

TEST(BadInput, TheUsersMistakesAreNeverInternalErrors) {
  // Each of these was exit 3 ("internal error: basic_filebuf::underflow", nlohmann's exception
  // text, ViewCamera's precondition, a filesystem_error) or exit 0 with a black image.
  const fs::path dir = setup();
  fs::create_directories(dir / "folder.vdrec.jsonl");
  fs::create_directories(dir / "folder.json");
  std::ifstream in(std::string(VDFX_SOURCE_DIR) + "/xr/headset/profiles/generic90.json");
  std::string profile((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t at = profile.find("\"refresh_hz\":") + 13;
  profile.replace(at, profile.find(',', at) - at, " 1e400");
  write_text(dir / "overflow.json", profile);
  write_text(dir / "afile", "x");
  write_short_recording(dir / "rec.vdrec.jsonl");
  const std::string pano = (dir / "pano.png").string(), s = (dir / "s.vdfx.json").string();
  const std::string render = "render " + pano + " --sidecar " + s +
                             " --view 0,0 --size 16x8 --out " + (dir / "o.png").string();
  expect_rows({
      {"replay " + (dir / "folder.vdrec.jsonl").string() + " --video " + pano + " --sidecar-out " +
           (dir / "o.vdfx.json").string(),
       1, "folder.vdrec.jsonl: is a folder, not a recording"},
      {"hmd show " + (dir / "folder.json").string(), 1,
       "folder.json: is a folder, not an HMD profile"},
      {"hmd show " + (dir / "overflow.json").string(), 1, "overflow.json: line "},
      {render + " --fov nan", 2, "--fov: 'nan' is not a finite number"},
      {render + " --fov nan --gpu", 2, "--fov: 'nan' is not a finite number"},
      {"replay " + (dir / "rec.vdrec.jsonl").string() + " --video " + pano + " --sidecar-out " +
           (dir / "o.vdfx.json").string() + " --frames " + (dir / "afile" / "sub").string(),
       1, "--frames " + (dir / "afile" / "sub").string() + ": cannot create the folder"},
      // No display for --gpu is how the command was run, not a bug: a usage error.
      {render + " --fov 90 --gpu", 2, "no display"},
  });
}

TEST(BadInput, ValuesAreReadExactlyOrRefused) {
  const fs::path dir = setup();
  std::ifstream rec_in(test_files::recordings_dir() / "sim_look_and_place.vdrec.jsonl");
  std::string header;
  std::getline(rec_in, header);
  write_text(dir / "wrap.vdrec.jsonl",
             header + "\n" +
                 R"({"t_ns":9223372036854775808,"head":{"q":[1,0,0,0],"p":[0,1.6,0]}})"
                 "\n");
  const std::string render = "render " + (dir / "pano.png").string() + " --sidecar " +
                             (dir / "s.vdfx.json").string() +
                             " --view 0,0 --fov 90 --size 16x8 --out " + (dir / "o.png").string();
  expect_rows({
      // Was accepted as a negative time (exit 0).
      {"replay " + (dir / "wrap.vdrec.jsonl").string() + " --video " + (dir / "pano.png").string() +
           " --sidecar-out " + (dir / "o.vdfx.json").string(),
       1, "wrap.vdrec.jsonl:2: /t_ns: time 9223372036854775808 is beyond"},
      // Was read as 2^63 - 1 ("frame 9223372036854775807 does not exist").
      {render + " --frame 9223372036854775808", 2,
       "--frame: '9223372036854775808' is out of range [0, 9223372036854775807]"},
      // Printed its range with 309 digits.
      {render + " --frame -1", 2, "--frame: '-1' is out of range [0, 9223372036854775807]"},
  });
  EXPECT_LT(run(render + " --frame -1").output.size(), 200u);
}

TEST(BadInput, MessagesAreShortSayWhatAndComeAlone) {
  const fs::path dir = setup();
  std::string text = exposure_sidecar();
  text.replace(text.find("30.0"), 4, "1" + std::string(10'000'000, '0'));
  write_text(dir / "long.vdfx.json", text);
  std::string nul = exposure_sidecar();
  nul[nul.find("\"video\"")] = '\0';
  write_text(dir / "nul.vdfx.json", nul);
  // Random bytes named .mp4: OpenCV, FFmpeg and GStreamer each printed their complaint first.
  std::string noise(4096, '\0');
  for (std::size_t i = 0; i < noise.size(); ++i) noise[i] = static_cast<char>((i * 7919u) >> 3);
  write_text(dir / "broken.mp4", noise);
  const std::string s = (dir / "s.vdfx.json").string();
  const std::string render = "render " + (dir / "pano.png").string() + " --sidecar " + s +
                             " --view 0,0 --fov 90 --size 16x8 --out " + (dir / "o.png").string();
  expect_rows({
      {"validate " + (dir / "long.vdfx.json").string(), 1, "number overflow parsing '10000000000"},
      {"validate " + (dir / "nul.vdfx.json").string(), 1, "a NUL byte"},
      // Options that would do nothing were accepted silently.
      {render + " --eye right", 2, "--eye: needs --hmd"},
      {render + " --no-lca", 2, "--no-lca: needs --distort"},
      {render + " --bake 64x32", 2, "--bake: needs --gpu --mode pixel"},
  });
  EXPECT_LT(run("validate " + (dir / "long.vdfx.json").string()).output.size(), 500u);
  const CommandResult broken =
      run("render " + (dir / "broken.mp4").string() + " --sidecar " + s +
          " --view 0,0 --fov 90 --size 16x8 --out " + (dir / "o.png").string());
  EXPECT_EQ(broken.exit_code, 1);
  EXPECT_EQ(broken.output.rfind("vdfx render: " + (dir / "broken.mp4").string() + ": ", 0), 0u)
      << broken.output;
  EXPECT_EQ(std::count(broken.output.begin(), broken.output.end(), '\n'), 1) << broken.output;
}

TEST(BadInput, ACutOrDamagedVideoIsAnInputErrorNotAHang) {
  const fs::path dir = setup();
  test_media::ClipSpec spec;
  spec.frames = 48;
  spec.gop = 12;
  const fs::path mp4 = test_media::write_clip(dir / "full.mp4", spec);  // index at the end
  const fs::path mkv = test_media::write_clip(dir / "full.mkv", spec);
  const auto cut = [&](const fs::path& full, const std::string& name, double keep) {
    fs::copy_file(full, dir / name);
    fs::resize_file(dir / name,
                    static_cast<std::uintmax_t>(static_cast<double>(fs::file_size(full)) * keep));
    return dir / name;
  };
  const fs::path mp4_cut = cut(mp4, "cut.mp4", 0.5);
  const fs::path mkv_cut = cut(mkv, "cut.mkv", 0.5);  // the frames before the cut are there
  // Noise over the middle half of the file (headers and the first frames intact).
  const fs::path noisy = dir / "noisy.mkv";
  fs::copy_file(mkv, noisy);
  {
    std::fstream f(noisy, std::ios::in | std::ios::out | std::ios::binary);
    const auto size = static_cast<std::streamoff>(fs::file_size(noisy));
    f.seekp(size / 4);
    for (std::streamoff i = size / 4; i < 3 * size / 4; ++i)
      f.put(static_cast<char>((i * 7919) >> 5));
  }
  const std::string s = (dir / "s.vdfx.json").string();
  const auto render = [&](const fs::path& video, int frame) {
    return run("render " + video.string() + " --sidecar " + s +
               " --view 0,0 --fov 90 --size 16x8 --frame " + std::to_string(frame) + " --out " +
               (dir / "o.png").string());
  };
  // Each: the contract's exit 1 (run() has a 60 s limit: a hang fails as 124), one line that
  // starts with the command and the file.
  for (const auto& [video, frame, says] :
       {std::tuple{mp4_cut, 0, ""}, std::tuple{mkv_cut, 47, "frame 47 does not exist"},
        std::tuple{noisy, 47, ""}}) {
    const CommandResult r = render(video, frame);
    EXPECT_EQ(r.exit_code, 1) << video << "\n" << r.output;
    EXPECT_EQ(r.output.rfind("vdfx render: " + video.string() + ": ", 0), 0u) << r.output;
    EXPECT_NE(r.output.find(says), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  }
  // The intact part of the cut file still renders.
  EXPECT_EQ(render(mkv_cut, 0).exit_code, 0);
}

TEST(BadInput, ACorruptAutosaveIsNotReportedAsRecovered) {
  // `edit --recover yes` printed "recovered" and then failed on the autosave.
  const fs::path dir = setup();
  write_text(dir / "s.vdfx.json.autosave", "{broken");
  const CommandResult r = run("edit " + (dir / "pano.png").string() + " --sidecar " +
                              (dir / "s.vdfx.json").string() + " --recover yes");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("s.vdfx.json.autosave: (document): line 1, column 2"), std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("recovered"), std::string::npos) << r.output;
  EXPECT_EQ(test_files::slurp(dir / "s.vdfx.json.autosave"), "{broken");
}

}  // namespace
}  // namespace vdfx::app::testing
