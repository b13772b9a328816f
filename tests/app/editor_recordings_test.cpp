/// @file
/// @brief recordings/editor_*.vdrec.jsonl and demo.vdrec.jsonl match their generator
/// (VDFX_REGENERATE_RECORDINGS=1 rewrites them).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "editor_scripts.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(EditorRecordings, CommittedFilesMatchTheGenerator) {
  const fs::path dir = fs::path(VDFX_TEST_DATA_DIR).parent_path().parent_path() / "recordings";
  const fs::path tmp = fs::path(VDFX_TEST_OUTPUT_DIR) / "editor" / "generated";
  fs::create_directories(tmp);
  const bool regenerate = std::getenv("VDFX_REGENERATE_RECORDINGS") != nullptr;
  for (const auto& s : test::editor_scripts()) {
    const fs::path out = (regenerate ? dir : tmp) / s.file_name;
    s.write(out);
    if (!regenerate) {
      EXPECT_EQ(slurp(out), slurp(dir / s.file_name)) << s.file_name << " differs from its generator";
    }
  }
}

}  // namespace
}  // namespace vdfx::app
