/// @file
/// @brief Autosave: sidecar + recovery copy per change, removed on a clean exit.
#include "app/editor/autosave.h"

#include <sys/stat.h>

#include <ctime>
#include <fstream>
#include <sstream>
#include <system_error>

#include "io/atomic_file.h"
#include "io/input_file.h"

namespace vdfx::app {

namespace fs = std::filesystem;

fs::path recovery_path(const fs::path& sidecar_path) {
  fs::path p = sidecar_path;
  p += ".autosave";
  return p;
}

namespace {
/// The whole file (a sidecar or its recovery copy), or nothing when it cannot be read.
std::optional<std::string> slurp(const fs::path& p) {
  std::string why;
  return io::try_read_input_file(p, io::kMaxSidecarBytes, "a sidecar", why);
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

fs::path side_file_path(const fs::path& sidecar_path, const std::string& tag) {
  std::string name = sidecar_path.filename().string();
  const std::string ext = ".vdfx.json";
  std::string tail = ext;
  if (name.size() > ext.size() && name.compare(name.size() - ext.size(), ext.size(), ext) == 0)
    name.resize(name.size() - ext.size());
  else
    tail = sidecar_path.extension().string(), name = sidecar_path.stem().string();
  return sidecar_path.parent_path() / (name + "-" + tag + tail);
}

FileFingerprint fingerprint(const fs::path& path) {
  FileFingerprint f;
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return f;
  const auto bytes = slurp(path);
  if (!bytes) return f;
  f.exists = true;
  f.size = bytes->size();
  f.mtime_ns = static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1'000'000'000 + st.st_mtim.tv_nsec;
  std::uint64_t h = 14695981039346656037ULL;
  for (const unsigned char c : *bytes) h = (h ^ c) * 1099511628211ULL;
  f.hash = h;
  return f;
}

namespace {
std::string utc_stamp() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  ::gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y%m%d-%H%M%S", &tm);
  return buf;
}
}  // namespace

fs::path new_side_file_path(const fs::path& sidecar_path, const std::string& what) {
  const std::string tag = what + "-" + utc_stamp();
  fs::path p = side_file_path(sidecar_path, tag);
  for (int n = 2; fs::exists(p); ++n)
    p = side_file_path(sidecar_path, tag + "-" + std::to_string(n));
  return p;
}

Autosave::Autosave(fs::path sidecar_path, Target target)
    : path_(std::move(sidecar_path)), target_(target), known_(fingerprint(path_)) {}

void Autosave::divert_if_changed_on_disk() {
  if (diverted_ || target_ != Target::Sidecar) return;
  const FileFingerprint now = fingerprint(path_);
  // Gone since: nothing of anyone's to keep there; written again as usual.
  if (!now.exists || now == known_) return;
  // Another program wrote the sidecar: its version stays; this author's goes beside it.
  const fs::path original = path_;
  const fs::path side = new_side_file_path(original, "yours");
  // The recovery copy follows the file saved to (the old one is left for the crash case).
  diverted_ = side;
  original_ = original;
  path_ = side;
  known_ = FileFingerprint{};
  note_ = original.filename().string() +
          " was changed by another program: kept as it is; your version is saved as " +
          side.filename().string();
}

bool Autosave::write(const std::string& text) {
  divert_if_changed_on_disk();
  try {
    // The recovery copy first: if the sidecar write fails, the recovery copy still holds the edit.
    // The recovery copy's name is vdfx's own: a link planted there is refused, not followed.
    io::write_file_atomic(recovery_path(path_), text, io::OutputName::Generated);
    io::write_file_atomic(path_, text);
  } catch (const std::exception& e) {
    failing_ = true;
    error_ = e.what();
    status_ = std::string("autosave FAILED, retrying every ") +
              std::to_string(kRetryNs / 1'000'000'000) +
              " s (the edits are kept in memory): " + e.what();
    return false;
  }
  known_ = fingerprint(path_);
  failing_ = false;
  last_try_ns_.reset();
  return true;
}

bool Autosave::save(const io::Sidecar& sidecar) {
  if (!write(io::format_sidecar(sidecar))) return false;
  ++saves_;
  status_ = "saved " + path_.filename().string() + " (" + std::to_string(saves_) +
            (saves_ == 1 ? " change)" : " changes)");
  if (!note_.empty()) status_ += "; " + note_;
  return true;
}

bool Autosave::retry_due(std::int64_t t_ns) {
  if (!failing_) return false;
  if (!last_try_ns_) {
    last_try_ns_ = t_ns;
    return false;
  }
  if (t_ns - *last_try_ns_ < kRetryNs) return false;
  last_try_ns_ = t_ns;
  return true;
}

bool Autosave::finish(const io::Sidecar& sidecar) {
  // The final state on disk: written when the file does not hold it yet (a new sidecar, or an
  // autosave that failed); not a change of its own. A copy (read-only session) only when changed.
  const std::string text = io::format_sidecar(sidecar);
  if (target_ == Target::CopyWhenChanged && saves_ == 0 && !failing_) {
    status_ = "no changes (read-only: nothing saved)";
    return true;
  }
  divert_if_changed_on_disk();
  const auto on_disk = slurp(path_);
  if (on_disk != text) {
    if (!write(text)) {
      status_ = "saving FAILED: " + error_;
      return false;
    }
  }
  if (saves_ == 0)
    status_ = path_.filename().string() +
              (on_disk ? ": no changes" : ": new sidecar written (no keyframes yet)");
  if (!note_.empty() && status_.find(note_) == std::string::npos) status_ += "; " + note_;
  std::error_code ec;
  fs::remove(recovery_path(path_), ec);
  // After a change under the editor the sidecar's own recovery copy holds an older state of what
  // the side file holds now: it is not left to be offered as a crash's.
  if (diverted_) {
    std::error_code ignored;
    fs::remove(recovery_path(original_), ignored);
  }
  return !ec;
}

}  // namespace vdfx::app
