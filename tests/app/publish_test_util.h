/// @file
/// @brief Shared by the `vdfx publish` tests: the command line, what a folder holds, what a
/// publish may leave beside it, whether the web player's module was built.
#pragma once

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "export_test_util.h"

namespace vdfx::app::testing {

/// Every regular file under `dir`, relative, as a set.
inline std::set<std::string> listing(const std::filesystem::path& dir) {
  std::set<std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files.insert(e.path().lexically_relative(dir).generic_string());
  return files;
}

/// Names in `dir`'s parent that a publish may leave behind by mistake (its staging folder).
inline std::vector<std::string> leftovers(const std::filesystem::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(dir.parent_path()))
    if (e.path().filename().string().find(".publish-") != std::string::npos)
      out.push_back(e.path().filename().string());
  return out;
}

/// The web player's module is built beside the executable unless -DVDFX_BUILD_WASM=OFF (the
/// sanitizer build): without it publish is an internal error naming it, and the tests that need
/// a published folder are skipped.
inline bool module_built() {
  return std::filesystem::exists(std::filesystem::path(VDFX_BINARY).parent_path() / "wasm" /
                                 "vdfx_player.wasm");
}

inline constexpr const char* kNoModule =
    "built without the web player's module (VDFX_BUILD_WASM=OFF)";

inline std::string publish_args(const Fixture& f, const std::filesystem::path& out,
                                const std::string& extra = "") {
  return "publish " + f.clip.string() + " --sidecar " + f.sidecar.string() + " --out " +
         out.string() + " " + extra;
}

}  // namespace vdfx::app::testing
