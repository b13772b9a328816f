/// @file
/// @brief Stereo layout and coverage: read from the stream's tags (MP4 st3d/sv3d written by vdfx's
/// own encoder, Matroska StereoMode written by the ffmpeg command line), resolved against the
/// command line and the sidecar, and recorded in the sidecar's `video` section.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "io/frame_decoder.h"
#include "io/input_error.h"
#include "io/sidecar.h"
#include "io/sidecar_validate.h"
#include "io/video_layout.h"
#include "io_test_util.h"
#include "tests/media_clips.h"

namespace vdfx::io {
namespace {

namespace fs = std::filesystem;
using effects::StereoLayout;
using effects::StereoMode;
using test_media::ClipSpec;

fs::path tagged_clip(const fs::path& dir, const std::string& name, StereoLayout stereo,
                     int width = 64, int height = 64) {
  ClipSpec c;
  c.width = width;
  c.height = height;
  c.frames = 2;
  c.spherical = true;
  c.stereo = stereo;
  return test_media::write_clip(dir / name, c);
}

fs::path untagged_clip(const fs::path& dir, const std::string& name, int width, int height) {
  ClipSpec c;
  c.width = width;
  c.height = height;
  c.frames = 2;
  return test_media::write_clip(dir / name, c);
}

StereoTags tags_of(const fs::path& p) {
  return open_frame_decoder(p)->properties().stereo_tags;
}

TEST(StereoTags, Mp4WrittenByVdfxReadsBack) {
  const fs::path dir = testing::temp_dir("stereo_tags_mp4");
  const struct {
    const char* name;
    StereoLayout layout;
  } rows[] = {
      {"mono.mp4", {StereoMode::Mono, 360}},       {"tb.mp4", {StereoMode::TopBottom, 360}},
      {"lr.mp4", {StereoMode::LeftRight, 360}},    {"vr180.mp4", {StereoMode::LeftRight, 180}},
      {"tb180.mp4", {StereoMode::TopBottom, 180}},
  };
  for (const auto& row : rows) {
    SCOPED_TRACE(row.name);
    const StereoTags t = tags_of(tagged_clip(dir, row.name, row.layout));
    EXPECT_EQ(t.mode, row.layout.mode);
    EXPECT_EQ(t.coverage_deg, row.layout.coverage_deg);
    EXPECT_EQ(t.unsupported, "");
  }
}

TEST(StereoTags, UntaggedSaysNothing) {
  const fs::path dir = testing::temp_dir("stereo_tags_none");
  const StereoTags t = tags_of(untagged_clip(dir, "plain.mp4", 64, 32));
  EXPECT_FALSE(t.mode);
  EXPECT_FALSE(t.coverage_deg);
}

TEST(StereoTags, MatroskaStereoModeFromFfmpeg) {
  const fs::path dir = testing::temp_dir("stereo_tags_mkv");
  const fs::path plain = untagged_clip(dir, "plain.mkv", 64, 64);
  const struct {
    const char* tag;
    StereoMode mode;
  } rows[] = {{"top_bottom", StereoMode::TopBottom},
              {"left_right", StereoMode::LeftRight},
              {"right_left", StereoMode::RightLeft}};
  for (const auto& row : rows) {
    SCOPED_TRACE(row.tag);
    const fs::path out = dir / (std::string(row.tag) + ".mkv");
    const std::string cmd = "ffmpeg -v error -y -i " + plain.string() +
                            " -c copy -metadata:s:v stereo_mode=" + row.tag + " " + out.string();
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    EXPECT_EQ(tags_of(out).mode, row.mode);
  }
}

VideoProperties props(int w, int h, StereoTags tags = {}) {
  VideoProperties p;
  p.path = "clip.mp4";
  p.width = w;
  p.height = h;
  p.stereo_tags = tags;
  return p;
}

TEST(ResolveVideoLayout, CommandLineOverTagsOverSidecar) {
  VideoInfo side;
  side.layout = StereoMode::LeftRight;
  side.coverage_deg = 180;
  // Untagged: the sidecar's record.
  EXPECT_EQ(resolve_video_layout(props(64, 64), {}, &side, "s.vdfx.json"),
            (StereoLayout{StereoMode::LeftRight, 180}));
  // Nothing anywhere: mono 360.
  EXPECT_EQ(resolve_video_layout(props(64, 32), {}, nullptr, ""), StereoLayout{});
  // Tags over nothing recorded.
  const StereoTags tb{StereoMode::TopBottom, 360, ""};
  EXPECT_EQ(resolve_video_layout(props(64, 64, tb), {}, nullptr, ""),
            (StereoLayout{StereoMode::TopBottom, 360}));
  // The command line over tags and sidecar (no contradiction reported for what it overrides).
  LayoutOverride cli{StereoMode::RightLeft, 360};
  EXPECT_EQ(resolve_video_layout(props(64, 64, tb), cli, &side, "s.vdfx.json"),
            (StereoLayout{StereoMode::RightLeft, 360}));
}

TEST(ResolveVideoLayout, AStereoSidecarOverAMonoVideoIsAnInputError) {
  VideoInfo side;
  side.layout = StereoMode::TopBottom;
  const StereoTags mono{StereoMode::Mono, 360, ""};
  try {
    resolve_video_layout(props(64, 64, mono), {}, &side, "s.vdfx.json");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("s.vdfx.json: /video/layout: the sidecar says top-bottom but clip.mp4 is "
                     "tagged mono (give --layout"),
              std::string::npos)
        << m;
  }
  VideoInfo vr;
  vr.coverage_deg = 180;
  EXPECT_THROW(resolve_video_layout(props(64, 64, mono), {}, &vr, "s.vdfx.json"), InputError);
}

TEST(ResolveVideoLayout, ALayoutThatDoesNotDivideTheFrame) {
  try {
    resolve_video_layout(props(64, 33), {StereoMode::TopBottom, std::nullopt}, nullptr, "");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "clip.mp4: --layout: top-bottom needs an even frame height; the frame is 64x33");
  }
}

