/// @file
/// @brief `vdfx bench`: a quick run on two cheap knobs checked against the report's JSON schema
/// (docs/bench.schema.json, by Debian's python3-jsonschema), finite non-negative errors, every
/// row naming its reference and peer, the CSV and markdown forms, PNG plots of the requested
/// size; GL rows listed as skipped without a display; usage and input errors. No timing is
/// asserted. Also the Pareto front and the timing summaries on their own.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/bench/plot.h"
#include "app/bench/report.h"
#include "app/bench/timing.h"
#include "command_test_util.h"
#include "tests/support/test_paths.h"

namespace vdfx::app {
namespace {

using testing::run_vdfx;
using testing::test_dir;

const std::string kSchema = std::string(VDFX_SOURCE_DIR) + "/docs/bench.schema.json";

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Validates a JSON file against the schema with Debian's jsonschema; empty when valid.
std::string schema_problem(const std::filesystem::path& json) {
  const std::string cmd =
      "/usr/bin/python3 -c 'import json, sys, jsonschema; "
      "jsonschema.validate(json.load(open(sys.argv[1])), json.load(open(sys.argv[2])))' '" +
      json.string() + "' '" + kSchema + "' 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return "cannot run python3";
  std::string out;
  char buf[4096];
  while (fgets(buf, sizeof buf, pipe)) out += buf;
  const int status = pclose(pipe);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? std::string()
                                                       : (out.empty() ? "failed" : out);
}

/// Width and height from a PNG's signature and IHDR chunk; {-1, -1} when it is no PNG.
std::pair<int, int> png_size(const std::filesystem::path& p) {
  const std::string b = read_file(p);
  const std::string sig = "\x89PNG\r\n\x1a\n";
  if (b.size() < 24 || b.compare(0, 8, sig) != 0 || b.compare(12, 4, "IHDR") != 0) return {-1, -1};
  const auto be32 = [&](std::size_t at) {
    return (static_cast<unsigned char>(b[at]) << 24) |
           (static_cast<unsigned char>(b[at + 1]) << 16) |
           (static_cast<unsigned char>(b[at + 2]) << 8) | static_cast<unsigned char>(b[at + 3]);
  };
  return {static_cast<int>(be32(16)), static_cast<int>(be32(20))};
}

TEST(BenchCommand, QuickReportOnTwoCheapKnobsFollowsItsSchemaWithPlotsOfTheRequestedSize) {
  const auto dir = test_dir();
  const auto r = run_vdfx(
      "bench --quick --filter '^(lens\\.inverse|rbf\\.solve/N=(10|100)$)' --json " +
      (dir / "r.json").string() + " --csv " + (dir / "r.csv").string() + " --markdown " +
      (dir / "r.md").string() + " --plot " + (dir / "plots").string() + " --plot-size 400x300");
  ASSERT_EQ(r.exit_code, 0) << r.output;

  EXPECT_EQ(schema_problem(dir / "r.json"), "");
  const auto j = nlohmann::json::parse(read_file(dir / "r.json"));
  ASSERT_EQ(j["rows"].size(), 6u);  // 4 inverses, 2 solves
  ASSERT_EQ(j["knobs"].size(), 2u);
  EXPECT_FALSE(j["machine"]["cpu"].get<std::string>().empty());
  for (const auto& row : j["rows"]) {
    SCOPED_TRACE(row.dump());
    EXPECT_EQ(row["status"], "ok");
    for (const char* e : {"max", "rms"}) {
      ASSERT_TRUE(row["error"][e].is_number());
      const double v = row["error"][e];
      EXPECT_TRUE(std::isfinite(v));
      EXPECT_GE(v, 0.0);
    }
    EXPECT_FALSE(row["error"]["reference"].get<std::string>().empty());
    EXPECT_FALSE(row["peer"]["name"].get<std::string>().empty());
    EXPECT_GT(row["time"]["median_s"].get<double>(), 0.0);
    EXPECT_GT(row["peer"]["median_s"].get<double>(), 0.0);
  }
  // The errors mean what they say: the closed form is pixels off at the panel edge, Newton is not.
  for (const auto& row : j["rows"]) {
    if (row["setting"] == "closed form") {
      EXPECT_GT(row["error"]["max"].get<double>(), 1.0);
    }
    if (row["setting"] == "Newton") {
      EXPECT_LT(row["error"]["max"].get<double>(), 1e-6);
    }
  }

  const std::string md = read_file(dir / "r.md");
  EXPECT_NE(md.find("## lens.inverse"), std::string::npos);
  EXPECT_NE(md.find("| N=100 |"), std::string::npos);
  EXPECT_NE(r.output.find("## rbf.solve"), std::string::npos);  // markdown on stdout too
  std::istringstream csv(read_file(dir / "r.csv"));
  int lines = 0;
  for (std::string l; std::getline(csv, l);) ++lines;
  EXPECT_EQ(lines, 7);

  for (const char* knob : {"lens.inverse", "rbf.solve"}) {
    const auto size = png_size(dir / "plots" / (std::string(knob) + ".png"));
    EXPECT_EQ(size.first, 400) << knob;
    EXPECT_EQ(size.second, 300) << knob;
  }
}

TEST(BenchCommand, TheSchemaRejectsANegativeErrorAndAMissingPeer) {
  const auto dir = test_dir();
  const auto r =
      run_vdfx("bench --quick --filter '^rbf\\.solve/N=10$' --json " + (dir / "r.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  auto j = nlohmann::json::parse(read_file(dir / "r.json"));
  ASSERT_EQ(schema_problem(dir / "r.json"), "");
  j["rows"][0]["error"]["max"] = -1.0;
  std::ofstream(dir / "negative.json") << j.dump();
  EXPECT_NE(schema_problem(dir / "negative.json"), "");
  j["rows"][0]["error"]["max"] = 0.0;
  j["rows"][0]["peer"]["name"] = "";
  std::ofstream(dir / "no_peer.json") << j.dump();
  EXPECT_NE(schema_problem(dir / "no_peer.json"), "");
}

TEST(BenchCommand, GlRowsWithoutADisplayAreListedAsSkippedWithTheReason) {
  const auto dir = test_dir();
  const auto r =
      run_vdfx("bench --quick --filter '^lens\\.lca/' --json " + (dir / "r.json").string(),
               "env -u DISPLAY -u WAYLAND_DISPLAY ");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(schema_problem(dir / "r.json"), "");
  const auto j = nlohmann::json::parse(read_file(dir / "r.json"));
  ASSERT_EQ(j["rows"].size(), 2u);
  for (const auto& row : j["rows"]) {
    EXPECT_EQ(row["status"], "skipped");
    EXPECT_NE(row["reason"].get<std::string>().find("display"), std::string::npos) << row["reason"];
  }
  EXPECT_NE(r.output.find("skipped: needs GL"), std::string::npos) << r.output;
}

// The grain knob (GL, run under Xvfb like every GL test): a shader style's GPU layer against the
// CPU reference is well under one 8-bit step while the grain itself moves the image by several
// steps (so the comparison compares something); a volumetric style has no reference, says so,
// and its null errors pass the schema.
TEST(BenchCommand, GrainRowsCompareTheShaderStylesAndNameTheMissingReference) {
  const auto dir = test_dir();
  const auto r = run_vdfx("bench --quick --filter '^grain/' --json " + (dir / "r.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(schema_problem(dir / "r.json"), "");
  const auto j = nlohmann::json::parse(read_file(dir / "r.json"));
  ASSERT_EQ(j["rows"].size(), 2u);
  const auto extra = [](const nlohmann::json& row, const char* name) {
    return row["extra"].contains(name) ? row["extra"][name].get<double>() : -1.0;
  };
  for (const auto& row : j["rows"]) {
    SCOPED_TRACE(row.dump());
    ASSERT_EQ(row["status"], "ok");
    EXPECT_GT(row["time"]["median_s"].get<double>(), 0.0);
    EXPECT_GT(row["peer"]["median_s"].get<double>(), 0.0);
    if (row["setting"] == "surface") {
      EXPECT_LT(row["error"]["max"].get<double>(), 1.0);
      EXPECT_GT(extra(row, "grain_rms_steps"), 2.0);
    } else {
      EXPECT_EQ(row["setting"], "object_cloud");
      EXPECT_EQ(row["error"]["reference"].get<std::string>().rfind("none", 0), 0u);
      EXPECT_TRUE(row["error"]["max"].is_null());
    }
  }
}

// The OpenXR knob (GL, the simulated runtime beside the executable in the build tree): the
// headset's frame and the sim's, both measured, no error (the pixels are OpenXrFrames' tests);
// and where the runtime is not beside the executable, the row says what it needs.
TEST(BenchCommand, OpenXrRowTimesTheHeadsetFrameBesideTheSims) {
  const auto dir = test_dir();
  const auto r =
      run_vdfx("bench --quick --filter '^openxr\\.' --json " + (dir / "r.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(schema_problem(dir / "r.json"), "");
  const auto j = nlohmann::json::parse(read_file(dir / "r.json"));
  ASSERT_EQ(j["rows"].size(), 1u);
  const auto& row = j["rows"][0];
  ASSERT_EQ(row["status"], "ok") << row.dump();
  EXPECT_GT(row["time"]["median_s"].get<double>(), 0.0);
  EXPECT_GT(row["peer"]["median_s"].get<double>(), 0.0);
  EXPECT_TRUE(row["error"]["max"].is_null());

  // A copy of the executables without the build tree's runtime beside them.
  const auto alone = dir / "alone";
  std::filesystem::create_directories(alone);
  for (const char* f : {"vdfx", "libvdfx_media.so"})
    std::filesystem::copy_file(std::filesystem::path(VDFX_BINARY).parent_path() / f, alone / f);
  const std::string cmd = (alone / "vdfx").string() +
                          " bench --quick --filter '^openxr\\.' --json " +
                          (dir / "s.json").string() + " > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const auto k = nlohmann::json::parse(read_file(dir / "s.json"));
  ASSERT_EQ(k["rows"].size(), 1u);
  EXPECT_EQ(k["rows"][0]["status"], "skipped");
  EXPECT_NE(k["rows"][0]["reason"].get<std::string>().find("simulated OpenXR runtime"),
            std::string::npos);
}

// The video knobs (a generated clip): vdfx's decode path hands on exactly the code values
// FFmpeg's plain loop decodes, every frame in order; the baked export's grid stays within one
// 8-bit step of the exact per-pixel render (with a step above 1: the grid is what is compared).
TEST(BenchCommand, VideoRowsDecodeWhatFFmpegDecodesAndBakeWithinOneStep) {
  const auto dir = test_dir();
  const auto r = run_vdfx("bench --quick --filter '^video\\.' --json " + (dir / "r.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(schema_problem(dir / "r.json"), "");
  const auto j = nlohmann::json::parse(read_file(dir / "r.json"));
  // H.264 decode, the top-bottom and the mono HEVC decode (docs/stereo.md), the export.
  ASSERT_EQ(j["rows"].size(), 4u);
  for (const auto& row : j["rows"]) {
    SCOPED_TRACE(row.dump());
    ASSERT_EQ(row["status"], "ok");
    EXPECT_GT(row["peer"]["median_s"].get<double>(), 0.0);
    if (row["knob"] == "video.decode") {
      EXPECT_EQ(row["error"]["max"].get<double>(), 0.0);
      if (row["setting"].get<std::string>().find("top-bottom") != std::string::npos) {
        EXPECT_GT(row["extra"]["vs_mono"].get<double>(), 0.0);  // timed beside the mono clip
      }
    } else {
      EXPECT_EQ(row["knob"], "video.export");
      EXPECT_LT(row["error"]["max"].get<double>(), 1.0);
      EXPECT_GT(row["extra"]["param_step"].get<double>(), 1.0);  // a grid, not the reference
    }
  }
}

// The suggestion's knob (docs/suggest.md, "Measured"): each fit ends within its tolerance, a
// tighter tolerance takes more keyframes.
TEST(BenchCommand, SuggestRowsPlaceMoreKeyframesForATighterTolerance) {
  const auto dir = test_dir();
  const auto r =
      run_vdfx("bench --quick --filter '^suggest\\.' --json " + (dir / "r.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(schema_problem(dir / "r.json"), "");
  const auto j = nlohmann::json::parse(read_file(dir / "r.json"));
  ASSERT_EQ(j["rows"].size(), 2u);
  std::vector<double> keyframes, tolerance{0.5, 0.1};
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& row = j["rows"][i];
    SCOPED_TRACE(row.dump());
    ASSERT_EQ(row["status"], "ok");
    EXPECT_EQ(row["knob"], "suggest.exposure");
    EXPECT_LE(row["error"]["max"].get<double>(), tolerance[i] + 1e-9);
    EXPECT_EQ(row["extra"]["within_tolerance"].get<double>(), 1.0);
    EXPECT_GT(row["peer"]["median_s"].get<double>(), 0.0);
    keyframes.push_back(row["extra"]["keyframes"].get<double>());
  }
  EXPECT_GT(keyframes[0], 0.0);
  EXPECT_GT(keyframes[1], keyframes[0]);
}

// The trackers' knobs (docs/anchors.md, "Measured"): against their clips' known truth the camera
// stays within its goals and the subject's hidden frames are all reported.
TEST(BenchCommand, TrackRowsMeetTheirGoalsOnTheirClips) {
  const auto dir = test_dir();
  const auto r = run_vdfx(
      "bench --quick --filter '^track[.](camera_width/W=512|subject_template/seam T=32)$' "
      "--json " +
      (dir / "r.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(schema_problem(dir / "r.json"), "");
  const auto j = nlohmann::json::parse(read_file(dir / "r.json"));
  ASSERT_EQ(j["rows"].size(), 2u);
  const auto& camera = j["rows"][0];
  SCOPED_TRACE(camera.dump());
  ASSERT_EQ(camera["status"], "ok");
  EXPECT_LE(camera["error"]["rms"].get<double>(), 0.1);
  EXPECT_LE(camera["error"]["max"].get<double>(), 0.3);
  EXPECT_GT(camera["peer"]["median_s"].get<double>(), 0.0);
  EXPECT_EQ(camera["extra"]["held"].get<double>(), 0.0);
  const auto& subject = j["rows"][1];
  SCOPED_TRACE(subject.dump());
  ASSERT_EQ(subject["status"], "ok");
  EXPECT_LE(subject["error"]["rms"].get<double>(), 1.0);
  EXPECT_EQ(subject["extra"]["hidden_frames_not_reported"].get<double>(), 0.0);
  EXPECT_EQ(subject["extra"]["visible_frames_lost"].get<double>(), 0.0);
}

TEST(BenchCommand, UsageAndInputErrorsUseTheContractsExitCodes) {
  const auto dir = test_dir();
  EXPECT_EQ(run_vdfx("bench --filter '('").exit_code, 2);
  const auto none = run_vdfx("bench --filter no-such-knob");
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.output.find("--list"), std::string::npos);
  EXPECT_EQ(run_vdfx("bench --plot-size 0x10 --filter x").exit_code, 2);
  const auto missing = run_vdfx("bench --quick --filter '^rbf\\.solve/N=10$' --json " +
                                (dir / "no" / "such" / "r.json").string());
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.output.find("does not exist"), std::string::npos);
  // A plot folder that cannot be made is found before the run, not after it as an internal error.
  testing::write_text(dir / "afile", "x");
  const auto plot = run_vdfx("bench --quick --filter '^rbf\\.solve/N=10$' --plot " +
                             (dir / "afile" / "plots").string());
  EXPECT_EQ(plot.exit_code, 1) << plot.output;
  EXPECT_NE(plot.output.find("--plot " + (dir / "afile" / "plots").string() +
                             ": cannot create the folder"),
            std::string::npos)
      << plot.output;
  EXPECT_EQ(plot.output.find("rbf.solve"), std::string::npos) << plot.output;  // nothing ran
  const auto list = run_vdfx("bench --quick --list");
  EXPECT_EQ(list.exit_code, 0);
  EXPECT_NE(list.output.find("lens.mesh/N=65  (GL)"), std::string::npos);
}

namespace b = vdfx::app::bench;

TEST(BenchReport, TheParetoFrontIsPerSeriesAndOnlyForAlternatives) {
  b::Report rep;
  rep.knobs = {{"x.alt", "", "view", "px", "ref", "peer", b::PlotError::Max, false, true},
               {"x.size", "", "view", "px", "ref", "peer", b::PlotError::Max, false, false}};
  const auto row = [](const char* knob, const char* series, double t, double e) {
    b::Row r;
    r.knob = knob;
    r.series = series;
    r.time.median_s = t;
    r.error = {e, e};
    return r;
  };
  rep.rows = {row("x.alt", "a", 1, 10), row("x.alt", "a", 2, 1), row("x.alt", "a", 3, 5),
              row("x.alt", "b", 9, 9), row("x.size", "", 1, 1)};
  b::mark_pareto_fronts(rep);
  EXPECT_TRUE(rep.rows[0].pareto);
  EXPECT_TRUE(rep.rows[1].pareto);
  EXPECT_FALSE(rep.rows[2].pareto);  // slower and less accurate than the second
  EXPECT_TRUE(rep.rows[3].pareto);   // alone in its series
  EXPECT_FALSE(rep.rows[4].pareto);  // sizes are not alternatives
}

// A plot replaces its file atomically: the PNG is drawn in a work folder and then written with
// io::write_file_atomic. So an old plot is replaced by a rename, never rewritten in place (a hard
// link to the old file keeps the old bytes), a plot path that is a link keeps the link (its
// target gets the picture), and nothing else is left in the folder.
TEST(BenchPlot, PlotsReplaceTheirFilesByRenameAndWriteThroughLinks) {
  namespace fs = std::filesystem;
  ASSERT_EQ(b::gnuplot_problem(), "");
  const fs::path dir = fs::temp_directory_path() / ("vdfx_plot_atomic_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "plots");
  std::ofstream(dir / "plots" / "x.size.png") << "old";
  fs::create_hard_link(dir / "plots" / "x.size.png", dir / "old.png");
  std::ofstream(dir / "target.png") << "old";
  fs::create_symlink(dir / "target.png", dir / "plots" / "x.alt.png");
  b::Report rep;
  rep.knobs = {{"x.size", "", "view", "px", "ref", "peer", b::PlotError::Max, false, false},
               {"x.alt", "", "view", "px", "ref", "peer", b::PlotError::Max, false, true}};
  for (const char* knob : {"x.size", "x.alt"})
    for (int i = 1; i <= 3; ++i) {
      b::Row r;
      r.knob = knob;
      r.setting = std::to_string(i);
      r.time.median_s = i * 1e-3;
      r.error = {1.0 / i, 0.5 / i};
      rep.rows.push_back(r);
    }
  b::PlotOptions o;
  o.dir = dir / "plots";
  EXPECT_EQ(b::write_plots(rep, o).size(), 2u);
  const auto head = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::string h(8, '\0');
    in.read(h.data(), 8);
    return h.substr(0, static_cast<std::size_t>(in.gcount()));
  };
  const std::string png = "\x89PNG\r\n\x1a\n";
  EXPECT_EQ(head(dir / "plots" / "x.size.png"), png);
  EXPECT_EQ(head(dir / "old.png"), "old");  // replaced by rename, not rewritten in place
  EXPECT_TRUE(fs::is_symlink(dir / "plots" / "x.alt.png"));
  EXPECT_EQ(head(dir / "target.png"), png);
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir / "plots")) ++entries;
  EXPECT_EQ(entries, 2);  // the two plots: no temporary file left
  fs::remove_all(dir);
}

TEST(BenchTiming, MedianP90AndInterleavedSamplesPerUnit) {
  EXPECT_EQ(b::median_of({5, 1, 3}), 3);
  EXPECT_EQ(b::p90_of({1, 2, 3, 4, 5, 6, 7, 8, 9, 10}), 9);
  EXPECT_EQ(b::p90_of({4}), 4);
  int subject = 0, peer = 0, resets = 0;
  const b::Budget budget{0.0, 4, 10};
  const auto t =
      b::measure_pair({[&] { ++subject; }, 1000.0, [&] { ++resets; }}, {[&] { ++peer; }}, budget);
  EXPECT_EQ(t.subject.samples, 4);  // the warm-up is not a sample
  EXPECT_EQ(subject, 5);
  EXPECT_EQ(peer, 5);
  EXPECT_EQ(resets, 5);
  EXPECT_GE(t.subject.median_s, 0.0);
}

}  // namespace
// The volumetric grain's cost knobs: every row runs (the layer generates a million particles on
// the GPU), gives a time and passes the schema; the refresh rows say no particle is sampled.
TEST(BenchCommand, GrainCostRowsRunAtEveryCount) {
  const auto dir = test_dir();
  const auto r = run_vdfx("bench --quick --filter '^grain[.]' --json " + (dir / "r.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(schema_problem(dir / "r.json"), "");
  const auto j = nlohmann::json::parse(read_file(dir / "r.json"));
  ASSERT_EQ(j["rows"].size(), 8u);  // 2 refresh counts, 3 clouds x 2 counts
  for (const auto& row : j["rows"]) {
    SCOPED_TRACE(row.dump());
    ASSERT_EQ(row["status"], "ok");
    EXPECT_GT(row["time"]["median_s"].get<double>(), 0.0);
    if (row["knob"] == "grain.refresh") {
      EXPECT_NE(row["note"].get<std::string>().find("no particle is sampled"), std::string::npos);
    }
  }
}

}  // namespace vdfx::app
