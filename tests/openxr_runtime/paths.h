/// @file
/// @brief XrPath atoms: the path strings an instance has seen, and OpenXR's well-formedness rule.
#pragma once

#include <openxr/openxr.h>

#include <string>
#include <unordered_map>
#include <vector>

namespace vdfx::test_runtime {

class PathTable {
 public:
  /// The atom of a path, made on first use (XR_NULL_PATH stays 0).
  XrPath get(const std::string& path);
  /// The string of an atom, nullptr for one never made.
  const std::string* str(XrPath path) const;
  /// The string, or "" for an unknown atom (for messages and comparisons).
  std::string name(XrPath path) const;

 private:
  std::vector<std::string> strings_;
  std::unordered_map<std::string, XrPath> atoms_;
};

/// OpenXR's path rule (spec 6.1 "Path Atom Type"): starts with '/', components of lower-case
/// letters, digits, '-', '_' and '.' (not only dots), no empty component, no trailing '/'.
bool is_well_formed_path(const std::string& path);

}  // namespace vdfx::test_runtime
