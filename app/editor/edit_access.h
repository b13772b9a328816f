/// @file
/// @brief Who may write the sidecar `vdfx edit` opens: one editor per file (io/file_lock.h).
///
/// The first editor takes the sidecar's lock and saves to it. A second one is told at start who
/// has it open and, by default, opens read-only: its edits are saved to a copy beside it
/// (NAME-copy-TIME.vdfx.json, created by the first change), never to the sidecar; `--access
/// write` makes it exit 1 instead. A lock left by a process that is gone is taken over, with a
/// message naming that process (docs/editor.md, "One editor per sidecar").
#pragma once

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>

#include "io/file_lock.h"

namespace vdfx::app {

enum class EditAccessMode {
  Auto,      //!< write when free, else read-only (told)
  Write,     //!< write, or exit 1 when another editor has the file
  ReadOnly,  //!< never write the sidecar (edits go to a copy)
};

/// "auto", "write", "read-only" (the option's values).
EditAccessMode parse_edit_access(const std::string& value);

struct EditAccess {
  std::optional<io::FileLock> lock;  //!< held for the whole session (released on destruction)
  std::filesystem::path save_to;     //!< the sidecar, or (read-only) the copy
  std::string read_only_note;        //!< empty: writable; else why and where edits go
};

/// Takes the sidecar's lock (or not) per `mode`, telling `log` what happened ("vdfx edit: ...").
/// Throws io::InputError (exit 1) with Write when another live editor holds it or when the lock
/// cannot be created (a read-only folder); Auto then opens read-only, saying why.
EditAccess open_for_editing(const std::filesystem::path& sidecar, EditAccessMode mode,
                            std::ostream& log);

}  // namespace vdfx::app
