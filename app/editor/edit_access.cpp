/// @file
/// @brief open_for_editing: the sidecar's lock and what a second editor does.
#include "app/editor/edit_access.h"

#include <ostream>

#include "app/editor/autosave.h"
#include "io/input_error.h"

namespace vdfx::app {
namespace fs = std::filesystem;

EditAccessMode parse_edit_access(const std::string& value) {
  if (value == "write") return EditAccessMode::Write;
  if (value == "read-only") return EditAccessMode::ReadOnly;
  return EditAccessMode::Auto;
}

EditAccess open_for_editing(const fs::path& sidecar, EditAccessMode mode, std::ostream& log) {
  EditAccess a;
  a.save_to = sidecar;
  if (mode == EditAccessMode::ReadOnly) {
    a.save_to = new_side_file_path(sidecar, "copy");
    a.read_only_note =
        "opened with --access read-only; edits are saved to " + a.save_to.filename().string();
    log << "vdfx edit: " << sidecar.string() << " opened read-only; edits go to "
        << a.save_to.string() << " (created by the first change)\n";
    return a;
  }
  const fs::path dir = sidecar.parent_path().empty() ? fs::path(".") : sidecar.parent_path();
  std::error_code ec;
  // No folder, no file anyone can have open: the command reports what is missing (the video
  // first) as before, and a save there fails with its own message.
  if (!fs::is_directory(dir, ec)) return a;
  io::FileLock::Result r;
  try {
    r = io::FileLock::acquire(sidecar, "vdfx edit");
  } catch (const io::InputError& e) {
    // No lock can be made there (a read-only folder, say): nothing can be saved there either.
    if (mode == EditAccessMode::Write) throw;
    a.save_to = new_side_file_path(sidecar, "copy");
    a.read_only_note = "no lock could be made; edits are saved to " +
                       a.save_to.filename().string() + " if the folder allows";
    log << "vdfx edit: " << e.what() << ": opening it READ-ONLY\n";
    return a;
  }
  if (r.took_over)
    log << "vdfx edit: " << sidecar.string() << ": took over the lock left by "
        << r.took_over->describe() << ", which is no longer running\n";
  if (r.lock) {
    a.lock = std::move(r.lock);
    return a;
  }
  const io::LockOwner& owner = *r.held_by;
  const std::string where = sidecar.string() + " is open in " + owner.describe();
  if (mode == EditAccessMode::Write)
    throw io::InputError(where + " (lock " + io::lock_path(sidecar).string() +
                         "); --access write needs it to itself: close that editor, or open with "
                         "--access read-only (or remove the lock if no editor has it open)");
  a.save_to = new_side_file_path(sidecar, "copy");
  a.read_only_note =
      "open in " + owner.describe() + "; edits are saved to " + a.save_to.filename().string();
  log << "vdfx edit: " << where << ": opening it READ-ONLY; edits go to " << a.save_to.string()
      << " (created by the first change); --access write exits instead\n";
  return a;
}

}  // namespace vdfx::app
