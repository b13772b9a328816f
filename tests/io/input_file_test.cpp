/// @file
/// @brief Issue 11, class 2 (hangs and unbounded reads): every reader takes regular files only
/// (a pipe, device or folder is refused at once, never waited on) and stops at its size limit.
#include "io/input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/frame_decoder.h"
#include "io/image_source.h"
#include "io/input_error.h"
#include "io/recording.h"
#include "io/sidecar.h"
#include "io/sidecar_validate.h"
#include "io_test_util.h"

namespace vdfx::io {
namespace {

namespace fs = std::filesystem;
using testing::error_of;
using testing::temp_dir;

/// A file of `bytes` bytes that takes no disk space (a hole).
fs::path sparse_file(const fs::path& p, std::uintmax_t bytes) {
  std::ofstream(p) << "{";
  fs::resize_file(p, bytes);
  return p;
}

TEST(InputFile, RefusesPipesDevicesAndFoldersWithoutBlocking) {
  const auto dir = temp_dir("input_special");
  ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);  // no writer: opening it would block
  const struct {
    fs::path path;
    const char* says;
  } rows[] = {
      {dir / "pipe", "is a named pipe (FIFO), not a regular file"},
      {"/dev/zero", "is a character device, not a regular file"},
      {dir, "is a folder, not a sidecar"},
      {dir / "missing", "no such file"},
  };
  for (const auto& row : rows) {
    const std::string msg = error_of([&] { read_input_file(row.path, 100, "a sidecar"); });
    EXPECT_EQ(msg.find(row.path.string() + ": "), 0u) << msg;
    EXPECT_NE(msg.find(row.says), std::string::npos) << msg;
  }
}

TEST(InputFile, StopsAtTheSizeLimitNamingBothSizes) {
  const auto dir = temp_dir("input_size");
  std::ofstream(dir / "ok") << std::string(100, 'x');
  EXPECT_EQ(read_input_file(dir / "ok", 100, "a sidecar"), std::string(100, 'x'));
  std::ofstream(dir / "big") << std::string(101, 'x');
  const std::string msg = error_of([&] { read_input_file(dir / "big", 100, "a sidecar"); });
  EXPECT_NE(msg.find("is 101 bytes, more than the 100 bytes a sidecar may be"), std::string::npos)
      << msg;
  EXPECT_EQ(byte_size_text(64u << 20), "64 MiB");
  EXPECT_EQ(byte_size_text(1536), "1.5 KiB");
}

TEST(InputFile, EveryReaderTakesOnlyRegularFilesWithinItsLimit) {
  const auto dir = temp_dir("input_readers");
  ASSERT_EQ(::mkfifo((dir / "pipe.vdfx.json").c_str(), 0600), 0);
  ASSERT_EQ(::mkfifo((dir / "pipe.vdrec.jsonl").c_str(), 0600), 0);
  ASSERT_EQ(::mkfifo((dir / "pipe.png").c_str(), 0600), 0);
  ASSERT_EQ(::mkfifo((dir / "pipe.mp4").c_str(), 0600), 0);
  const SidecarReport s = validate_sidecar_file(dir / "pipe.vdfx.json");
  ASSERT_EQ(s.problems.size(), 1u);
  EXPECT_NE(s.problems[0].message.find("named pipe"), std::string::npos);
  EXPECT_NE(error_of([&] { read_recording(dir / "pipe.vdrec.jsonl"); }).find("named pipe"),
            std::string::npos);
  EXPECT_NE(error_of([&] { load_image(dir / "pipe.png"); }).find("named pipe"), std::string::npos);
  EXPECT_NE(error_of([&] { open_frame_decoder(dir / "pipe.mp4"); }).find("named pipe"),
            std::string::npos);

  // Size limits: files with holes, so the test writes no gigabytes.
  const SidecarReport big =
      validate_sidecar_file(sparse_file(dir / "big.vdfx.json", kMaxSidecarBytes + 1));
  ASSERT_EQ(big.problems.size(), 1u);
  EXPECT_NE(big.problems[0].message.find("more than the 256 MiB a sidecar may be"),
            std::string::npos)
      << big.problems[0].message;
  const std::string rec = error_of(
      [&] { read_recording(sparse_file(dir / "big.vdrec.jsonl", kMaxRecordingBytes + 1)); });
  EXPECT_NE(rec.find("more than the 1 GiB a recording may be"), std::string::npos) << rec;
}

TEST(InputFile, ARecordingLineStopsAtItsLimitWithItsNumber) {
  const std::string header =
      R"({"format":"vdfx.recording","version":1,"hmd":"sim","video":null,"note":""})";
  // Within the limit the reader goes on to the JSON (and fails there); one byte more stops it at
  // the line, terminated or not.
  for (const bool newline : {true, false}) {
    std::istringstream ok(header + "\n" + std::string(kMaxRecordingLineBytes, ' ') + "x" +
                          (newline ? "\n" : ""));
    const std::string over = error_of([&] { parse_recording(ok, "r.jsonl"); });
    EXPECT_NE(over.find("r.jsonl:2: line longer than 1 MiB"), std::string::npos)
        << over.substr(0, 200);
    std::istringstream at(header + "\n" + std::string(kMaxRecordingLineBytes - 1, ' ') + "x\n");
    const std::string within = error_of([&] { parse_recording(at, "r.jsonl"); });
    EXPECT_NE(within.find("r.jsonl:2: bad JSON"), std::string::npos) << within.substr(0, 200);
  }
}

}  // namespace
}  // namespace vdfx::io
