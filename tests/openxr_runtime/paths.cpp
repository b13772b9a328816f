/// @file
/// @brief XrPath atoms.
#include "tests/openxr_runtime/paths.h"

namespace vdfx::test_runtime {

XrPath PathTable::get(const std::string& path) {
  if (const auto it = atoms_.find(path); it != atoms_.end()) return it->second;
  strings_.push_back(path);
  const XrPath atom = strings_.size();  // 1-based: 0 is XR_NULL_PATH
  atoms_.emplace(path, atom);
  return atom;
}

const std::string* PathTable::str(XrPath path) const {
  if (path == XR_NULL_PATH || path > strings_.size()) return nullptr;
  return &strings_[path - 1];
}

std::string PathTable::name(XrPath path) const {
  const std::string* s = str(path);
  return s ? *s : std::string();
}

bool is_well_formed_path(const std::string& path) {
  if (path.size() < 2 || path.front() != '/' || path.back() == '/') return false;
  if (path.size() >= XR_MAX_PATH_LENGTH) return false;
  std::size_t start = 1;
  while (start <= path.size()) {
    std::size_t end = path.find('/', start);
    if (end == std::string::npos) end = path.size();
    const std::string part = path.substr(start, end - start);
    if (part.empty() || part.find_first_not_of(".") == std::string::npos) return false;
    for (const char c : part) {
      const bool ok =
          (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
      if (!ok) return false;
    }
    start = end + 1;
  }
  return true;
}

}  // namespace vdfx::test_runtime
