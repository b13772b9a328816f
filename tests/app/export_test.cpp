/// @file
/// @brief `vdfx export` end to end on clips made in the test (tests/media_clips.h), checked the
/// way ffprobe would through libavformat: Spherical Video V2 side data, audio copied packet for
/// packet, frame count, size and timestamps; exported pixels against the CPU renders (lossless
/// settings: within 2/255); the viewer's path against `vdfx render`; a killed or interrupted
/// export leaves the previous file byte-identical.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <thread>
#include <vector>

extern "C" {
#include <libavutil/spherical.h>
#include <libavutil/stereo3d.h>
}

#include "app/export/baked_export.h"
#include "app/export/path_export.h"
#include "command_test_util.h"
#include "effects/stack_interpolator.h"
#include "effects/view_renderer.h"
#include "export_test_util.h"
#include "io/frame_decoder.h"
#include "io/libav_util.h"
#include "io/recording.h"
#include "io/sidecar.h"
#include "io/ycbcr.h"
#include "tests/media_clips.h"
#include "tests/support/test_paths.h"
#include "tests/test_files.h"
#include "xr/input/actions.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;
using testing::command_output;
using testing::run_vdfx;
using testing::test_dir;
using testing::write_text;

using testing::decoded_rgb8;
using testing::Fixture;
using testing::kFrames;
using testing::kH;
using testing::kW;
using testing::make_fixture;
using testing::write_path_recording;

/// What ffprobe reports, read through libavformat.
struct Probe {
  int width = 0, height = 0;
  std::int64_t video_frames = 0;
  bool equirect = false, mono = false;
  std::vector<std::string> audio_codecs;
  std::vector<std::string> audio_packets;  //!< each packet's bytes
  std::vector<double> video_times;         //!< presentation times, sorted, seconds
};

Probe probe(const fs::path& p) {
  Probe r;
  std::string error;
  io::av::InputPtr in = io::av::open_input(p.string(), error);
  EXPECT_TRUE(in) << p << ": " << error;
  if (!in) return r;
  int video = -1;
  for (unsigned i = 0; i < in->nb_streams; ++i) {
    const AVStream* s = in->streams[i];
    if (s->codecpar->codec_type == AVMEDIA_TYPE_VIDEO && video < 0) {
      video = static_cast<int>(i);
      r.width = s->codecpar->width;
      r.height = s->codecpar->height;
      size_t size = 0;
      const auto* sph = reinterpret_cast<const AVSphericalMapping*>(
          av_stream_get_side_data(s, AV_PKT_DATA_SPHERICAL, &size));
      r.equirect = sph && sph->projection == AV_SPHERICAL_EQUIRECTANGULAR;
      const auto* st3d = reinterpret_cast<const AVStereo3D*>(
          av_stream_get_side_data(s, AV_PKT_DATA_STEREO3D, &size));
      r.mono = st3d && st3d->type == AV_STEREO3D_2D;
    } else if (s->codecpar->codec_type == AVMEDIA_TYPE_AUDIO) {
      r.audio_codecs.push_back(avcodec_get_name(s->codecpar->codec_id));
    }
  }
  io::av::PacketPtr pkt = io::av::make_packet();
  while (av_read_frame(in.get(), pkt.get()) >= 0) {
    const AVStream* s = in->streams[pkt->stream_index];
    if (pkt->stream_index == video) {
      ++r.video_frames;
      r.video_times.push_back(static_cast<double>(pkt->pts) * av_q2d(s->time_base));
    } else if (s->codecpar->codec_type == AVMEDIA_TYPE_AUDIO) {
      r.audio_packets.emplace_back(reinterpret_cast<const char*>(pkt->data),
                                   static_cast<std::size_t>(pkt->size));
    }
    av_packet_unref(pkt.get());
  }
  std::sort(r.video_times.begin(), r.video_times.end());
  return r;
}

int max_diff(const cv::Mat& a, const cv::Mat& b) {
  return test_media::max_abs_diff(a, b);
}

