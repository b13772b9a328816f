/// @file
/// @brief Shader errors name the shader and quote the line; a missing display is a clear error.
#include <gtest/gtest.h>

#include <cstdlib>

#include "gl_test_support.h"
#include "xr/render/gl_program.h"

namespace vdfx::xr {
namespace {

class GlProgramTest : public test::GlTest {};

TEST_F(GlProgramTest, CompileErrorNamesTheShaderAndQuotesTheLine) {
  const std::string bad =
      "out vec4 frag;\nvoid main() {\n  frag = vec4(undeclared_thing, 1.0);\n}\n";
  try {
    GlProgram::build("broken_pass", fullscreen_vertex_source(), bad);
    FAIL() << "a broken shader compiled";
  } catch (const GlError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("broken_pass.frag line 3"), std::string::npos) << m;
    EXPECT_NE(m.find(">   frag = vec4(undeclared_thing, 1.0);"), std::string::npos) << m;
  }
}

const struct {
  const char* driver;
  const char* log;
} kLogs[] = {
    {"mesa", "0:2(7): error: syntax error"},
    {"nvidia", "0(2) : error C0000: syntax error"},
    {"khronos", "ERROR: 0:2: 'x' : syntax error"},
};

TEST(GlProgramLog, AnnotatesEachDriversLineFormat) {
  for (const auto& row : kLogs) {
    const std::string a = annotate_shader_log("s.frag", "line one\nline two\n", row.log);
    EXPECT_NE(a.find("s.frag line 2: "), std::string::npos) << row.driver << ": " << a;
    EXPECT_NE(a.find("  > line two"), std::string::npos) << row.driver << ": " << a;
  }
}

TEST(GlContextNoDisplay, FailsWithAClearMessage) {
  const char* saved = std::getenv("DISPLAY");
  const std::string keep = saved ? saved : "";
  unsetenv("DISPLAY");
  unsetenv("WAYLAND_DISPLAY");
  try {
    GlContext::create();
    ADD_FAILURE() << "a context without a display";
  } catch (const GlError& e) {
    EXPECT_NE(std::string(e.what()).find("xvfb-run -a"), std::string::npos) << e.what();
  }
  if (saved) setenv("DISPLAY", keep.c_str(), 1);
}

}  // namespace
}  // namespace vdfx::xr
