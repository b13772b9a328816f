/// @file
/// @brief The deterministic generator of recordings/editor_*.vdrec.jsonl and demo.vdrec.jsonl:
/// scripted desktop events fed to the sim backend through the recording decorator, with the
/// cursor aimed at the editor's widgets by projecting their panel pixels into the sim window.
/// VDFX_REGENERATE_RECORDINGS=1 ./build/tests/vdfx_test_app --gtest_filter=EditorRecordings.*
/// rewrites them; otherwise the test checks the committed files still match.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "app/editor/editor_panels.h"

namespace vdfx::app::test {

inline constexpr std::int64_t kFrameNs = 33'333'333;
/// Frame count of the clip the all-widgets session was made for (tests write it: 30 fps).
inline constexpr int kClipFrames = 90;

struct EditorScript {
  std::string file_name;
  std::function<void(const std::filesystem::path&)> write;
};
const std::vector<EditorScript>& editor_scripts();

/// The desktop view the sessions are recorded in (the window's default size and FOV); their
/// recording headers say so, and replays lay the panels out for it.
inline constexpr DesktopViewport kScriptViewport{1280, 720, 100.0};

/// Window position (kScriptViewport) of a pixel of a panel in the desktop layout (head-locked,
/// so independent of where the head looks), for a video of `frames` frames.
glm::dvec2 cursor_for(const std::string& panel, glm::dvec2 pixel, int frames = 1);
/// Centre of a widget's rectangle, as a window position.
glm::dvec2 widget_cursor(const std::string& panel, const std::string& widget, int frames = 1);

}  // namespace vdfx::app::test