TEST(Export, BakedVideoHasSphericalMetadataAudioFramesAndPerPixelEffects) {
  const Fixture f = make_fixture();
  const fs::path out = f.dir / "baked.mp4";
  const auto e = run_vdfx("export " + f.clip.string() + " --sidecar " + f.sidecar.string() +
                          " --baked " + out.string() + " --crf 0 --chroma 444 --param-step 1");
  ASSERT_EQ(e.exit_code, 0) << e.output;
  EXPECT_NE(e.output.find("flare and grain"), std::string::npos) << e.output;
  EXPECT_NE(e.output.find("export: 12/12 frames (100%)"), std::string::npos)
      << e.output;  // not a terminal: lines

  const Probe src = probe(f.clip), got = probe(out);
  EXPECT_EQ(got.width, kW);
  EXPECT_EQ(got.height, kH);
  EXPECT_EQ(got.video_frames, kFrames);
  EXPECT_TRUE(got.equirect);
  EXPECT_TRUE(got.mono);
  ASSERT_EQ(got.audio_codecs, std::vector<std::string>{"aac"});
  EXPECT_EQ(got.audio_packets, src.audio_packets);  // copied untouched, every packet
  ASSERT_EQ(got.video_times.size(), src.video_times.size());
  for (std::size_t k = 0; k < got.video_times.size(); ++k)
    EXPECT_NEAR(got.video_times[k], src.video_times[k], 1e-6) << k;  // the source's timestamps

  // What a 360 player's tools see: ffprobe's own words.
  const std::string ffprobe = command_output("ffprobe -hide_banner '" + out.string() + "' 2>&1");
  EXPECT_NE(ffprobe.find("spherical: equirectangular"), std::string::npos) << ffprobe;

  // Pixels: each exported frame is the CPU per-pixel render of the same source frame (lossless
  // settings: only the 8-bit Y'CbCr rounding is left).
  const io::Sidecar sc = io::read_sidecar(f.sidecar);
  const effects::StackInterpolator stack(sc.effects, sc.interpolation, sc.video.fps);
  io::DecoderOptions fo;
  fo.format = io::PixelFormat::RgbF32;
  auto source = io::open_frame_decoder(f.clip, fo);
  auto exported = io::open_frame_decoder(out);
  BakedOptions bo;
  bo.param_step = 1;
  for (const std::int64_t k : {0, 5, 11}) {
    source->seek(k);
    cv::Mat rgb;
    ASSERT_EQ(source->read(rgb), io::DecodeStatus::Ok);
    const cv::Mat want = effects::to_rgb8(render_baked(rgb, stack, k, bo));
    const cv::Mat got_px = decoded_rgb8(*exported, k);
    EXPECT_LE(max_diff(got_px, want), 2) << "frame " << k;
    // The effects follow each pixel's own direction: +1 stop at azimuth 0 (the centre column),
    // -1 stop behind (the edge columns), measured on the source's green (every frame: keyframes
    // that share one frame hold over the clip).
    cv::Mat src8;
    rgb.convertTo(src8, CV_8UC3, 255.0);
    const double front = got_px.at<cv::Vec3b>(kH / 2, kW / 2)[1] /
                         static_cast<double>(src8.at<cv::Vec3b>(kH / 2, kW / 2)[1]);
    const double back =
        got_px.at<cv::Vec3b>(kH / 2, 0)[1] / static_cast<double>(src8.at<cv::Vec3b>(kH / 2, 0)[1]);
    EXPECT_GT(front, 1.5) << k;
    EXPECT_LT(back, 0.75) << k;
  }
}

