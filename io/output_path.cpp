/// @file
/// @brief resolve_output_path (symbolic links, file types) and check_output_is_not_input (device
/// and inode).
#include "io/output_path.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "io/file_type.h"
#include "io/input_error.h"

namespace vdfx::io {

namespace fs = std::filesystem;

namespace {

/// The same limit as the kernel's (MAXSYMLINKS), so a chain the kernel follows is followed here.
constexpr int kMaxLinks = 40;

[[noreturn]] void refuse(const fs::path& path, const std::string& why) {
  throw InputError("cannot write " + path.string() + ": " + why);
}

}  // namespace

fs::path resolve_output_path(const fs::path& path, OutputName name) {
  fs::path target = path;
  for (int links = 0;; ++links) {
    struct stat st {};
    if (::lstat(target.c_str(), &st) != 0) {
      // Missing: this is the name to create (a dangling link's target is created, as `cp`
      // would). Any other error is reported by the write itself, with its reason.
      return target;
    }
    if (S_ISREG(st.st_mode)) return target;
    if (!S_ISLNK(st.st_mode)) {
      std::string what = std::string("it is ") + file_type_name(st.st_mode);
      if (target != path) what += " (" + target.string() + ", where the link points)";
      refuse(path, what + "; vdfx writes regular files only");
    }
    if (name == OutputName::Generated)
      refuse(path,
             "it is a symbolic link, and vdfx chose this name itself: it writes through "
             "links only when they are named on the command line");
    if (links == kMaxLinks) refuse(path, "too many levels of symbolic links");
    std::error_code ec;
    const fs::path next = fs::read_symlink(target, ec);
    if (ec) refuse(path, "cannot read the symbolic link " + target.string() + ": " + ec.message());
    // A relative link is relative to the folder that holds the link, not to the working folder.
    target = next.is_absolute() ? next : target.parent_path() / next;
  }
}

void check_output_is_not_input(const std::string& output_role, const fs::path& output,
                               const std::vector<NamedInput>& inputs) {
  struct stat out {};
  if (::stat(output.c_str(), &out) != 0) return;  // not there yet: it cannot be an input
  for (const NamedInput& in : inputs) {
    struct stat st {};
    if (in.path.empty() || ::stat(in.path.c_str(), &st) != 0) continue;
    if (st.st_dev == out.st_dev && st.st_ino == out.st_ino) {
      const bool same_name = in.path.lexically_normal() == output.lexically_normal();
      throw InputError("refusing to write " + output_role + " " + output.string() + ": it is " +
                       (same_name ? "" : "the same file as ") + "the " + in.role + " input" +
                       (same_name ? "" : " " + in.path.string()) +
                       " (vdfx never overwrites its inputs; choose another output)");
    }
  }
}

}  // namespace vdfx::io
