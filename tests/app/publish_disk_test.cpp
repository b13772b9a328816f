/// @file
/// @brief `vdfx publish` and the disk around OUT (docs/publish.md, docs/reliability.md): it makes
/// its own folder durable and nothing else (beside a named pipe and thousands of the user's files
/// it opens none of them and finishes), a full disk keeps the old folder, and a parent folder
/// that cannot be synced is a warning. The real executable with tests/fault/fault_inject.c
/// preloaded (the opens it logs, the faults it injects).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <sstream>

#include "publish_test_util.h"

namespace vdfx::app::testing {
namespace {

namespace fs = std::filesystem;
using test_files::slurp;

/// `vdfx publish` with the injector preloaded and `env` (VAR=value ...) set, under a time limit
/// (a publish that blocks is exit 124, not a hung test).
CommandResult publish_with(const std::string& env, const Fixture& f, const fs::path& out) {
  return run_vdfx(publish_args(f, out),
                  "env -u DISPLAY LD_PRELOAD=" + std::string(VDFX_FAULT_SO) + " " + env +
                      " ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0"
                      " timeout 60 ");
}

/// A folder as a user's busy one: `folders` sub-folders of `files` files each, and a named pipe
/// at its top and in one sub-folder (opening one for reading blocks until a writer comes).
void fill_busy_folder(const fs::path& dir, int folders, int files) {
  for (int d = 0; d < folders; ++d) {
    const fs::path sub = dir / ("d" + std::to_string(d));
    fs::create_directories(sub);
    for (int i = 0; i < files; ++i) std::ofstream(sub / ("f" + std::to_string(i))) << i;
  }
  ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0644), 0);
  ASSERT_EQ(::mkfifo((dir / "d0" / "pipe").c_str(), 0644), 0);
}

/// The lines of the open log naming something in `busy` that is neither `busy` itself nor the
/// published folder `site` or its staging folder beside it.
std::vector<std::string> foreign_opens(const fs::path& log, const fs::path& busy) {
  std::vector<std::string> out;
  std::istringstream lines(slurp(log));
  const std::string root = busy.string() + "/";
  for (std::string l; std::getline(lines, l);) {
    if (!l.starts_with(root)) continue;
    const std::string rel = l.substr(root.size());
    if (rel.empty() || rel == "." || rel == "site" || rel.starts_with("site/") ||
        rel.starts_with(".site.publish-"))
      continue;
    out.push_back(l);
  }
  return out;
}

// Publishing into a busy folder (thousands of files, named pipes) syncs the new folder and the
// parent's own entry: it finishes, and nothing else there is opened. It once walked and opened
// every entry of the parent, and blocked for ever on the pipe.
TEST(PublishDisk, BesideANamedPipeAndThousandsOfFilesItOpensNoneOfThemAndFinishes) {
  if (!module_built()) GTEST_SKIP() << kNoModule;
  const Fixture f = make_fixture();
  const fs::path busy = fs::canonical(f.dir) / "busy";
  fill_busy_folder(busy, 20, 100);
  const fs::path log = f.dir / "opens.log";
  // Twice: a new folder (a rename), then the replacement of the one it wrote (an exchange).
  for (int run = 0; run < 2; ++run) {
    const CommandResult r = publish_with("VDFX_OPEN_LOG=" + log.string(), f, busy / "site");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(fs::is_regular_file(busy / "site" / "index.html"));
  }
  ASSERT_TRUE(fs::exists(log));
  const std::vector<std::string> foreign = foreign_opens(log, busy);
  EXPECT_TRUE(foreign.empty()) << foreign.size() << " of the user's entries opened, the first "
                               << foreign.front();
  // The parent itself was opened (its entry synced, its names read for stale staging folders).
  EXPECT_NE(slurp(log).find(busy.string() + "\n"), std::string::npos);
  EXPECT_TRUE(fs::is_fifo(busy / "pipe"));
  EXPECT_TRUE(leftovers(busy / "site").empty());
}

// A disk that fills up during a publish: exit 1 naming the reason; the old folder stays exactly
// as it was and no staging folder is left (and a first publish leaves no OUT at all).
TEST(PublishDisk, OnAFullDiskItFailsNamingTheReasonAndKeepsTheOldFolder) {
  if (!module_built()) GTEST_SKIP() << kNoModule;
  const Fixture f = make_fixture();
  const fs::path out = f.dir / "site";
  const std::string full = "VDFX_FAULT=write_enospc VDFX_FAULT_AFTER=";
  CommandResult r = publish_with(full + "20000", f, out);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_TRUE(leftovers(out).empty());

  ASSERT_EQ(run_vdfx_headless(publish_args(f, out, "--title First")).exit_code, 0);
  const std::set<std::string> first = listing(out);
  const std::string page = slurp(out / "index.html");
  // The disk fills at several points: in the video's copy, in the page's files, in the module.
  for (const char* after : {"0", "20000", "400000"}) {
    r = publish_with(full + after, f, out);
    EXPECT_EQ(r.exit_code, 1) << after << ": " << r.output;
    EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
    EXPECT_EQ(listing(out), first) << after;
    EXPECT_EQ(slurp(out / "index.html"), page) << after;
    EXPECT_TRUE(leftovers(out).empty()) << after;
  }
}

// The parent's entry cannot be synced (EIO): the folder is in place and publish says it is not
// yet durable (exit 0, a warning naming the folder). A file system that cannot sync folders at
// all (EINVAL) is no failure. A file of the new folder that cannot be synced keeps the old one.
TEST(PublishDisk, AParentThatCannotBeSyncedIsAWarningAndTheFolderIsInPlace) {
  if (!module_built()) GTEST_SKIP() << kNoModule;
  const Fixture f = make_fixture();
  const fs::path parent = fs::canonical(f.dir);
  const fs::path out = parent / "site";
  CommandResult r = publish_with("VDFX_FAULT=fsync_dir VDFX_FAULT_PATH=" + parent.string(), f, out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("vdfx publish: warning: " + out.string() +
                          ": published, but not yet durable: the fsync of its folder " +
                          parent.string() + " failed (Input/output error)"),
            std::string::npos)
      << r.output;
  EXPECT_TRUE(fs::is_regular_file(out / "player.json"));

  r = publish_with("VDFX_FAULT=fsync_dir VDFX_FAULT_ERRNO=EINVAL", f, out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;

  const std::string page = slurp(out / "index.html");
  r = run_vdfx_headless(publish_args(f, out, "--title Second"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string second = slurp(out / "index.html");
  ASSERT_NE(second, page);
  r = publish_with("VDFX_FAULT=fsync_file", f, out);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("cannot be made durable"), std::string::npos) << r.output;
  EXPECT_EQ(slurp(out / "index.html"), second);
  EXPECT_TRUE(leftovers(out).empty());
}

}  // namespace
}  // namespace vdfx::app::testing