TEST(Export, PartialRangeWithH265StartsAtZeroAndCutsTheAudio) {
  const Fixture f = make_fixture();
  const fs::path out = f.dir / "part.mkv";
  const auto e =
      run_vdfx("export " + f.clip.string() + " --sidecar " + f.sidecar.string() + " --baked " +
               out.string() + " --codec h265 --frames 3-7 --preset ultrafast");
  ASSERT_EQ(e.exit_code, 0) << e.output;
  const Probe got = probe(out);
  EXPECT_EQ(got.video_frames, 5);
  EXPECT_TRUE(got.equirect);
  ASSERT_FALSE(got.video_times.empty());
  EXPECT_NEAR(got.video_times.front(), 0.0, 1e-3);
  EXPECT_EQ(got.audio_codecs, std::vector<std::string>{"aac"});
  // About 5 / 24 s of audio (whole AAC packets of 1024 samples at 48 kHz).
  EXPECT_NEAR(static_cast<double>(got.audio_packets.size()) * 1024.0 / 48000.0, 5.0 / 24.0, 0.05);
  // Frame 0 of the export is frame 3 of the source (smooth_frame moves 3 px per frame).
  auto exported = io::open_frame_decoder(out);
  EXPECT_EQ(exported->properties().codec, "hevc");
  const io::Sidecar sc = io::read_sidecar(f.sidecar);
  const effects::StackInterpolator stack(sc.effects, sc.interpolation, sc.video.fps);
  io::DecoderOptions fo;
  fo.format = io::PixelFormat::RgbF32;
  auto source = io::open_frame_decoder(f.clip, fo);
  cv::Mat rgb3, rgb4;
  source->seek(3);
  ASSERT_EQ(source->read(rgb3), io::DecodeStatus::Ok);
  ASSERT_EQ(source->read(rgb4), io::DecodeStatus::Ok);
  const cv::Mat got0 = decoded_rgb8(*exported, 0);
  auto mean_diff = [&](const cv::Mat& rgb, std::int64_t k) {
    cv::Mat d;
    cv::absdiff(got0, effects::to_rgb8(render_baked(rgb, stack, k)), d);
    const cv::Scalar m = cv::mean(d);
    return (m[0] + m[1] + m[2]) / 3.0;
  };
  EXPECT_LT(mean_diff(rgb3, 3), 3.0);  // lossy h265: a mean, not a maximum
  EXPECT_LT(mean_diff(rgb3, 3), mean_diff(rgb4, 4));
}

TEST(Export, ViewerPathDrawsTheFlareAndGrainAsVdfxRenderDoes) {
  const Fixture f = make_fixture(kW, kH, 30);
  const fs::path rec = write_path_recording(f.dir);
  // The fixture's effects plus a flare whose fixed light is where the path starts looking and a
  // headset grain (size 4: visible at this small size).
  std::string text = test_files::slurp(f.sidecar);
  const std::string layers = R"(,
    {"type": "flare", "style": "directional", "light": {"azimuth_deg": 30.0, "altitude_deg": 10.0},
     "keyframes": [{"azimuth_deg": 30.0, "altitude_deg": 10.0, "frame": 0, "params": {"intensity": 3.0}}]},
    {"type": "grain", "style": "headset", "seed": 3,
     "keyframes": [{"azimuth_deg": 30.0, "altitude_deg": 10.0, "frame": 0, "params": {"intensity": 1.0, "size": 4.0}}]}
  ]})";
  text.replace(text.rfind("\n  ]}"), std::string::npos, layers);
  const fs::path sidecar = f.dir / "layers.vdfx.json";
  write_text(sidecar, text);
  const fs::path out = f.dir / "layers.mp4", plain = f.dir / "plain.mp4";
  const std::string common =
      " --path " + rec.string() + " --fov 80 --size 96x64 --crf 0 --chroma 444 --frames 0-2";
  ASSERT_EQ(run_vdfx("export " + f.clip.string() + " --sidecar " + sidecar.string() + " --out " +
                     out.string() + common)
                .exit_code,
            0);
  ASSERT_EQ(run_vdfx("export " + f.clip.string() + " --sidecar " + f.sidecar.string() + " --out " +
                     plain.string() + common)
                .exit_code,
            0);
  const fs::path png = f.dir / "layers0.png";
  const auto r = run_vdfx("render " + f.clip.string() + " --sidecar " + sidecar.string() +
                          " --view 30,10,0 --frame 0 --fov 80 --size 96x64 --out " + png.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  cv::Mat want = cv::imread(png.string()), want_rgb;
  cv::cvtColor(want, want_rgb, cv::COLOR_BGR2RGB);
  auto with = io::open_frame_decoder(out), without = io::open_frame_decoder(plain);
  const cv::Mat got = decoded_rgb8(*with, 0), bare = decoded_rgb8(*without, 0);
  EXPECT_LE(max_diff(got, want_rgb), 2) << "the path export draws what vdfx render draws";
  EXPECT_GT(max_diff(got, bare), 40) << "the flare and the grain are in the export";
}

