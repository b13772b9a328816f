/// @file
/// @brief Every GLSL source the two players share compiles for both targets (desktop GL 4.30 and
/// GLSL ES 3.00 for WebGL2), checked with the Khronos reference compiler, glslangValidator
/// (Debian's glslang-tools; its path is found by CMake). The GL tests compile the desktop sources
/// on Mesa as well; this test is what keeps the ES sources compiling without a browser.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "effects/effect_shaders.h"
#include "effects/flare_shaders.h"
#include "effects/glsl_common.h"
#include "effects/grain_shaders.h"
#include "effects/video_shaders.h"
#include "tests/support/test_paths.h"

namespace vdfx::effects {
namespace {

namespace fs = std::filesystem;

struct Source {
  std::string name;  //!< file name, its extension the stage (.vert, .frag) as glslang reads it
  std::string text;  //!< without a #version line
};

std::string stack_name(const StackShader& v) {
  static const std::array<const char*, 4> blur = {"none", "fused", "blurred", "levels"};
  return "stack_m" + std::to_string(v.mask) + "_" + blur[static_cast<size_t>(v.blur)] +
         (v.blur == StackShader::Blur::Levels ? std::to_string(v.levels) : "") +
         (v.per_pixel ? "_pixel" : "_view") + ".frag";
}

// The stack variants the GL side can ask for: no effect, all, each alone, with every blur mode
// (Levels only per pixel: its sigma comes from the grid), in view and per-pixel mode.
std::vector<Source> stack_sources() {
  std::vector<unsigned> masks = {0u, kAllEffectsMask};
  for (int i = 0; i < kEffectCount; ++i) masks.push_back(shader_bit(static_cast<EffectType>(i)));
  std::vector<Source> out;
  using B = StackShader::Blur;
  for (unsigned mask : masks) {
    for (bool per_pixel : {false, true}) {
      for (B blur : {B::None, B::FusedVertical, B::Blurred, B::Levels}) {
        if (blur == B::Levels && !per_pixel) continue;
        for (int levels : {1, kMaxBlurLevels}) {
          if (blur != B::Levels && levels != 1) continue;
          StackShader v;
          v.mask = mask;
          v.blur = blur;
          v.per_pixel = per_pixel;
          v.levels = blur == B::Levels ? levels : 0;
          out.push_back({stack_name(v), stack_fragment_source(v)});
        }
      }
    }
  }
  return out;
}

std::vector<Source> all_sources() {
  std::vector<Source> s = {
      {"fullscreen.vert", glsl::kFullscreenVertex},
      {"video_layer.frag", video_layer_fragment_source()},
      {"mip_level.frag", mip_level_fragment_source()},
      {"blur_1d.frag", blur_1d_fragment_source()},
      {"downsample.frag", downsample_fragment_source()},
      {"flare.vert", flare_vertex_source()},
      {"flare.frag", flare_fragment_source()},
      {"grain_styles.frag", grain_shader_fragment_source()},
      {"grain_particle.vert", grain_particle_vertex_source()},
      {"grain_particle.frag", grain_particle_fragment_source()},
  };
  for (Source& v : stack_sources()) s.push_back(std::move(v));
  return s;
}

// Writes each source with the target's prelude under `dir` and runs glslangValidator on them
// all; returns its exit status, `log` its output.
int validate(glsl::Target target, const fs::path& dir, std::string& log) {
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string cmd = std::string("\"") + VDFX_GLSLANG_VALIDATOR + "\"";
  for (const Source& s : all_sources()) {
    std::ofstream(dir / s.name) << glsl::prelude(target) << s.text;
    cmd += " \"" + (dir / s.name).string() + "\"";
  }
  cmd += " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return -1;
  std::array<char, 4096> buf{};
  size_t n = 0;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) log.append(buf.data(), n);
  return pclose(p);
}

class GlslTargets : public ::testing::TestWithParam<glsl::Target> {};

TEST_P(GlslTargets, EverySharedSourceCompiles) {
  ASSERT_TRUE(fs::exists(VDFX_GLSLANG_VALIDATOR))
      << "glslangValidator not found (" << VDFX_GLSLANG_VALIDATOR
      << "): install glslang-tools (.ci/deps.sh) and configure again";
  const bool es = GetParam() == glsl::Target::Es300;
  std::string log;
  const int rc =
      validate(GetParam(), fs::path(VDFX_TEST_OUTPUT_DIR) / (es ? "glsl_es300" : "glsl_430"), log);
  EXPECT_EQ(rc, 0) << log;
  // glslang names every file it reads; a run that read none would pass vacuously.
  EXPECT_NE(log.find("grain_styles.frag"), std::string::npos) << log;
}

// The ES prelude really selects ES: a desktop-only construct outside `#ifdef GL_ES` (here
// dual-source outputs, which WebGL2 lacks) fails there and compiles on the desktop.
TEST(GlslTargets, EsPreludeRejectsDesktopOnlyGlsl) {
  const fs::path dir = fs::path(VDFX_TEST_OUTPUT_DIR) / "glsl_prelude";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string body =
      "layout(location = 0, index = 1) out vec4 f;\nvoid main() { f = vec4(1.0); }\n";
  for (glsl::Target t : {glsl::Target::Desktop, glsl::Target::Es300}) {
    const fs::path file = dir / (t == glsl::Target::Es300 ? "es.frag" : "desktop.frag");
    std::ofstream(file) << glsl::prelude(t) << body;
    const std::string cmd =
        std::string("\"") + VDFX_GLSLANG_VALIDATOR + "\" \"" + file.string() + "\" >/dev/null 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()) == 0, t == glsl::Target::Desktop) << file;
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, GlslTargets,
                         ::testing::Values(glsl::Target::Desktop, glsl::Target::Es300),
                         [](const auto& info) {
                           return info.param == glsl::Target::Es300 ? std::string("Es300")
                                                                    : std::string("Desktop");
                         });

}  // namespace
}  // namespace vdfx::effects
