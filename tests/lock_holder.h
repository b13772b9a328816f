/// @file
/// @brief A second, real process that holds a file's lock (io/file_lock.h) until killed: the
/// other editor of the tests of issue 23.
#pragma once

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "io/file_lock.h"

namespace vdfx::test_files {

class LockHolder {
 public:
  /// Forks a child that takes `file`'s lock as `command` and waits; returns once it holds it.
  explicit LockHolder(const std::filesystem::path& file, const std::string& command = "vdfx edit") {
    int fds[2];
    if (::pipe(fds) != 0) throw std::runtime_error("pipe");
    pid_ = ::fork();
    if (pid_ < 0) throw std::runtime_error("fork");
    if (pid_ == 0) {
      ::close(fds[0]);
      char ok = 0;
      try {
        auto r = io::FileLock::acquire(file, command);
        ok = r.lock ? 1 : 0;
        (void)!::write(fds[1], &ok, 1);
        if (ok) {
          for (;;) ::pause();
        }
      } catch (...) {
        (void)!::write(fds[1], &ok, 1);
      }
      ::_exit(0);
    }
    ::close(fds[1]);
    char ok = 0;
    const bool got = ::read(fds[0], &ok, 1) == 1;
    ::close(fds[0]);
    if (!got || !ok) {
      kill();
      throw std::runtime_error("the child could not take the lock of " + file.string());
    }
  }
  LockHolder(const LockHolder&) = delete;
  LockHolder& operator=(const LockHolder&) = delete;
  ~LockHolder() { kill(); }
  pid_t pid() const { return pid_; }
  /// SIGKILL, as a crash: the lock file stays behind, stale. `reap`: false leaves the child a
  /// zombie until the destructor (a parent that has not waited for it yet).
  void kill(bool reap = true) {
    if (pid_ <= 0) return;
    if (!killed_) ::kill(pid_, SIGKILL);
    killed_ = true;
    if (!reap) {
      for (int i = 0; i < 500 && state() != 'Z'; ++i) ::usleep(2000);
      return;
    }
    ::waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }
  /// The child's state letter from /proc ('Z': zombie), '?' when unknown.
  char state() const {
    FILE* f = std::fopen(("/proc/" + std::to_string(pid_) + "/stat").c_str(), "r");
    if (!f) return '?';
    char buf[512] = {};
    const std::size_t n = std::fread(buf, 1, sizeof buf - 1, f);
    std::fclose(f);
    const std::string line(buf, n);
    const auto close = line.rfind(')');
    return close != std::string::npos && close + 2 < line.size() ? line[close + 2] : '?';
  }

 private:
  pid_t pid_ = -1;
  bool killed_ = false;
};

}  // namespace vdfx::test_files
