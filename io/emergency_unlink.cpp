/// @file
/// @brief EmergencyUnlink: a fixed table of paths, each slot claimed and released through an
/// atomic state, so a signal handler on any thread reads only complete entries.
#include "io/emergency_unlink.h"

#include <fcntl.h>
#include <sched.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>

namespace vdfx::io {
namespace {

enum SlotState : int {
  kFree = 0,
  kFilling = 1,  //!< being written by the thread that registers it
  kReady = 2,
  kInUse = 3,  //!< being read by emergency_unlink_all
};

struct Slot {
  std::atomic<int> state{kFree};
  char path[EmergencyUnlink::kMaxPath + 1] = {};
  char content[EmergencyUnlink::kMaxContent] = {};
  std::size_t content_size = 0;
  bool check_content = false;
};

std::array<Slot, EmergencyUnlink::kSlots> g_slots;
static_assert(std::atomic<int>::is_always_lock_free, "the handler needs a lock-free state");

/// Whether the file at `path` holds exactly `want` (open, read and close only).
bool holds_exactly(const char* path, const char* want, std::size_t size) noexcept {
  const int fd = ::open(path, O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return false;
  char buf[EmergencyUnlink::kMaxContent + 1];
  std::size_t got = 0;
  for (;;) {
    const ssize_t n = ::read(fd, buf + got, sizeof buf - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += static_cast<std::size_t>(n);
    if (got == sizeof buf) break;
  }
  ::close(fd);
  if (got != size) return false;
  for (std::size_t i = 0; i < size; ++i)
    if (buf[i] != want[i]) return false;
  return true;
}

}  // namespace

EmergencyUnlink::EmergencyUnlink(const std::filesystem::path& path, std::string_view content) {
  // Absolute: the handler must find the file whatever the working folder is by then.
  std::error_code ec;
  const std::filesystem::path abs = std::filesystem::absolute(path, ec);
  const std::string& p = ec ? path.native() : abs.native();
  if (p.empty() || p.size() > kMaxPath || content.size() > kMaxContent) return;
  for (std::size_t i = 0; i < g_slots.size(); ++i) {
    Slot& s = g_slots[i];
    int expected = kFree;
    if (!s.state.compare_exchange_strong(expected, kFilling)) continue;
    std::memcpy(s.path, p.c_str(), p.size() + 1);
    // (An empty view's data() may be null, which memcpy may not be given even for 0 bytes.)
    if (!content.empty()) std::memcpy(s.content, content.data(), content.size());
    s.content_size = content.size();
    s.check_content = !content.empty();
    s.state.store(kReady, std::memory_order_release);
    slot_ = static_cast<int>(i);
    return;
  }
}

EmergencyUnlink::~EmergencyUnlink() {
  reset();
}

EmergencyUnlink::EmergencyUnlink(EmergencyUnlink&& other) noexcept : slot_(other.slot_) {
  other.slot_ = -1;
}

EmergencyUnlink& EmergencyUnlink::operator=(EmergencyUnlink&& other) noexcept {
  if (this != &other) {
    reset();
    slot_ = other.slot_;
    other.slot_ = -1;
  }
  return *this;
}

void EmergencyUnlink::reset() noexcept {
  if (slot_ < 0) return;
  Slot& s = g_slots[static_cast<std::size_t>(slot_)];
  slot_ = -1;
  // A handler reading the slot on another thread ends the process when it is done; until then
  // the slot must not change under it.
  for (;;) {
    int expected = kReady;
    if (s.state.compare_exchange_strong(expected, kFree)) return;
    ::sched_yield();
  }
}

int emergency_unlink_all() noexcept {
  int removed = 0;
  for (Slot& s : g_slots) {
    int expected = kReady;
    if (!s.state.compare_exchange_strong(expected, kInUse, std::memory_order_acquire)) continue;
    if (!s.check_content || holds_exactly(s.path, s.content, s.content_size))
      removed += ::unlink(s.path) == 0 ? 1 : 0;
    s.state.store(kReady, std::memory_order_release);
  }
  return removed;
}

}  // namespace vdfx::io
