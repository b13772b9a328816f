/// @file
/// @brief Autosave and crash recovery of the sidecar being edited.
///
/// Every change writes the sidecar atomically to its path and a recovery copy next to it
/// (NAME.vdfx.json.autosave). A clean exit removes the recovery copy, so finding one at start means
/// the last session did not end cleanly: the editor offers it (it holds the last state even when
/// writing the sidecar itself failed, e.g. the folder became read-only).
///
/// Nothing another author wrote is overwritten: the file's size, modification time and content
/// hash as last read or written are kept, and a save that finds them changed (another program
/// rewrote the sidecar) leaves that version in place and saves this author's to a side file
/// (NAME-yours-TIME.vdfx.json), where later saves go too; the status names it. A failed save
/// (full disk, read-only folder) keeps the document in memory and is retried (retry_due) until
/// one succeeds; the status says so meanwhile.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "io/sidecar.h"

namespace vdfx::app {

/// NAME.autosave next to the sidecar.
std::filesystem::path recovery_path(const std::filesystem::path& sidecar_path);

/// A recovery copy exists (only an unclean exit leaves one); the message says whether it differs
/// from the sidecar.
struct RecoveryOffer {
  std::filesystem::path path;
  std::string message;  //!< one line for the user
};
std::optional<RecoveryOffer> find_recovery(const std::filesystem::path& sidecar_path);

/// A sidecar's name with a tag before its .vdfx.json ("clip.vdfx.json", "yours-20261202-140509"
/// -> "clip-yours-20261202-140509.vdfx.json"), in the same folder (its relative video path holds).
std::filesystem::path side_file_path(const std::filesystem::path& sidecar_path,
                                     const std::string& tag);

/// A side file that does not exist yet: side_file_path with tag WHAT-YYYYMMDD-HHMMSS (UTC, now),
/// "-2", "-3", ... added while that name is taken.
std::filesystem::path new_side_file_path(const std::filesystem::path& sidecar_path,
                                         const std::string& what);

/// What identifies a file's contents cheaply enough to compare before every save.
struct FileFingerprint {
  bool exists = false;
  std::uintmax_t size = 0;
  std::int64_t mtime_ns = 0;
  std::uint64_t hash = 0;  //!< FNV-1a of the bytes
  bool operator==(const FileFingerprint&) const = default;
};
FileFingerprint fingerprint(const std::filesystem::path& path);

class Autosave {
 public:
  /// What save() writes to: the sidecar itself, or a copy that only a change creates (a read-only
  /// session's edits, app/editor/edit_access.h).
  enum class Target { Sidecar, CopyWhenChanged };
  explicit Autosave(std::filesystem::path sidecar_path, Target target = Target::Sidecar);
  /// Writes the sidecar and the recovery copy (both atomically). Never throws: a failure is kept
  /// in status() and retried (retry_due).
  bool save(const io::Sidecar& sidecar);
  /// Clean exit: the sidecar is written if it does not hold this state yet (a new one, or after
  /// a failed autosave), then the recovery copy is removed. Not counted as a change.
  bool finish(const io::Sidecar& sidecar);
  /// After a failed save: true once kRetryNs of display time have passed since the last attempt
  /// (the caller then saves again). The first call after a failure starts the clock.
  bool retry_due(std::int64_t t_ns);
  static constexpr std::int64_t kRetryNs = 2'000'000'000;
  /// "saved NAME (n changes)", "NAME: no changes", "autosave FAILED (...): reason" or, after a
  /// file changed under the editor, where this author's version went.
  const std::string& status() const { return status_; }
  int saves() const { return saves_; }
  /// The last save failed and none has succeeded since.
  bool failing() const { return failing_; }
  /// Where saves go now: the sidecar, or the side file after a change under the editor.
  const std::filesystem::path& path() const { return path_; }
  /// The side file this author's version went to when the sidecar changed under the editor.
  const std::optional<std::filesystem::path>& diverted_to() const { return diverted_; }

 private:
  /// Before a write: the sidecar changed since it was last read or written (another program)?
  /// Then saves go to a side file from now on, and the status says so.
  void divert_if_changed_on_disk();
  bool write(const std::string& text);

  std::filesystem::path path_;
  Target target_;
  FileFingerprint known_;  //!< the sidecar as last read or written by this session
  std::optional<std::filesystem::path> diverted_;
  std::filesystem::path original_;  //!< the sidecar, once saves were diverted from it
  std::string status_ = "no changes yet";
  std::string error_;  //!< the last failed save's reason
  std::string note_;   //!< said after every later status (the side file's name)
  int saves_ = 0;
  bool failing_ = false;
  std::optional<std::int64_t> last_try_ns_;
};

}  // namespace vdfx::app
