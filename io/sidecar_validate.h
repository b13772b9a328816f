/// @file
/// @brief Validating sidecar documents: every problem, each with the file, a JSON pointer and
/// what is wrong (contract: "A reader reports every problem ...").
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/sidecar.h"

namespace vdfx::io {

struct Problem {
  std::string file;     //!< as given by the caller
  std::string pointer;  //!< JSON pointer ("/effects/0/keyframes/3/frame"); "" is the whole document
  std::string message;  //!< what is wrong (syntax errors carry "line L, column C")
  /// "FILE: POINTER: MESSAGE" ("FILE: (document): MESSAGE" for the empty pointer).
  std::string to_string() const;
};

struct SidecarReport {
  std::vector<Problem> problems;
  std::optional<Sidecar> sidecar;  //!< set only when there are no problems
  bool ok() const { return problems.empty(); }
  /// Every problem, one per line.
  std::string to_string() const;
};

/// Checks a parsed document against format 1. Appends every problem found to `problems` and
/// returns what could be read (meaningful only when nothing was appended).
Sidecar parse_sidecar(const nlohmann::json& document, const std::string& file_for_messages,
                      std::vector<Problem>& problems);

/// Parses and checks sidecar text (syntax errors with line and column, duplicate keys too).
SidecarReport validate_sidecar_text(std::string_view text, const std::string& file_for_messages);

/// Reads and checks a sidecar file; an unreadable file is one problem, not an exception.
SidecarReport validate_sidecar_file(const std::filesystem::path& path);

}  // namespace vdfx::io
