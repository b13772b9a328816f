/// @file
/// @brief Autosave and crash recovery of the sidecar being edited.
///
/// Every change writes the sidecar atomically to its path and a recovery copy next to it
/// (NAME.vdfx.json.autosave). A clean exit removes the recovery copy, so finding one at start means
/// the last session did not end cleanly: the editor offers it (it holds the last state even when
/// writing the sidecar itself failed, e.g. the folder became read-only).
#pragma once

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

class Autosave {
 public:
  explicit Autosave(std::filesystem::path sidecar_path);
  /// Writes the sidecar and the recovery copy (both atomically). Never throws: a failure is kept
  /// in status() and the next save tries again.
  bool save(const io::Sidecar& sidecar);
  /// Clean exit: the sidecar is written if it does not hold this state yet (a new one, or after
  /// a failed autosave), then the recovery copy is removed. Not counted as a change.
  bool finish(const io::Sidecar& sidecar);
  /// "saved NAME (n changes)", "NAME: no changes" or "autosave FAILED: reason".
  const std::string& status() const { return status_; }
  int saves() const { return saves_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::string status_ = "no changes yet";
  int saves_ = 0;
};

}  // namespace vdfx::app
