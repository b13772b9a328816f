/// @file
/// @brief Autosave: sidecar + recovery copy per change, removed on a clean exit.
#include "app/editor/autosave.h"

#include <fstream>
#include <sstream>
#include <system_error>

#include "io/atomic_file.h"

namespace vdfx::app {

namespace fs = std::filesystem;

fs::path recovery_path(const fs::path& sidecar_path) {
  fs::path p = sidecar_path;
  p += ".autosave";
  return p;
}

namespace {
std::optional<std::string> slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

std::optional<RecoveryOffer> find_recovery(const fs::path& sidecar_path) {
  const fs::path rec = recovery_path(sidecar_path);
  std::error_code ec;
  if (!fs::is_regular_file(rec, ec)) return std::nullopt;
  const auto rec_bytes = slurp(rec);
  if (!rec_bytes) return std::nullopt;
  const auto side_bytes = slurp(sidecar_path);
  std::string why;
  if (!side_bytes) {
    why = "the sidecar is missing";
  } else if (*side_bytes != *rec_bytes) {
    why = "it differs from the sidecar";
  } else {
    why = "the last session did not exit cleanly; the sidecar holds the same edits";
  }
  return RecoveryOffer{rec, "found an autosave " + rec.string() + " (" + why +
                                "): start with it to recover the last session"};
}

Autosave::Autosave(fs::path sidecar_path) : path_(std::move(sidecar_path)) {}

bool Autosave::save(const io::Sidecar& sidecar) {
  const std::string text = io::format_sidecar(sidecar);
  try {
    // The recovery copy first: if the sidecar write fails, the recovery copy still holds the edit.
    // The recovery copy's name is vdfx's own: a link planted there is refused, not followed.
    io::write_file_atomic(recovery_path(path_), text, io::OutputName::Generated);
    io::write_file_atomic(path_, text);
  } catch (const std::exception& e) {
    status_ = std::string("autosave FAILED: ") + e.what();
    return false;
  }
  ++saves_;
  status_ = "saved " + path_.filename().string() + " (" + std::to_string(saves_) +
            (saves_ == 1 ? " change)" : " changes)");
  return true;
}

bool Autosave::finish(const io::Sidecar& sidecar) {
  // The final state on disk: written when the file does not hold it yet (a new sidecar, or an
  // autosave that failed); not a change of its own.
  const std::string text = io::format_sidecar(sidecar);
  const auto on_disk = slurp(path_);
  if (on_disk != text) {
    try {
      io::write_file_atomic(path_, text);
    } catch (const std::exception& e) {
      status_ = std::string("saving FAILED: ") + e.what();
      return false;
    }
  }
  if (saves_ == 0)
    status_ = path_.filename().string() +
              (on_disk ? ": no changes" : ": new sidecar written (no keyframes yet)");
  std::error_code ec;
  fs::remove(recovery_path(path_), ec);
  return !ec;
}

}  // namespace vdfx::app
