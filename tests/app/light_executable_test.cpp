/// @file
/// @brief The light/media split as a fact (docs/architecture.md, "Start-up"): the `vdfx`
/// executable's dynamic section names none of the media libraries, the light commands run from
/// the executable alone, and every other command needs the module beside it.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>
#include <string>

#include "app/cli/command_registry.h"
#include "tests/app/command_test_util.h"
#include "tests/support/test_paths.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;

/// The NEEDED entries of an ELF file's dynamic section, as `readelf -d` prints them.
std::set<std::string> needed_libraries(const fs::path& elf) {
  FILE* pipe = popen(("readelf -d --wide '" + elf.string() + "' 2>&1").c_str(), "r");
  std::string text;
  char buf[4096];
  while (pipe && fgets(buf, sizeof buf, pipe)) text += buf;
  if (pipe) pclose(pipe);
  std::set<std::string> needed;
  const std::regex entry(R"(\(NEEDED\)\s+Shared library: \[([^\]]+)\])");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), entry);
       it != std::sregex_iterator(); ++it)
    needed.insert((*it)[1]);
  return needed;
}

/// The libraries the light commands must never make the executable load at start-up.
const std::regex kMediaLibrary(
    R"(^lib(avcodec|avformat|avutil|swscale|GL|GLX|EGL|OpenGL|epoxy|glfw|opencv_videoio|opencv_imgcodecs|openxr_loader)\.so.*)");

TEST(LightExecutable, NeedsNoVideoImageOrGlLibrary) {
  const std::set<std::string> exe = needed_libraries(VDFX_BINARY);
  ASSERT_TRUE(exe.count("libc.so.6")) << "readelf found no NEEDED entries in " << VDFX_BINARY;
  for (const std::string& lib : exe)
    EXPECT_FALSE(std::regex_match(lib, kMediaLibrary)) << VDFX_BINARY << " needs " << lib;

  // The same check finds them in the module (so the names above are the ones the linker writes).
  const fs::path module = fs::path(VDFX_BINARY).parent_path() / "libvdfx_media.so";
  std::set<std::string> media_found;
  for (const std::string& lib : needed_libraries(module))
    if (std::regex_match(lib, kMediaLibrary)) media_found.insert(lib.substr(0, lib.find('.')));
  for (const char* lib : {"libavcodec", "libavformat", "libepoxy", "libglfw", "libopenxr_loader"})
    EXPECT_TRUE(media_found.count(lib)) << module << " does not need " << lib;
}

/// Runs a shell command line; its output (stdout and stderr) and exit code.
testing::CommandResult run_shell(const std::string& command) {
  testing::CommandResult r;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  char buf[4096];
  while (fgets(buf, sizeof buf, pipe)) r.output += buf;
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

TEST(LightExecutable, LightCommandsRunWithoutTheModuleAndMediaOnesAskForIt) {
  // A copy of the executable alone in a folder: no libvdfx_media.so beside it.
  const fs::path exe = testing::test_dir() / "vdfx";
  fs::copy_file(VDFX_BINARY, exe);
  int light = 0, media = 0;
  for (const Command& c : commands()) {
    const testing::CommandResult r = run_shell(exe.string() + " " + c.name + " --help");
    if (c.home == CommandHome::kLight) {
      ++light;
      EXPECT_EQ(r.exit_code, kExitOk) << c.name << ": " << r.output;
      EXPECT_NE(c.light_run, nullptr) << c.name;
    } else {
      ++media;
      EXPECT_EQ(r.exit_code, kExitInternal) << c.name << ": " << r.output;
      EXPECT_NE(r.output.find("cannot load the media module"), std::string::npos) << r.output;
      EXPECT_EQ(c.light_run, nullptr) << c.name;
    }
  }
  EXPECT_GE(light, 4);
  EXPECT_GE(media, 5);
  // `hmd` is light, but its OpenXR part (GL and the loader) asks for the module.
  const testing::CommandResult openxr = run_shell(exe.string() + " hmd openxr");
  EXPECT_EQ(openxr.exit_code, kExitInternal) << openxr.output;
  EXPECT_NE(openxr.output.find("cannot load the media module"), std::string::npos) << openxr.output;
  // A light command does its whole job alone.
  const std::string demo = std::string(VDFX_SOURCE_DIR) + "/app/demo/interior.vdfx.json";
  const testing::CommandResult v = run_shell(exe.string() + " validate " + demo);
  EXPECT_EQ(v.exit_code, kExitOk) << v.output;
}

}  // namespace
}  // namespace vdfx::app
