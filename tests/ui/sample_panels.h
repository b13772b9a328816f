/// @file
/// @brief The demo panels of tests/support/demo_panels.h under the names the ui tests use.
#pragma once

#include "tests/support/demo_panels.h"

namespace vdfx::ui::test {

using demo::make_effect_panel;
using demo::make_timeline_panel;
using demo::synthetic_frame;
/// Shared fonts (loaded once per process).
inline std::shared_ptr<const FontSet> test_fonts() {
  return demo::demo_fonts();
}

}  // namespace vdfx::ui::test
