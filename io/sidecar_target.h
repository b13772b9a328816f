/// @file
/// @brief What a command that writes a sidecar (`suggest`, `replay`, `track`) starts from, and the
/// rule that keeps it from replacing an author's sidecar (docs/cli.md, "Writing a sidecar").
///
/// An existing --sidecar-out is somebody's work. Without --sidecar-in it is what the command adds
/// to; with a --sidecar-in that is another file it is replaced only when the user says --force;
/// --sidecar-in and --sidecar-out may name the same file (updated in place, atomically). While the
/// command runs it holds --sidecar-out's lock, so an editor opened meanwhile opens it read-only
/// and one already open makes the command stop before any work.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "io/file_lock.h"
#include "io/output_path.h"
#include "io/sidecar.h"

namespace vdfx::io {

/// A command's sidecar options.
struct SidecarOptions {
  std::optional<std::filesystem::path> in;  //!< --sidecar-in
  std::filesystem::path out;                //!< --sidecar-out
  bool force = false;                       //!< --force: an existing --sidecar-out may be replaced
};

/// Where the command starts, decided before any work.
struct SidecarTarget {
  std::optional<std::filesystem::path> base;  //!< the sidecar to start from; none: a new one
  bool adds_to_out = false;      //!< base is the existing --sidecar-out (no --sidecar-in given)
  bool replaces_out = false;     //!< --force: an existing --sidecar-out is replaced
  std::optional<FileLock> lock;  //!< --sidecar-out's lock, held until the result is written
};

/// Checks `o.out` (resolved as an output the user named, never one of `other_inputs`: the video,
/// a recording) and decides the base. Throws io::InputError naming the file and the options to
/// use when an existing --sidecar-out would be replaced without --force, and when another live
/// process (an editor) holds its lock. `command` names the lock's holder ("vdfx suggest").
SidecarTarget resolve_sidecar_target(const SidecarOptions& o,
                                     const std::vector<NamedInput>& other_inputs,
                                     const std::string& command);

/// The sidecar the command starts from: `target.base` read (with its problems listed), or
/// `fresh` when there is none.
Sidecar read_sidecar_base(const SidecarTarget& target, Sidecar fresh);

/// What the command says about the sidecar it wrote, or "" when there is nothing to add: "added
/// to the existing F (it had 2 effects, 14 keyframes)" or "replaced F (--force)".
std::string sidecar_target_note(const SidecarTarget& target, const std::filesystem::path& out,
                                const Sidecar& before);

/// Keyframes of every kind in `s` (stack effects, flares and grain).
std::size_t keyframe_count(const Sidecar& s);

}  // namespace vdfx::io
