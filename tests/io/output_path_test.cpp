/// @file
/// @brief Outputs never destroy what the user did not name: links are followed (named) or refused
/// (generated), devices/pipes/folders refused, an output that is an input refused by inode.
#include "io/output_path.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "io/atomic_file.h"
#include "io/input_error.h"
#include "io_test_util.h"

namespace vdfx::io {
namespace {

namespace fs = std::filesystem;
using test_files::slurp;
using testing::error_of;
using testing::temp_dir;

TEST(OutputPath, FollowsChainsOfLinksToTheFileTheyName) {
  const auto dir = temp_dir("output_links");
  fs::create_directories(dir / "sub");
  std::ofstream(dir / "sub" / "target.txt") << "t";
  // A relative link is relative to its own folder: sub/a -> target.txt is sub/target.txt.
  fs::create_symlink("target.txt", dir / "sub" / "a");
  fs::create_symlink("sub/a", dir / "b");
  EXPECT_EQ(resolve_output_path(dir / "b"), dir / "sub" / "target.txt");
  // A dangling link names the file to create.
  fs::create_symlink("new.txt", dir / "dangling");
  EXPECT_EQ(resolve_output_path(dir / "dangling"), dir / "new.txt");
  EXPECT_EQ(resolve_output_path(dir / "plain.txt"), dir / "plain.txt");
}

TEST(OutputPath, RefusesWhatIsNotARegularFile) {
  const auto dir = temp_dir("output_special");
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
  fs::create_directories(dir / "folder");
  fs::create_symlink("/dev/null", dir / "to_null");
  fs::create_symlink("loop2", dir / "loop1");
  fs::create_symlink("loop1", dir / "loop2");
  const struct {
    fs::path path;
    const char* expected;
  } rows[] = {
      {dir / "fifo", "named pipe"},          {dir / "folder", "a folder"},
      {"/dev/null", "character device"},  // only stat'ed: nothing is ever written here
      {dir / "to_null", "character device"}, {dir / "loop1", "too many levels of symbolic links"},
  };
  for (const auto& row : rows) {
    const std::string msg = error_of([&] { resolve_output_path(row.path); });
    EXPECT_NE(msg.find(row.path.string()), std::string::npos) << msg;
    EXPECT_NE(msg.find(row.expected), std::string::npos) << msg;
  }
  EXPECT_TRUE(fs::is_fifo(dir / "fifo"));
}

TEST(OutputPath, GeneratedNamesRefuseLinks) {
  const auto dir = temp_dir("output_generated");
  std::ofstream(dir / "precious.txt") << "keep";
  fs::create_symlink("precious.txt", dir / "replay_000.png");
  const std::string msg =
      error_of([&] { write_file_atomic(dir / "replay_000.png", "png", OutputName::Generated); });
  EXPECT_NE(msg.find("symbolic link"), std::string::npos) << msg;
  EXPECT_EQ(slurp(dir / "precious.txt"), "keep");
  EXPECT_TRUE(fs::is_symlink(dir / "replay_000.png"));
  // A regular file of a generated name is replaced as before.
  write_file_atomic(dir / "replay_001.png", "old", OutputName::Generated);
  write_file_atomic(dir / "replay_001.png", "new", OutputName::Generated);
  EXPECT_EQ(slurp(dir / "replay_001.png"), "new");
}

TEST(OutputPath, WritingANamedLinkReplacesItsTargetAndKeepsTheLink) {
  const auto dir = temp_dir("output_write_link");
  fs::create_directories(dir / "real");
  std::ofstream(dir / "real" / "s.vdfx.json") << "old";
  fs::permissions(dir / "real" / "s.vdfx.json", fs::perms::owner_read | fs::perms::owner_write);
  fs::create_symlink("real/s.vdfx.json", dir / "link.vdfx.json");
  write_file_atomic(dir / "link.vdfx.json", "new");
  EXPECT_TRUE(fs::is_symlink(dir / "link.vdfx.json"));
  EXPECT_EQ(slurp(dir / "real" / "s.vdfx.json"), "new");
  EXPECT_EQ(fs::status(dir / "real" / "s.vdfx.json").permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write);
  // The temporary file went to the target's folder (rename is atomic only within one).
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir / "real")) ++n;
  EXPECT_EQ(n, 1u);
}

TEST(OutputPath, AnOutputThatIsAnInputIsRefusedWhateverItsName) {
  const auto dir = temp_dir("output_is_input");
  std::ofstream(dir / "in.png") << "pixels";
  std::ofstream(dir / "other.png") << "other";
  fs::create_hard_link(dir / "in.png", dir / "hard.png");
  fs::create_symlink("in.png", dir / "soft.png");
  const std::vector<NamedInput> inputs = {{"INPUT", dir / "in.png"}, {"--sidecar", dir / "none"}};
  for (const fs::path& out :
       {dir / "in.png", dir / "." / "in.png", dir / "hard.png", dir / "soft.png"}) {
    const std::string msg = error_of([&] { check_output_is_not_input("--out", out, inputs); });
    EXPECT_NE(msg.find("refusing to write --out " + out.string()), std::string::npos) << msg;
    EXPECT_NE(msg.find("INPUT input"), std::string::npos) << msg;
  }
  // Another file, or one not there yet, is fine.
  EXPECT_NO_THROW(check_output_is_not_input("--out", dir / "other.png", inputs));
  EXPECT_NO_THROW(check_output_is_not_input("--out", dir / "new.png", inputs));
  EXPECT_EQ(slurp(dir / "in.png"), "pixels");
}

TEST(AtomicFile, RemovesTemporaryFilesOfKilledWritersOnly) {
  const auto dir = temp_dir("atomic_stale");
  // A PID that surely no longer exists: a child that has exited and been reaped.
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  ::waitpid(child, nullptr, 0);
  const std::string dead = std::to_string(child), alive = std::to_string(::getppid());
  const fs::path stale = dir / (".s.vdfx.json.tmp-" + dead + "-3");
  const fs::path live = dir / (".s.vdfx.json.tmp-" + alive + "-0");
  const fs::path other_name = dir / (".t.vdfx.json.tmp-" + dead + "-0");
  const fs::path not_ours = dir / (".s.vdfx.json.tmp-" + dead + "-x");
  for (const fs::path& p : {stale, live, other_name, not_ours}) std::ofstream(p) << "partial";
  write_file_atomic(dir / "s.vdfx.json", "saved");
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(live));        // its writer may still rename it
  EXPECT_TRUE(fs::exists(other_name));  // another file's temporary: not ours to judge
  EXPECT_TRUE(fs::exists(not_ours));    // not the exact pattern vdfx writes
  EXPECT_EQ(slurp(dir / "s.vdfx.json"), "saved");
}

}  // namespace
}  // namespace vdfx::io
