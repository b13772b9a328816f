/// @file
/// @brief The editor's controls help is generated from the binding table: every binding and
/// pointer use is in it with its sim keys, a change of the table changes it, and docs/editor.md
/// shows it as printed.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "app/editor/bindings.h"
#include "tests/support/test_paths.h"
#include "xr/input/input_backend.h"

namespace vdfx::app {
namespace {

/// The text with its word wrapping undone (runs of spaces and newlines as one space).
std::string unwrapped(const std::string& text) {
  std::istringstream in(text);
  std::string word, out;
  while (in >> word) out += (out.empty() ? "" : " ") + word;
  return out;
}

TEST(EditorBindings, HelpHasEveryBindingAndPointerUse) {
  const std::string text = unwrapped(bindings_help_text());
  for (const Binding& b : kBindings)
    EXPECT_NE(text.find(unwrapped(std::string(b.does))), std::string::npos) << b.does;
  for (const PointerUse& u : kPointerUses)
    EXPECT_NE(text.find(unwrapped(std::string(u.does))), std::string::npos) << u.does;
  for (const DesktopUse& d : kDesktopUses)
    EXPECT_NE(text.find(unwrapped(std::string(d.input) + " " + std::string(d.does))),
              std::string::npos)
        << d.does;
  // Issue 23: Space places at the centre; on a panel only the mouse button presses it.
  EXPECT_NE(text.find("right trigger [left mouse button] on a panel: use it"), std::string::npos)
      << text;
  EXPECT_NE(text.find("drag left, the view turns right"), std::string::npos) << text;
  // The controls by their OpenXR names, with what presses them in the sim.
  for (const char* row :
       {"right squeeze [G] grab:", "right trigger [left mouse button, Space]", "right b [K]",
        "right a [J]", "left x [X] undo", "left y [Y] redo",
        "left squeeze [Q, Left Shift, Right Shift]", "right thumbstick click [L] deselect",
        "right thumbstick [Up arrow, Down arrow, Left arrow, Right arrow]"})
    EXPECT_NE(text.find(row), std::string::npos) << row << "\nin: " << text;
}

TEST(EditorBindings, DesktopRowsNameTheSimsInputs) {
  const std::string sim = xr::sim_bindings_text(xr::SimConfig{});
  for (const DesktopUse& d : kDesktopUses)
    EXPECT_NE(sim.find("  " + std::string(d.input) + " "), std::string::npos) << d.input << "\n"
                                                                              << sim;
}

TEST(EditorBindings, EveryRowIsWithinOneHundredColumns) {
  std::istringstream lines(bindings_help_text());
  int rows = 0;
  for (std::string line; std::getline(lines, line); ++rows) EXPECT_LE(line.size(), 100u) << line;
  EXPECT_GE(rows, static_cast<int>(kBindings.size() + kPointerUses.size()));
}

TEST(EditorBindings, DocsShowTheGeneratedText) {
  std::ifstream in(std::string(VDFX_SOURCE_DIR) + "/docs/editor.md");
  ASSERT_TRUE(in) << "docs/editor.md";
  const std::string doc{std::istreambuf_iterator<char>(in), {}};
  EXPECT_NE(doc.find("```\n" + bindings_help_text() + "```\n"), std::string::npos)
      << "docs/editor.md, \"Bindings\": paste this block:\n"
      << bindings_help_text();
}

}  // namespace
}  // namespace vdfx::app