TEST(ResolveVideoLayout, HintForAnUntaggedSquareFrame) {
  std::string hint;
  EXPECT_EQ(resolve_video_layout(props(64, 64), {}, nullptr, "", &hint), StereoLayout{});
  EXPECT_NE(hint.find("--layout"), std::string::npos) << hint;
  hint.clear();
  resolve_video_layout(props(64, 32), {}, nullptr, "", &hint);
  EXPECT_EQ(hint, "");
  resolve_video_layout(props(64, 64), {StereoMode::Mono, std::nullopt}, nullptr, "", &hint);
  EXPECT_EQ(hint, "");  // said mono on purpose
}

std::string sidecar_text(const std::string& video_extra) {
  return R"({"format": "vdfx.sidecar", "version": 1,
  "video": {"path": "c.mp4", "fps": 30.0, "frames": 10, "width": 64, "height": 64)" +
         video_extra + R"(},
  "interpolation": {"exponent": 1.0, "time_scale": 1.0}, "effects": []})";
}

TEST(SidecarStereo, ReadWrittenAndOldFilesAreMono360) {
  const SidecarReport old = validate_sidecar_text(sidecar_text(""), "s.vdfx.json");
  ASSERT_TRUE(old.ok()) << old.to_string();
  EXPECT_FALSE(old.sidecar->video.layout);
  EXPECT_EQ(old.sidecar->video.stereo(), StereoLayout{});
  EXPECT_EQ(format_sidecar(*old.sidecar).find("layout"), std::string::npos);

  const SidecarReport r = validate_sidecar_text(
      sidecar_text(R"(, "layout": "left-right", "coverage": 180)"), "s.vdfx.json");
  ASSERT_TRUE(r.ok()) << r.to_string();
  EXPECT_EQ(r.sidecar->video.stereo(), (StereoLayout{StereoMode::LeftRight, 180}));
  const std::string text = format_sidecar(*r.sidecar);
  EXPECT_NE(text.find(R"("layout": "left-right",)"), std::string::npos) << text;
  EXPECT_NE(text.find(R"("coverage": 180)"), std::string::npos) << text;
  const SidecarReport again = validate_sidecar_text(text, "s.vdfx.json");
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(*again.sidecar, *r.sidecar);
}

TEST(SidecarStereo, BadValuesNameTheField) {
  const struct {
    std::string extra, want;
  } rows[] = {
      {R"(, "layout": "sbs")", "s.vdfx.json: /video/layout: unknown layout \"sbs\""},
      {R"(, "layout": 1)", "s.vdfx.json: /video/layout: expected a string"},
      {R"(, "coverage": 0)", "s.vdfx.json: /video/coverage: coverage 0 covers nothing"},
      {R"(, "coverage": 270)", "s.vdfx.json: /video/coverage: coverage 270 is not supported"},
      {R"(, "coverage": 180.5)", "s.vdfx.json: /video/coverage:"},
  };
  for (const auto& row : rows) {
    SCOPED_TRACE(row.extra);
    const SidecarReport r = validate_sidecar_text(sidecar_text(row.extra), "s.vdfx.json");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.to_string().find(row.want), std::string::npos) << r.to_string();
  }
  std::string odd = sidecar_text(R"(, "layout": "top-bottom")");
  odd.replace(odd.find("\"height\": 64"), 12, "\"height\": 63");
  const SidecarReport r = validate_sidecar_text(odd, "s.vdfx.json");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.to_string().find("s.vdfx.json: /video/layout: top-bottom needs an even frame height"),
            std::string::npos)
      << r.to_string();
}

}  // namespace
}  // namespace vdfx::io
