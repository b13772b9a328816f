/// @file
/// @brief Files to remove when the process must end at once: a second Ctrl-C within two seconds
/// (app/cli/stop_signals.h) has no time for destructors, yet must not leave a lock behind that
/// says the file is still open. The paths are kept in a fixed table that a signal handler can
/// walk with async-signal-safe calls only (open, read, close, unlink: POSIX.1-2017, 2.4.3).
///
/// What registers: every held lock (io/file_lock.h; removed only while it still holds the bytes
/// this process wrote, so a lock another process took over stays) and an export's temporary file
/// (app/export/output_file.h). A folder cannot be removed that way: a publish's staging folder is
/// left for the next publish to clear (docs/publish.md).
#pragma once

#include <filesystem>
#include <string_view>

namespace vdfx::io {

/// One registered path, for as long as the object lives (movable, not copyable). When the table
/// is full or the path too long (kMaxPath bytes), nothing is registered: the file is then left at
/// a hard stop, as it was before the table existed, and the destructors still remove it on every
/// ordinary way out.
class EmergencyUnlink {
 public:
  static constexpr std::size_t kSlots = 16;
  static constexpr std::size_t kMaxPath = 4095;
  static constexpr std::size_t kMaxContent = 1024;

  EmergencyUnlink() = default;
  /// `content` not empty: at a hard stop the file is removed only when it holds exactly these
  /// bytes (and no more than kMaxContent of them; a longer content registers nothing).
  explicit EmergencyUnlink(const std::filesystem::path& path, std::string_view content = {});
  ~EmergencyUnlink();
  EmergencyUnlink(EmergencyUnlink&& other) noexcept;
  EmergencyUnlink& operator=(EmergencyUnlink&& other) noexcept;
  EmergencyUnlink(const EmergencyUnlink&) = delete;
  EmergencyUnlink& operator=(const EmergencyUnlink&) = delete;

  /// Whether the path is in the table.
  bool registered() const { return slot_ >= 0; }
  /// Takes the path out of the table (the file itself is left alone).
  void reset() noexcept;

 private:
  int slot_ = -1;
};

/// Removes every registered file (async-signal-safe; for a signal handler that ends the process
/// right after). Returns how many it removed.
int emergency_unlink_all() noexcept;

}  // namespace vdfx::io
