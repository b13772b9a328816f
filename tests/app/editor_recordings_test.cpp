/// @file
/// @brief recordings/editor_*.vdrec.jsonl and demo.vdrec.jsonl match their generator
/// (VDFX_REGENERATE_RECORDINGS=1 rewrites them).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "editor_scripts.h"
#include "tests/support/test_paths.h"
#include "tests/test_files.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;

using test_files::slurp;

TEST(EditorRecordings, CommittedFilesMatchTheGenerator) {
  const fs::path dir = test_files::recordings_dir();
  const fs::path tmp = fs::path(VDFX_TEST_OUTPUT_DIR) / "editor" / "generated";
  fs::create_directories(tmp);
  const bool regenerate = std::getenv("VDFX_REGENERATE_RECORDINGS") != nullptr;
  for (const auto& s : test::editor_scripts()) {
    const fs::path out = (regenerate ? dir : tmp) / s.file_name;
    s.write(out);
    if (!regenerate) {
      EXPECT_EQ(slurp(out), slurp(dir / s.file_name))
          << s.file_name << " differs from its generator";
    }
  }
}

}  // namespace
}  // namespace vdfx::app
