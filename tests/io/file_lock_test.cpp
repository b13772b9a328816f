/// @file
/// @brief Issue 23: one writer per file. The lock beside a file (pid, host, start time), held by a
/// second real process, refused to vdfx's writers, taken over once that process is gone.
#include "io/file_lock.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "io/atomic_file.h"
#include "io_test_util.h"
#include "tests/lock_holder.h"

namespace vdfx::io {
namespace {

namespace fs = std::filesystem;
using test_files::LockHolder;
using test_files::slurp;
using testing::error_of;
using testing::temp_dir;

std::string hostname() {
  char buf[256] = {};
  ::gethostname(buf, sizeof buf - 1);
  return buf;
}

TEST(FileLock, TheLockSaysWhoWhereAndSinceWhenAndGoesWithTheHolder) {
  const fs::path file = temp_dir("lock_basic") / "clip.vdfx.json";
  {
    auto r = FileLock::acquire(file, "vdfx edit");
    ASSERT_TRUE(r.lock.has_value());
    EXPECT_FALSE(r.held_by || r.took_over);
    EXPECT_EQ(r.lock->path(), lock_path(file));
    EXPECT_EQ(lock_path(file).filename(), "clip.vdfx.json.lock");
    const auto j = nlohmann::json::parse(slurp(lock_path(file)));
    EXPECT_EQ(j.at("pid").get<long>(), static_cast<long>(::getpid()));
    EXPECT_EQ(j.at("host").get<std::string>(), hostname());
    EXPECT_EQ(j.at("command").get<std::string>(), "vdfx edit");
    EXPECT_EQ(j.at("started").get<std::string>().size(), 20u);  // 2026-12-02T14:05:09Z
    // Its own lock does not stop this process's writes.
    write_file_atomic(file, "mine");
    EXPECT_EQ(slurp(file), "mine");
  }
  EXPECT_FALSE(fs::exists(lock_path(file))) << "released with the lock";
}

TEST(FileLock, ASecondProcessHoldsItUntilItIsGoneThenItIsTakenOver) {
  const fs::path file = temp_dir("lock_two") / "clip.vdfx.json";
  std::ofstream(file) << "the other author's";
  LockHolder other(file);
  const pid_t pid = other.pid();

  auto second = FileLock::acquire(file, "vdfx edit");
  EXPECT_FALSE(second.lock.has_value());
  ASSERT_TRUE(second.held_by.has_value());
  EXPECT_EQ(second.held_by->pid, pid);
  EXPECT_EQ(second.held_by->host, hostname());
  EXPECT_TRUE(owner_alive(*second.held_by));
  EXPECT_NE(second.held_by->describe().find("vdfx edit (process " + std::to_string(pid) + " on "),
            std::string::npos);

  // Every writer of vdfx refuses it, naming the owner and the lock.
  const std::string e = error_of([&] { write_file_atomic(file, "mine"); });
  EXPECT_NE(e.find("refusing to write " + file.string() + ": it is open in vdfx edit (process " +
                   std::to_string(pid)),
            std::string::npos)
      << e;
  EXPECT_NE(e.find(lock_path(file).string()), std::string::npos) << e;
  EXPECT_EQ(slurp(file), "the other author's");
  EXPECT_NE(error_of([&] {
              check_not_locked_by_another(file, "--sidecar-out");
            }).find("refusing to write --sidecar-out "),
            std::string::npos);

  // Killed: the lock stays behind, stale; the next one takes it over and says whose it was.
  other.kill();
  ASSERT_TRUE(fs::exists(lock_path(file)));
  EXPECT_FALSE(owner_alive(*read_lock(file)));
  EXPECT_EQ(error_of([&] { check_not_locked_by_another(file); }), "");
  auto third = FileLock::acquire(file, "vdfx edit");
  ASSERT_TRUE(third.lock.has_value());
  ASSERT_TRUE(third.took_over.has_value());
  EXPECT_EQ(third.took_over->pid, pid);
  EXPECT_EQ(read_lock(file)->pid, static_cast<long>(::getpid()));
}

TEST(FileLock, AKilledHolderNotYetReapedHoldsNothing) {
  // Found by the probe: an editor killed while its parent had not waited for it yet (a zombie;
  // a container's init may never reap it) still answered kill(pid, 0), so its lock looked held.
  const fs::path file = temp_dir("lock_zombie") / "clip.vdfx.json";
  LockHolder other(file);
  other.kill(/*reap=*/false);
  ASSERT_EQ(other.state(), 'Z');
  EXPECT_FALSE(owner_alive(*read_lock(file)));
  auto r = FileLock::acquire(file, "vdfx edit");
  ASSERT_TRUE(r.lock.has_value());
  ASSERT_TRUE(r.took_over.has_value());
  EXPECT_EQ(r.took_over->pid, other.pid());
}

struct LockCase {
  const char* name;
  std::string text;  //!< the lock file's contents (PID and HOST replaced)
  bool alive;
};
void PrintTo(const LockCase& c, std::ostream* os) {
  *os << c.name;
}
const LockCase kLocks[] = {
    // An id that now belongs to a process started later than the lock's (here: this one).
    {"reused_pid", R"({"format":"vdfx.lock","pid":PPID,"host":"HOST","process_start":1})", false},
    {"live_pid", R"({"format":"vdfx.lock","pid":PPID,"host":"HOST"})", true},
    {"free_pid", R"({"format":"vdfx.lock","pid":2147483000,"host":"HOST"})", false},
    // Another machine (a shared folder): its processes cannot be checked, so it is held.
    {"other_host", R"({"format":"vdfx.lock","pid":2147483000,"host":"elsewhere.example"})", true},
    {"malformed", "not a lock", true},
};

class FileLockOwners : public ::testing::TestWithParam<LockCase> {};
TEST_P(FileLockOwners, OnlyAProcessKnownToBeGoneMakesALockStale) {
  const LockCase& c = GetParam();
  const fs::path file = temp_dir(std::string("lock_") + c.name) / "s.vdfx.json";
  std::string text = c.text;
  auto replace = [&](const std::string& what, const std::string& with) {
    if (const auto at = text.find(what); at != std::string::npos)
      text.replace(at, what.size(), with);
  };
  replace("PPID", std::to_string(::getppid()));
  replace("PID", std::to_string(::getpid()));
  replace("HOST", hostname());
  std::ofstream(lock_path(file)) << text;
  const auto owner = read_lock(file);
  ASSERT_TRUE(owner.has_value());
  EXPECT_EQ(owner_alive(*owner), c.alive);
  auto r = FileLock::acquire(file, "vdfx edit");
  EXPECT_EQ(r.lock.has_value(), !c.alive);
  EXPECT_EQ(r.held_by.has_value(), c.alive);
  if (c.alive) {
    EXPECT_EQ(slurp(lock_path(file)), text) << "a held lock is left alone";
  }
}
INSTANTIATE_TEST_SUITE_P(Rows, FileLockOwners, ::testing::ValuesIn(kLocks),
                         [](const auto& i) { return std::string(i.param.name); });

}  // namespace
}  // namespace vdfx::io
