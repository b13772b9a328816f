/// @file
/// @brief The mechanism every long command shares (app/cli/stop_signals.h), with real signals:
/// raised in this process while a StopSignals lives (the flag, the signal's name, linked cancel
/// flags, nesting, the previous handlers back), and in forked children for what ends a process
/// (a second signal within 2 s, removing a held lock; end_by_stop_signal; a second one later
/// that does not).
#include "app/cli/stop_signals.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "app/bench/bench_request.h"
#include "app/cli/command_registry.h"
#include "io/emergency_unlink.h"
#include "io/file_lock.h"
#include "tests/app/command_test_util.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;

/// The handler installed for `sig` now.
void (*current_handler(int sig))(int) {
  struct sigaction sa {};
  ::sigaction(sig, nullptr, &sa);
  return sa.sa_handler;
}

TEST(StopSignals, ASignalSetsTheFlagAndTheProcessGoesOn) {
  const auto before = current_handler(SIGTERM);
  {
    const StopSignals stop;
    EXPECT_FALSE(stop_requested());
    EXPECT_EQ(stop_signal(), 0);
    std::atomic<bool> cancel{false};
    const CancelOnStop link(cancel);
    ASSERT_EQ(::raise(SIGTERM), 0);
    EXPECT_TRUE(stop_requested());
    EXPECT_TRUE(StopSignals::flag().load());
    EXPECT_EQ(stop_signal(), SIGTERM);
    EXPECT_EQ(stopped_by(), "stopped by SIGTERM");
    EXPECT_TRUE(cancel.load()) << "a linked cancel flag is set too";
    // A flag linked after the signal came is set at once: the loop it stops starts stopped.
    std::atomic<bool> late{false};
    const CancelOnStop late_link(late);
    EXPECT_TRUE(late.load());
  }
  EXPECT_EQ(current_handler(SIGTERM), before) << "the previous handler is back";
  EXPECT_EQ(signal_name(SIGINT), "SIGINT");
  EXPECT_EQ(signal_name(SIGHUP), "SIGHUP");
  EXPECT_EQ(signal_name(SIGUSR1), "signal " + std::to_string(SIGUSR1));
}

TEST(StopSignals, NestedOnesShareTheOutermostsHandler) {
  const auto before = current_handler(SIGHUP);
  const StopSignals outer;
  const auto installed = current_handler(SIGHUP);
  EXPECT_NE(installed, before);
  {
    const StopSignals inner;  // an export inside a publish
    EXPECT_EQ(current_handler(SIGHUP), installed);
    ASSERT_EQ(::raise(SIGHUP), 0);
  }
  EXPECT_EQ(current_handler(SIGHUP), installed) << "still the outer one's";
  EXPECT_EQ(stop_signal(), SIGHUP);
}

TEST(StopSignals, RunGuardedSaysWhatTheStoppedCommandKept) {
  const StopSignals stop;
  ASSERT_EQ(::raise(SIGINT), 0);
  ::testing::internal::CaptureStderr();
  const int code = run_guarded(
      "suggest",
      [](const Args&) -> int { throw Stopped("nothing written; o.json left as it was"); }, {});
  const std::string said = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(code, 128 + SIGINT);
  EXPECT_NE(said.find("vdfx suggest: stopped by SIGINT: nothing written; o.json left as it was\n"),
            std::string::npos)
      << said;
}

TEST(StopSignals, BenchStopsBetweenRowsAndWritesNothing) {
  const fs::path json = testing::test_dir() / "report.json";
  bench::BenchRequest req;
  req.quick = true;
  req.filter = "^rbf\\.";
  req.json_path = json.string();
  const StopSignals stop;
  ASSERT_EQ(::raise(SIGINT), 0);
  std::ostringstream markdown;
  try {
    bench::run_bench(req, markdown);
    ADD_FAILURE() << "not stopped";
  } catch (const Stopped& e) {
    EXPECT_NE(std::string(e.what()).find("after 0 of "), std::string::npos) << e.what();
  }
  EXPECT_TRUE(markdown.str().empty());
  EXPECT_FALSE(fs::exists(json));
}

/// Runs `body` in a forked child; returns its wait status.
template <class Body>
int in_child(Body body) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    body();
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

TEST(StopSignals, ASecondSignalWithinTwoSecondsEndsAtOnceRemovingTheLock) {
  const fs::path dir = testing::test_dir();
  const fs::path file = dir / "clip.vdfx.json", temp = dir / ".clip.tmp-1.mp4";
  testing::write_text(temp, "partial");
  const int status = in_child([&] {
    const StopSignals stop;
    auto lock = io::FileLock::acquire(file, "vdfx edit");
    const io::EmergencyUnlink temp_entry(temp);
    ::raise(SIGINT);  // the first: a request, the child goes on
    if (!stop_requested() || !fs::exists(io::lock_path(file))) ::_exit(10);
    ::raise(SIGINT);  // the second: ends it here
    ::_exit(11);
  });
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT)
      << (WIFEXITED(status) ? "exit " + std::to_string(WEXITSTATUS(status)) : "other");
  EXPECT_FALSE(fs::exists(io::lock_path(file))) << "the lock went with it";
  EXPECT_FALSE(fs::exists(temp)) << "and the temporary file";
}

TEST(StopSignals, ASecondSignalMoreThanTwoSecondsLaterIsAnotherRequest) {
  const int status = in_child([] {
    const StopSignals stop;
    ::raise(SIGTERM);
    std::this_thread::sleep_for(std::chrono::milliseconds(2100));
    ::raise(SIGTERM);
    ::_exit(stop_signal() == SIGTERM ? 0 : 12);
  });
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
}

TEST(StopSignals, EndByStopSignalEndsByTheSignalThatCameOrReturnsTheCode) {
  const int stopped = in_child([] {
    {
      const StopSignals stop;
      ::raise(SIGHUP);
    }
    ::_exit(end_by_stop_signal(0) + 20);
  });
  EXPECT_TRUE(WIFSIGNALED(stopped) && WTERMSIG(stopped) == SIGHUP) << stopped;
  const int plain = in_child([] {
    { const StopSignals stop; }
    ::_exit(end_by_stop_signal(7));
  });
  EXPECT_TRUE(WIFEXITED(plain) && WEXITSTATUS(plain) == 7) << plain;
}

}  // namespace
}  // namespace vdfx::app