TEST(Export, ViewerPathFirstAndLastFramesEqualVdfxRender) {
  const Fixture f = make_fixture(kW, kH, 30);
  const fs::path rec = write_path_recording(f.dir);
  const fs::path out = f.dir / "path.mp4";
  const auto e = run_vdfx("export " + f.clip.string() + " --sidecar " + f.sidecar.string() +
                          " --path " + rec.string() + " --out " + out.string() +
                          " --fov 80 --size 96x64 --crf 0 --chroma 444");
  ASSERT_EQ(e.exit_code, 0) << e.output;
  const Probe got = probe(out);
  EXPECT_EQ(got.width, 96);
  EXPECT_EQ(got.height, 64);
  EXPECT_EQ(got.video_frames,
            24);  // the recording lasts 1 s: frames 0..24, of which the video has 0..29
  EXPECT_FALSE(got.equirect);  // a flat view, no 360 metadata
  EXPECT_EQ(got.audio_codecs, std::vector<std::string>{"aac"});
  auto exported = io::open_frame_decoder(out);
  const struct {
    std::int64_t frame;
    const char* view;
  } ends[] = {{0, "30,10,0"}, {23, "-60,-5,0"}};
  for (const auto& end : ends) {
    const fs::path png = f.dir / ("render" + std::to_string(end.frame) + ".png");
    const auto r = run_vdfx("render " + f.clip.string() + " --sidecar " + f.sidecar.string() +
                            " --view " + end.view + " --frame " + std::to_string(end.frame) +
                            " --fov 80 --size 96x64 --out " + png.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    cv::Mat want = cv::imread(png.string()), want_rgb;
    cv::cvtColor(want, want_rgb, cv::COLOR_BGR2RGB);
    EXPECT_LE(max_diff(decoded_rgb8(*exported, end.frame), want_rgb), 2) << "frame " << end.frame;
  }
}

TEST(Export, HeadPathIsResampledAtFrameTimes) {
  const fs::path dir = test_dir();
  const io::Recording rec = io::read_recording(write_path_recording(dir));
  const std::vector<HeadSample> path = head_path(rec);
  EXPECT_EQ(path.front().t_ns, 0);  // relative to the first sample
  const io::Rational fps{24, 1};
  const PathView v0 = path_view(path, 0, fps);
  EXPECT_NEAR(v0.look.azimuth_deg, 30.0, 1e-6);
  EXPECT_NEAR(v0.look.altitude_deg, 10.0, 1e-6);
  EXPECT_NEAR(v0.roll_deg, 0.0, 1e-6);
  // Mid-turn, frame 10 (0.4167 s): slerp between the samples around that time lands on the
  // path; with yaw then pitch the path is close to the linear one (within a few tenths).
  const PathView v10 = path_view(path, 10, fps);
  const double f = (10.0 / 24.0 - 0.25) / 0.35;
  EXPECT_NEAR(v10.look.azimuth_deg, 30.0 - 90.0 * f, 0.5);
  EXPECT_NEAR(v10.look.altitude_deg, 10.0 - 15.0 * f, 0.5);
  const PathView v_end = path_view(path, 100, fps);  // after the recording: the last pose holds
  EXPECT_NEAR(v_end.look.azimuth_deg, -60.0, 1e-6);
  EXPECT_EQ(path_last_frame(path, fps), 23);  // the last sample is at 0.9999 s
}

/// Runs `vdfx export ...` as a child; returns its pid.
pid_t spawn_vdfx(const std::vector<std::string>& args, const fs::path& log) {
  const pid_t pid = fork();
  if (pid == 0) {
    FILE* f = std::freopen(log.c_str(), "w", stderr);
    (void)f;
    std::vector<char*> argv;
    std::string bin = VDFX_BINARY;
    argv.push_back(bin.data());
    std::vector<std::string> copy = args;
    for (auto& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(bin.c_str(), argv.data());
    _exit(127);
  }
  return pid;
}

/// Waits until a temporary export file appears in `dir` (true) or the child ends (false).
bool wait_for_temp(const fs::path& dir, pid_t child) {
  for (int i = 0; i < 6000; ++i) {
    // The child's own temporary file (its PID in the name), with data in it.
    const std::string own = ".tmp-" + std::to_string(child) + ".";
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().filename().string().find(own) != std::string::npos &&
          fs::file_size(e.path()) > 0)
        return true;
    int status = 0;
    if (waitpid(child, &status, WNOHANG) == child) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

TEST(Export, KilledOrInterruptedExportLeavesThePreviousFileByteIdenticalAndNoStaleTemp) {
  const Fixture f = make_fixture(512, 256, 48);  // long enough to be caught mid-way
  const fs::path out = f.dir / "baked.mp4";
  const std::string previous = "the previous export, byte for byte";
  for (const int sig : {SIGKILL, SIGINT}) {
    write_text(out, previous);
    const pid_t child =
        spawn_vdfx({"export", f.clip.string(), "--sidecar", f.sidecar.string(), "--baked",
                    out.string(), "--threads", "1", "--preset", "veryslow", "--param-step", "1"},
                   f.dir / "child.log");
    ASSERT_TRUE(wait_for_temp(f.dir, child)) << test_files::slurp(f.dir / "child.log");
    kill(child, sig);
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFSIGNALED(status))
        << "signal " << sig << ": " << test_files::slurp(f.dir / "child.log");
    if (WIFSIGNALED(status)) {
      EXPECT_EQ(WTERMSIG(status), sig);
    }
    EXPECT_EQ(test_files::slurp(out), previous) << "signal " << sig;
    int temps = 0;
    for (const auto& e : fs::directory_iterator(f.dir))
      temps += e.path().filename().string().find(".tmp-") != std::string::npos;
    if (sig == SIGKILL) {
      // Killed: it could not remove its temporary file; the next export to OUT removes it once
      // the killed process is gone (the SIGINT round below starts by doing so).
      EXPECT_EQ(temps, 1);
    } else {
      // Interrupted (not killed): it removed its own temporary file, and the killed one's.
      EXPECT_EQ(temps, 0);
      EXPECT_NE(test_files::slurp(f.dir / "child.log")
                    .find("vdfx export: stopped by SIGINT: the temporary file removed; "),
                std::string::npos);
    }
  }
}

TEST(Export, BadUsageAndBadInputGiveTheContractsExitCodes) {
  const Fixture f = make_fixture(kW, kH, 4);
  const std::string base = "export " + f.clip.string() + " --sidecar " + f.sidecar.string();
  const struct {
    std::string args;
    int code;
    const char* says;
  } cases[] = {
      {base, 2, "either --baked"},
      {base + " --baked a.mp4 --path r.vdrec.jsonl --out b.mp4", 2, "either --baked"},
      {base + " --path r.vdrec.jsonl", 2, "--out"},
      {base + " --baked out.avi", 2, ".mp4, .mov or .mkv"},
      {base + " --baked " + f.clip.string(), 1, "it is the VIDEO input"},
      {base + " --baked " + (f.dir / "link.mp4").string(), 1,
       "the same file as the --sidecar input"},
      {base + " --baked o.mp4 --frames 3", 2, "A-B"},
      {base + " --baked o.mp4 --frames 5-2", 2, "A-B"},
      {base + " --baked o.mp4 --fov 70", 2, "--path"},
      {base + " --baked o.mp4 --codec vp9", 2, "--codec"},
      {base + " --baked " + (f.dir / "o.mp4").string() + " --frames 2-9", 1,
       "past the video's last frame"},
      {"export " + (f.dir / "missing.mp4").string() + " --sidecar " + f.sidecar.string() +
           " --baked o.mp4",
       1, "no such file"},
      {"export " + f.clip.string() + " --sidecar " + (f.dir / "missing.vdfx.json").string() +
           " --baked o.mp4",
       1, "missing.vdfx.json"},
      {base + " --path " + (f.dir / "missing.vdrec.jsonl").string() + " --out o.mp4", 1,
       "missing.vdrec.jsonl"},
      {base + " --path " + (f.dir / "r.vdrec.jsonl").string() + " --out o.mp4 --size 95x64", 1,
       "odd"},
      {base + " --baked " + (f.dir / "nofolder" / "o.mp4").string(), 1, "does not exist"},
  };
  write_path_recording(f.dir);
  fs::rename(f.dir / "path.vdrec.jsonl", f.dir / "r.vdrec.jsonl");
  fs::create_symlink(f.sidecar, f.dir / "link.mp4");  // an output name that leads to an input
  for (const auto& c : cases) {
    const auto r = run_vdfx(c.args);
    EXPECT_EQ(r.exit_code, c.code) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.says), std::string::npos) << c.args << "\n" << r.output;
  }
  EXPECT_FALSE(fs::exists(f.dir / "o.mp4"));  // nothing written by a refused export
}

}  // namespace
}  // namespace vdfx::app
