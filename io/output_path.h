/// @file
/// @brief Where an output lands, and the checks that keep an output from destroying anything the
/// user did not mean to replace: an input of the same command, a device, a named pipe, a symbolic
/// link (docs/reliability.md, "Outputs").
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace vdfx::io {

/// Who chose an output's name, which decides what happens to a symbolic link there.
enum class OutputName {
  Given,      //!< the user named this file: a link is written through to the file it names
  Generated,  //!< vdfx made the name up inside a folder the user named (replay frames, autosave
              //!< copies): a link there is refused, since the user never named what it points to
};

/// The file a write to `path` replaces. With OutputName::Given symbolic links are followed to
/// the file they name (which need not exist yet), so the link itself is kept. Throws
/// io::InputError naming `path` when the file is a folder or not a regular file (a device, named
/// pipe or socket: vdfx writes regular files only), when the links loop or are nested deeper than
/// 40, or (OutputName::Generated) when it is a link.
std::filesystem::path resolve_output_path(const std::filesystem::path& path,
                                          OutputName name = OutputName::Given);

/// A file a command reads, with the option (or argument) that named it, for messages.
struct NamedInput {
  std::string role;  //!< "--sidecar", "INPUT", "the recording", ...
  std::filesystem::path path;
};

/// Throws io::InputError when `output` is the same file as one of `inputs`: same device and
/// inode, so hard links, symbolic links and different spellings of one name all count. An output
/// that does not exist yet, or an input that does not exist, matches nothing. `output_role`
/// names the output in the message ("--out", "--sidecar-out").
void check_output_is_not_input(const std::string& output_role, const std::filesystem::path& output,
                               const std::vector<NamedInput>& inputs);

}  // namespace vdfx::io
