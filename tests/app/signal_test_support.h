/// @file
/// @brief Real vdfx processes sent real signals (docs/cli.md, "Stopping a command"): start the
/// executable with its output in a file, wait until it is at work (a file appears, a line count
/// is reached), kill() it, and read how it ended.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "tests/openxr/child_process.h"
#include "tests/support/test_paths.h"
#include "tests/test_files.h"

namespace vdfx::app::testing {

/// A vdfx process: started by the constructor, killed (SIGKILL) by the destructor if still there.
class VdfxProcess {
 public:
  /// `vdfx ARGS...` with `env` added to this process's environment, stdout and stderr into `log`.
  VdfxProcess(const std::vector<std::string>& args, const std::filesystem::path& log,
              const std::vector<std::pair<std::string, std::string>>& env = {})
      : log_(log) {
    std::vector<std::string> env_strings = test_runtime::environment_with(env),
                             argv_strings = {std::string(VDFX_BINARY)};
    argv_strings.insert(argv_strings.end(), args.begin(), args.end());
    std::vector<char*> envp, argv;
    for (auto& s : env_strings) envp.push_back(s.data());
    for (auto& s : argv_strings) argv.push_back(s.data());
    envp.push_back(nullptr);
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    // A process group of its own: a terminal's Ctrl-C reaches the whole group, but these signals
    // go to vdfx alone (kill() below), as a test should send them.
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attr, 0);
    if (posix_spawn(&pid_, argv[0], &actions, &attr, argv.data(), envp.data()) != 0) pid_ = -1;
    posix_spawnattr_destroy(&attr);
    posix_spawn_file_actions_destroy(&actions);
  }
  ~VdfxProcess() {
    if (pid_ > 0 && !ended_) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, &status_, 0);
    }
  }
  VdfxProcess(const VdfxProcess&) = delete;
  VdfxProcess& operator=(const VdfxProcess&) = delete;

  pid_t pid() const { return pid_; }
  std::string output() const { return test_files::slurp(log_); }

  /// Polls `ready` every 10 ms until it holds (true), the process ends or `timeout` passes.
  bool wait_until(const std::function<bool()>& ready,
                  std::chrono::milliseconds timeout = std::chrono::seconds(120)) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < end) {
      if (ready()) return true;
      if (reap(false)) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
  }

  void signal(int sig) const { ::kill(pid_, sig); }

  /// Sends `sig` every `every` until the process has ended (at most `timeout`); the wait status.
  /// Two signals sent back to back can merge into one pending signal; sent apart, the first one's
  /// clean stop may be over before the second: a steady stream is sure to land during it.
  int signal_until_ended(int sig, std::chrono::microseconds every = std::chrono::microseconds(500),
                         std::chrono::milliseconds timeout = std::chrono::seconds(60)) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (!reap(false) && std::chrono::steady_clock::now() < end) {
      ::kill(pid_, sig);
      std::this_thread::sleep_for(every);
    }
    return wait();
  }

  /// Waits for the end (at most `timeout`; then SIGKILL) and returns the wait status.
  int wait(std::chrono::milliseconds timeout = std::chrono::seconds(60)) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (!reap(false)) {
      if (std::chrono::steady_clock::now() > end) {
        ::kill(pid_, SIGKILL);
        reap(true);
        timed_out_ = true;
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return status_;
  }
  bool timed_out() const { return timed_out_; }

 private:
  bool reap(bool block) {
    if (ended_) return true;
    if (::waitpid(pid_, &status_, block ? 0 : WNOHANG) == pid_) ended_ = true;
    return ended_;
  }

  std::filesystem::path log_;
  pid_t pid_ = -1;
  int status_ = 0;
  bool ended_ = false;
  bool timed_out_ = false;
};

/// "signal 2" or "exit 0": how a wait status ended, for messages.
inline std::string describe_status(int status) {
  if (WIFSIGNALED(status)) return "signal " + std::to_string(WTERMSIG(status));
  if (WIFEXITED(status)) return "exit " + std::to_string(WEXITSTATUS(status));
  return "status " + std::to_string(status);
}

/// Lines in a file so far (0 when it does not exist).
inline std::size_t line_count(const std::filesystem::path& p) {
  const std::string text = test_files::slurp(p);
  std::size_t n = 0;
  for (const char c : text) n += c == '\n' ? 1 : 0;
  return n;
}

}  // namespace vdfx::app::testing
