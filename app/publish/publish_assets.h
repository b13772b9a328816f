/// @file
/// @brief The page's files: where publish finds them (the page's sources in the checkout, the
/// WebAssembly module beside the executable), the GLSL written from effects/' own strings, the
/// manifest (player.json) the page starts from.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/publish/publish_request.h"
#include "app/publish/publish_video.h"
#include "io/sidecar.h"

namespace vdfx::app {

struct PageAssets {
  std::filesystem::path page_dir;  //!< index.html, player.js, ... (app/publish/page/)
  std::filesystem::path wasm_dir;  //!< vdfx_player.js and vdfx_player.wasm
};

/// The page's sources and the module; std::runtime_error (an internal error, exit 3) naming
/// what is missing (a build without the module: -DVDFX_BUILD_WASM=OFF).
PageAssets find_page_assets();

/// What the page starts from: player.json's object and the title.
struct PageSettings {
  nlohmann::ordered_json manifest;
  std::string title;
};
PageSettings page_settings(const PublishRequest& request, const io::Sidecar& sidecar,
                           const PublishedVideo& video, const std::string& codec);

/// Writes index.html (the title filled in), the player's scripts, the module, shaders/ (the
/// GLSL ES 3.00 sources) and player.json into `dir` (lights.json is run_publish's).
void write_page(const PageAssets& assets, const std::filesystem::path& dir,
                const PageSettings& settings);

/// The sidecar's effects the page does not draw: its volumetric grains ("grain #2 (free_cloud)").
std::vector<std::string> left_out_of(const io::Sidecar& sidecar);

/// Every file under `dir`, relative, sorted.
std::vector<std::string> folder_listing(const std::filesystem::path& dir);

/// The whole file; io::InputError naming it when it cannot be read.
std::string read_asset_text(const std::filesystem::path& path);
/// Copies the regular file `from` into the new file `to` (io::InputError naming both when it
/// fails: a full disk, say; naming `from` when it is not a regular file, which is never opened
/// to wait on: a named pipe, a device).
void copy_file_checked(const std::filesystem::path& from, const std::filesystem::path& to);
/// Writes `text` to a new file (io::InputError naming it on failure).
void write_text_file(const std::filesystem::path& path, const std::string& text);

}  // namespace vdfx::app
