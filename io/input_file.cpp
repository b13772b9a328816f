/// @file
/// @brief Input files: type and size checks, non-blocking whole-file reads.
#include "io/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "io/file_type.h"
#include "io/input_error.h"

namespace vdfx::io {

namespace {

std::optional<std::string> stat_problem(const struct stat& st, std::uintmax_t max_bytes,
                                        std::string_view kind) {
  if (S_ISDIR(st.st_mode)) return "is a folder, not " + std::string(kind);
  if (!S_ISREG(st.st_mode))
    return "is " + std::string(file_type_name(st.st_mode)) + ", not a regular file (vdfx reads " +
           std::string(kind) + " only from a regular file)";
  if (static_cast<std::uintmax_t>(st.st_size) > max_bytes) {
    std::string size = byte_size_text(static_cast<std::uintmax_t>(st.st_size));
    // "1.0 MiB, more than the 1 MiB" would read as a contradiction: give the bytes then.
    if (size.find('.') != std::string::npos &&
        size.substr(0, size.find('.')) == byte_size_text(max_bytes).substr(0, size.find('.')))
      size = std::to_string(st.st_size) + " bytes";
    return "is " + size + ", more than the " + byte_size_text(max_bytes) + " " + std::string(kind) +
           " may be";
  }
  return std::nullopt;
}

std::string open_problem(int err) {
  if (err == ENOENT) return "no such file";
  return std::string("cannot open for reading (") + std::strerror(err) + ")";
}

}  // namespace

std::string byte_size_text(std::uintmax_t bytes) {
  if (bytes < 1024) return std::to_string(bytes) + " bytes";
  const char* units[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  double v = static_cast<double>(bytes) / 1024.0;
  int u = 0;
  while (v >= 1024.0 && u < 5) {
    v /= 1024.0;
    ++u;
  }
  char buf[32];
  if (v == static_cast<double>(static_cast<std::uintmax_t>(v)))
    std::snprintf(buf, sizeof buf, "%.0f %s", v, units[u]);
  else
    std::snprintf(buf, sizeof buf, "%.1f %s", v, units[u]);
  return buf;
}

std::optional<std::string> input_file_problem(const std::filesystem::path& path,
                                              std::uintmax_t max_bytes, std::string_view kind) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return open_problem(errno);
  return stat_problem(st, max_bytes, kind);
}

void check_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes,
                      std::string_view kind) {
  if (auto why = input_file_problem(path, max_bytes, kind))
    throw InputError(path.string() + ": " + *why);
}

std::optional<std::string> try_read_input_file(const std::filesystem::path& path,
                                               std::uintmax_t max_bytes, std::string_view kind,
                                               std::string& why) {
  if (auto problem = input_file_problem(path, max_bytes, kind)) {
    why = *problem;
    return std::nullopt;
  }
  // O_NONBLOCK: should a pipe have taken the file's place since the check, open returns at
  // once instead of waiting for a writer; fstat below then refuses it.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    why = open_problem(errno);
    return std::nullopt;
  }
  struct stat st {};
  std::optional<std::string> problem = ::fstat(fd, &st) != 0
                                           ? std::optional<std::string>(std::strerror(errno))
                                           : stat_problem(st, max_bytes, kind);
  std::string bytes;
  if (!problem) {
    bytes.resize(static_cast<std::size_t>(st.st_size));
    std::size_t got = 0;
    while (!problem) {
      if (got == bytes.size()) {
        // The file may have grown since fstat: read on, up to the limit plus one byte.
        if (bytes.size() > max_bytes) {
          problem = "grew past the " + byte_size_text(max_bytes) + " " + std::string(kind) +
                    " may be while being read";
          break;
        }
        bytes.resize(std::min<std::uintmax_t>(max_bytes + 1, bytes.size() + 65536));
      }
      const ssize_t n = ::read(fd, bytes.data() + got, bytes.size() - got);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) problem = std::string("read error (") + std::strerror(errno) + ")";
      if (n <= 0) break;
      got += static_cast<std::size_t>(n);
    }
    bytes.resize(got);
  }
  ::close(fd);
  if (problem) {
    why = *problem;
    return std::nullopt;
  }
  return bytes;
}

std::string read_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes,
                            std::string_view kind) {
  std::string why;
  auto bytes = try_read_input_file(path, max_bytes, kind, why);
  if (!bytes) throw InputError(path.string() + ": " + why);
  return std::move(*bytes);
}

}  // namespace vdfx::io
