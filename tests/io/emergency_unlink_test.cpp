/// @file
/// @brief The table a second Ctrl-C empties (io/emergency_unlink.h): what is registered is
/// removed, a lock only while it still holds this process's bytes, and nothing once released.
#include "io/emergency_unlink.h"

#include <gtest/gtest.h>

#include <fstream>
#include <optional>
#include <vector>

#include "io/file_lock.h"
#include "io_test_util.h"

namespace vdfx::io {
namespace {

namespace fs = std::filesystem;
using testing::temp_dir;

void write(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

TEST(EmergencyUnlink, RemovesWhatIsRegisteredAndNothingOnceReleased) {
  const fs::path dir = temp_dir("emergency_basic");
  const fs::path kept = dir / "kept.tmp", gone = dir / "gone.tmp", released = dir / "released";
  for (const auto& p : {kept, gone, released}) write(p, "x");
  EmergencyUnlink a(gone);
  EmergencyUnlink b(released);
  ASSERT_TRUE(a.registered() && b.registered());
  b.reset();
  EXPECT_FALSE(b.registered());
  EXPECT_EQ(emergency_unlink_all(), 1);
  EXPECT_FALSE(fs::exists(gone));
  EXPECT_TRUE(fs::exists(released)) << "released: no longer in the table";
  EXPECT_TRUE(fs::exists(kept)) << "never registered";
}

TEST(EmergencyUnlink, AFileWithOtherContentIsLeft) {
  const fs::path dir = temp_dir("emergency_content");
  const fs::path mine = dir / "mine.lock", taken = dir / "taken.lock";
  write(mine, "pid 1\n");
  write(taken, "pid 1\n");
  EmergencyUnlink a(mine, "pid 1\n"), b(taken, "pid 1\n");
  write(taken, "pid 2\n");  // another process took it over meanwhile
  EXPECT_EQ(emergency_unlink_all(), 1);
  EXPECT_FALSE(fs::exists(mine));
  EXPECT_TRUE(fs::exists(taken));
}

TEST(EmergencyUnlink, MovesCarryTheEntryAndAFullTableRegistersNothing) {
  const fs::path dir = temp_dir("emergency_full");
  std::vector<EmergencyUnlink> held;
  for (std::size_t i = 0; i < EmergencyUnlink::kSlots; ++i)
    held.emplace_back(dir / ("f" + std::to_string(i)));  // moved as the vector grows
  for (const auto& h : held) EXPECT_TRUE(h.registered());
  const fs::path extra = dir / "extra";
  write(extra, "x");
  EmergencyUnlink none(extra);
  EXPECT_FALSE(none.registered()) << "the table is full";
  EmergencyUnlink moved = std::move(held.front());
  EXPECT_TRUE(moved.registered());
  EXPECT_FALSE(held.front().registered());
  held.clear();
  moved.reset();
  EXPECT_EQ(emergency_unlink_all(), 0);
  EXPECT_TRUE(fs::exists(extra));
  EmergencyUnlink again(extra);
  EXPECT_TRUE(again.registered()) << "slots are free again";
}

TEST(EmergencyUnlink, AHeldLockIsInTheTableWhileHeld) {
  const fs::path dir = temp_dir("emergency_lock");
  const fs::path file = dir / "clip.vdfx.json";
  std::optional<FileLock> lock = FileLock::acquire(file, "vdfx edit").lock;
  ASSERT_TRUE(lock.has_value());
  FileLock moved = std::move(*lock);  // the entry moves with the lock
  lock.reset();
  ASSERT_TRUE(fs::exists(lock_path(file)));
  EXPECT_EQ(emergency_unlink_all(), 1);
  EXPECT_FALSE(fs::exists(lock_path(file)));
  // Released (here: already gone), a later lock of the file is the only entry.
  auto again = FileLock::acquire(file, "vdfx edit");
  ASSERT_TRUE(again.lock.has_value());
  again.lock.reset();
  EXPECT_FALSE(fs::exists(lock_path(file)));
  EXPECT_EQ(emergency_unlink_all(), 0) << "released locks are out of the table";
}

}  // namespace
}  // namespace vdfx::io
