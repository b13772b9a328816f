/// @file
/// @brief StopSignals: the handler (async-signal-safe: atomics, clock_gettime, write, unlink
/// through io::emergency_unlink_all, sigaction, sigprocmask, raise, _exit) and the way out.
#include "app/cli/stop_signals.h"

#include <sched.h>
#include <signal.h>
#include <time.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "io/emergency_unlink.h"

namespace vdfx::app {
namespace {

constexpr std::array<int, 3> kStopSignals = {SIGINT, SIGTERM, SIGHUP};
/// A stop signal this soon after the one before ends the process at once.
constexpr std::int64_t kHardStopWindowNs = 2'000'000'000;

std::atomic<bool> g_flag{false};
std::atomic<int> g_signal{0};            //!< the first stop signal (0: none)
std::atomic<std::int64_t> g_last_ns{0};  //!< CLOCK_MONOTONIC of the last one (0: none)
std::atomic<int> g_handlers_running{0};  //!< handlers between reading and using g_cancel
std::array<std::atomic<std::atomic<bool>*>, CancelOnStop::kMaxCancelFlags> g_cancel{};
int g_depth = 0;  //!< live StopSignals (main thread only)
std::array<struct sigaction, kStopSignals.size()> g_previous{};

static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free &&
                  std::atomic<std::int64_t>::is_always_lock_free &&
                  std::atomic<std::atomic<bool>*>::is_always_lock_free,
              "a signal handler may only touch lock-free atomics");

const char* literal_name(int sig) noexcept {
  switch (sig) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return "a signal";
  }
}

void write_stderr(const char* text) noexcept {
  std::size_t left = std::strlen(text);
  while (left > 0) {
    const ssize_t n = ::write(STDERR_FILENO, text, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    text += n;
    left -= static_cast<std::size_t>(n);
  }
}

/// Ends the process by `sig` with its default action (from a handler too: the signal, blocked
/// while its handler runs, is delivered as soon as it is unblocked).
[[noreturn]] void die_by(int sig) noexcept {
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  ::sigaction(sig, &dfl, nullptr);
  ::raise(sig);
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, sig);
  ::sigprocmask(SIG_UNBLOCK, &set, nullptr);
  ::_exit(128 + sig);  // only if the default action did not end it
}

std::int64_t monotonic_ns() noexcept {
  timespec ts{};
  ::clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

extern "C" void on_stop_signal(int sig) {
  const int saved_errno = errno;
  const std::int64_t now = monotonic_ns();
  const std::int64_t last = g_last_ns.exchange(now);
  if (last != 0 && now - last <= kHardStopWindowNs) {
    // No time for destructors: what must not stay behind goes now.
    const int removed = io::emergency_unlink_all();
    write_stderr("\nvdfx: ");
    write_stderr(literal_name(sig));
    write_stderr(removed > 0 ? " again within 2 s: stopped at once (its locks removed)\n"
                             : " again within 2 s: stopped at once\n");
    die_by(sig);
  }
  int none = 0;
  g_signal.compare_exchange_strong(none, sig);
  g_flag.store(true);
  g_handlers_running.fetch_add(1);
  for (auto& c : g_cancel)
    if (std::atomic<bool>* f = c.load()) f->store(true);
  g_handlers_running.fetch_sub(1);
  errno = saved_errno;
}

}  // namespace

StopSignals::StopSignals() {
  if (g_depth++ > 0) return;
  g_flag = false;
  g_signal = 0;
  g_last_ns = 0;
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  // Restarted system calls: a read or write a signal lands in goes on (the loops see the flag).
  sa.sa_flags = SA_RESTART;
  for (std::size_t i = 0; i < kStopSignals.size(); ++i)
    ::sigaction(kStopSignals[i], &sa, &g_previous[i]);
}

StopSignals::~StopSignals() {
  if (--g_depth > 0) return;
  for (std::size_t i = 0; i < kStopSignals.size(); ++i)
    ::sigaction(kStopSignals[i], &g_previous[i], nullptr);
  // Loops that run later (a library call in the same process) are not stopped by it; the
  // signal stays recorded for end_by_stop_signal.
  g_flag = false;
}

const std::atomic<bool>& StopSignals::flag() {
  return g_flag;
}

bool stop_requested() {
  return g_flag.load();
}

int stop_signal() {
  return g_signal.load();
}

std::string signal_name(int sig) {
  const char* name = literal_name(sig);
  return name[0] == 'S' ? std::string(name) : "signal " + std::to_string(sig);
}

std::string stopped_by() {
  return "stopped by " + signal_name(stop_signal());
}

CancelOnStop::CancelOnStop(std::atomic<bool>& flag) {
  for (std::size_t i = 0; i < g_cancel.size(); ++i) {
    std::atomic<bool>* none = nullptr;
    if (g_cancel[i].compare_exchange_strong(none, &flag)) {
      slot_ = static_cast<int>(i);
      // A signal that came before the link still stops the loop.
      if (g_flag.load()) flag.store(true);
      return;
    }
  }
  throw std::logic_error("CancelOnStop: more than " + std::to_string(kMaxCancelFlags) +
                         " cancel flags linked at once");
}

CancelOnStop::~CancelOnStop() {
  g_cancel[static_cast<std::size_t>(slot_)].store(nullptr);
  // A handler on another thread may hold the pointer it read: the flag must outlive it.
  while (g_handlers_running.load() > 0) ::sched_yield();
}

int end_by_stop_signal(int code) {
  const int sig = g_signal.load();
  if (sig == 0) return code;
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  die_by(sig);
}

}  // namespace vdfx::app
