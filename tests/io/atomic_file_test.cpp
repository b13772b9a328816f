/// @file
/// @brief write_file_atomic: replaces whole files, and a failed write leaves the old file.
#include "io/atomic_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/input_error.h"
#include "io_test_util.h"

namespace vdfx::io {
namespace {

namespace fs = std::filesystem;

using testing::temp_dir;

using test_files::slurp;

std::size_t entries(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicFile, CreatesAndReplaces) {
  const auto dir = temp_dir("atomic_replace");
  const auto p = dir / "f.txt";
  write_file_atomic(p, "first");
  EXPECT_EQ(slurp(p), "first");
  const std::string big(1 << 20, 'x');
  write_file_atomic(p, big);
  EXPECT_EQ(slurp(p), big);
  write_file_atomic(p, "");
  EXPECT_EQ(slurp(p), "");
  EXPECT_EQ(entries(dir), 1u);  // no temporary file left
}

TEST(AtomicFile, KeepsModeOfExistingFile) {
  const auto dir = temp_dir("atomic_mode");
  const auto p = dir / "f.txt";
  write_file_atomic(p, "a");
  fs::permissions(p, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  write_file_atomic(p, "b");
  EXPECT_EQ(fs::status(p).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

TEST(AtomicFile, ParentIsAFileFailsNamingTheFile) {
  const auto dir = temp_dir("atomic_parent_file");
  write_file_atomic(dir / "plain", "x");
  const auto p = dir / "plain" / "f.txt";
  try {
    write_file_atomic(p, "y");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos) << e.what();
  }
  EXPECT_EQ(slurp(dir / "plain"), "x");
  EXPECT_EQ(entries(dir), 1u);
}

TEST(AtomicFile, TargetIsAFolderFails) {
  const auto dir = temp_dir("atomic_folder");
  fs::create_directories(dir / "sub");
  EXPECT_THROW(write_file_atomic(dir / "sub", "y"), InputError);
  EXPECT_TRUE(fs::is_directory(dir / "sub"));
  EXPECT_EQ(entries(dir), 1u);
}

TEST(AtomicFile, UnwritableFolderLeavesOldFileAndNoTemp) {
  if (::geteuid() == 0) {
    // root ignores folder permissions; use a failure root cannot bypass instead: a target name
    // too long for the file system (the temporary name is longer still).
    const auto dir = temp_dir("atomic_readonly");
    const auto p = dir / "old.txt";
    write_file_atomic(p, "old");
    EXPECT_THROW(write_file_atomic(dir / std::string(250, 'n'), "new"), InputError);
    EXPECT_EQ(slurp(p), "old");
    EXPECT_EQ(entries(dir), 1u);
    return;
  }
  const auto dir = temp_dir("atomic_readonly");
  const auto p = dir / "old.txt";
  write_file_atomic(p, "old");
  fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec);
  try {
    write_file_atomic(p, "new");
    fs::permissions(dir, fs::perms::owner_all);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    fs::permissions(dir, fs::perms::owner_all);
    EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos) << e.what();
  }
  EXPECT_EQ(slurp(p), "old");
  EXPECT_EQ(entries(dir), 1u);
}

}  // namespace
}  // namespace vdfx::io
