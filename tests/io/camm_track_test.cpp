/// @file
/// @brief The CAMM reader (io/camm_track.h) on MP4s made in the test with a CAMM track beside the
/// video: records, times and types come back as written; a file without the track has none; a
/// damaged record is an input error naming the file and the packet.
#include "io/camm_track.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "io/input_error.h"
#include "io_test_util.h"
#include "tests/camm_clip.h"
#include "tests/media_clips.h"

namespace vdfx::io {
namespace {

namespace fs = std::filesystem;
using test_media::CammPacket;

fs::path plain_clip(const fs::path& dir) {
  test_media::ClipSpec c;
  c.frames = 12;
  return test_media::write_clip(dir / "plain.mp4", c);
}

TEST(CammTrack, RecordsComeBackAsWrittenWithTheirTimes) {
  const fs::path dir = testing::temp_dir("camm_records");
  const fs::path out = dir / "camm.mp4";
  std::vector<CammPacket> packets;
  for (int i = 0; i < 10; ++i) {
    packets.push_back({i * 0.05, 0, {0.01f * i, -0.02f * i, 0.5f}});
    packets.push_back({i * 0.05 + 0.01, 2, {0.1f, 0.2f * i, -0.3f}});
    packets.push_back({i * 0.05 + 0.02, 3, {0.0f, -9.8f, 0.0f}});  // accelerometer: skipped
  }
  test_media::write_camm_clip(plain_clip(dir), out, packets);
  const std::optional<CammTrack> t = read_camm_track(out);
  ASSERT_TRUE(t);
  ASSERT_EQ(t->angle_axis.size(), 10u);
  ASSERT_EQ(t->gyro.size(), 10u);
  EXPECT_EQ(t->other_records, 10);
  for (int i = 0; i < 10; ++i) {
    EXPECT_NEAR(t->angle_axis[i].time_s, i * 0.05, 1e-4);
    EXPECT_FLOAT_EQ(static_cast<float>(t->angle_axis[i].value[0]), 0.01f * i);
    EXPECT_FLOAT_EQ(static_cast<float>(t->angle_axis[i].value[1]), -0.02f * i);
    EXPECT_FLOAT_EQ(static_cast<float>(t->angle_axis[i].value[2]), 0.5f);
    EXPECT_NEAR(t->gyro[i].time_s, i * 0.05 + 0.01, 1e-4);
    EXPECT_FLOAT_EQ(static_cast<float>(t->gyro[i].value[1]), 0.2f * i);
  }
}

TEST(CammTrack, AFileWithoutTheTrackHasNone) {
  const fs::path dir = testing::temp_dir("camm_none");
  EXPECT_FALSE(read_camm_track(plain_clip(dir)));
  EXPECT_FALSE(read_camm_track(dir / "missing.mp4"));
}

TEST(CammTrack, ADamagedRecordNamesTheFileAndThePacket) {
  const fs::path dir = testing::temp_dir("camm_damaged");
  const fs::path clip = plain_clip(dir);
  const fs::path cut = dir / "cut.mp4", nan = dir / "nan.mp4";
  test_media::write_camm_clip(clip, cut, {{0.0, 0, {0, 0, 0}}, {0.1, 0, {0, 0, 0}, 8}});
  test_media::write_camm_clip(clip, nan,
                              {{0.0, 2, {0, std::numeric_limits<float>::quiet_NaN(), 0}}});
  const std::string cut_error = testing::error_of([&] { read_camm_track(cut); });
  EXPECT_NE(cut_error.find(cut.string() + ": CAMM track, packet 1: a type 0 record is cut short"),
            std::string::npos)
      << cut_error;
  const std::string nan_error = testing::error_of([&] { read_camm_track(nan); });
  EXPECT_NE(nan_error.find(nan.string() + ": CAMM track, packet 0: a value is not a finite number"),
            std::string::npos)
      << nan_error;
}

}  // namespace
}  // namespace vdfx::io
