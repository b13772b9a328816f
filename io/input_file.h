/// @file
/// @brief Opening what the user names as an input: a regular file (never a folder, device, named
/// pipe or socket, which would block or never end), within the size limit of its kind, read
/// whole. Each reader states its own limit (docs/reliability.md lists them all).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace vdfx::io {

/// Why `path` cannot be an input (links followed): "no such file", "is a folder, not KIND",
/// "is a named pipe (FIFO), not a regular file ...", "is 8.0 GiB, more than the 64 MiB a KIND may
/// be"; std::nullopt when it is a regular file of at most `max_bytes`. Never opens the file.
/// `kind` names what was expected ("a sidecar"); the message does not name the file.
std::optional<std::string> input_file_problem(const std::filesystem::path& path,
                                              std::uintmax_t max_bytes, std::string_view kind);

/// Throws io::InputError "PATH: problem" when input_file_problem() finds one.
void check_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes,
                      std::string_view kind);

/// The whole file, after the checks above; the file is opened without blocking and checked again
/// once open (it may have been replaced meanwhile), and a file that grows past `max_bytes` while
/// read is refused too. On failure returns std::nullopt with the reason (no file name) in `why`.
std::optional<std::string> try_read_input_file(const std::filesystem::path& path,
                                               std::uintmax_t max_bytes, std::string_view kind,
                                               std::string& why);

/// try_read_input_file() that throws io::InputError "PATH: why" instead.
std::string read_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes,
                            std::string_view kind);

/// "512 bytes", "64 KiB", "1.5 MiB", "8.0 GiB": sizes in messages.
std::string byte_size_text(std::uintmax_t bytes);

}  // namespace vdfx::io
