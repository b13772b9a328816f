/// @file
/// @brief HMD profiles: the bundled files load and are sound; bad files are rejected with the
/// file, the JSON pointer and the reason.
#include "xr/headset/hmd_profile.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/input_error.h"
#include "tests/support/test_paths.h"

namespace vdfx::xr {
namespace {

using nlohmann::json;

TEST(HmdProfile, ListsTheBundledProfiles) {
  const auto names = list_hmd_profiles();
  for (const char* want : {"cardboard-v1", "generic90", "offcentre"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), want), names.end()) << want;
  }
}

TEST(HmdProfile, EveryBundledProfileLoadsAndInvertsOverItsPanel) {
  for (const auto& name : list_hmd_profiles()) {
    SCOPED_TRACE(name);
    const HmdProfile p = load_hmd_profile(name);
    EXPECT_EQ(p.name, name);
    for (const Eye e : kEyes) {
      const effects::EyeLens eye = p.eye_lens(e);
      // Forward and inverse agree over the whole panel, out to its farthest corner.
      const double corner =
          std::max({eye.pixel_to_tan({0, 0}).norm(), eye.pixel_to_tan({1.0 * eye.width, 0}).norm(),
                    eye.pixel_to_tan({0, 1.0 * eye.height}).norm(),
                    eye.pixel_to_tan({1.0 * eye.width, 1.0 * eye.height}).norm()});
      const double r_top = corner / p.lens.radius;
      ASSERT_LT(r_top, eye.lens.max_undistorted_radius());
      for (int k = 0; k <= 500; ++k) {
        const double r_u = r_top * k / 500.0;
        const effects::InverseResult inv = eye.lens.inverse_newton(eye.lens.forward(r_u));
        ASSERT_TRUE(inv.valid);
        EXPECT_NEAR(inv.r_u, r_u, 1e-6);
      }
      // Every panel corner has a valid source for every channel.
      for (const Eigen::Vector2d& px :
           {Eigen::Vector2d(0.5, 0.5), Eigen::Vector2d(eye.width - 0.5, eye.height - 0.5)}) {
        const effects::ChannelSamples s = effects::panel_source_uv(eye, px, true);
        for (int c = 0; c < 3; ++c) EXPECT_TRUE(s.valid[c]);
      }
    }
  }
}

TEST(HmdProfile, BundledValuesAreTheDocumentedOnes) {
  const HmdProfile cb = load_hmd_profile("cardboard-v1");
  EXPECT_DOUBLE_EQ(cb.lens.c1, 0.441);
  EXPECT_DOUBLE_EQ(cb.lens.c2, 0.156);
  const HmdProfile g = load_hmd_profile("generic90");
  EXPECT_EQ(g.eye(Eye::Left).width, 1440);
  EXPECT_EQ(g.eye(Eye::Left).height, 1600);
  EXPECT_DOUBLE_EQ(g.refresh_hz, 90.0);
  // offcentre: mirrored eyes with the optical centre far from the viewport centre.
  const HmdProfile o = load_hmd_profile("offcentre");
  EXPECT_DOUBLE_EQ(o.eye(Eye::Left).fov.angle_left, -o.eye(Eye::Right).fov.angle_right);
  EXPECT_DOUBLE_EQ(o.eye(Eye::Left).fov.angle_right, -o.eye(Eye::Right).fov.angle_left);
  EXPECT_GT(std::abs(o.eye(Eye::Left).lens_centre[0] - 0.5), 0.2);
}

TEST(HmdProfile, LoadsByPathAndFromTheOverrideDirectory) {
  const std::filesystem::path src = hmd_profile_dir() / "offcentre.json";
  EXPECT_EQ(load_hmd_profile(src.string()).name, "offcentre");
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "vdfx_hmd_profile_test_dir";
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(src, dir / "mine.json",
                             std::filesystem::copy_options::overwrite_existing);
  ::setenv("VDFX_HMD_PROFILE_DIR", dir.c_str(), 1);
  EXPECT_EQ(list_hmd_profiles(), std::vector<std::string>{"mine"});
  EXPECT_EQ(load_hmd_profile("mine").name, "offcentre");
  EXPECT_THROW(load_hmd_profile("generic90"), io::InputError);
  ::unsetenv("VDFX_HMD_PROFILE_DIR");
  std::filesystem::remove_all(dir);
  EXPECT_EQ(load_hmd_profile("generic90").name, "generic90");
}

TEST(HmdProfile, UnknownNameListsTheKnownOnes) {
  try {
    load_hmd_profile("no-such-headset");
    FAIL() << "expected InputError";
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("generic90"), std::string::npos) << e.what();
  }
}

json generic90_doc() {
  std::ifstream in(hmd_profile_dir() / "generic90.json");
  return json::parse(in);
}

/// One broken field per row: where it is (JSON pointer), what to put there (or remove), and
/// what the message must say.
const struct {
  const char* pointer;
  json value;  //!< null: remove the field
  const char* expect;
} kBadFields[] = {
    {"/ipd_m", nullptr, "/ipd_m: missing"},
    {"/eyes/right", nullptr, "/eyes/right: missing"},
    {"/eyes/left/resolution/0", -1440, "/eyes/left/resolution/0: must be an integer"},
    {"/eyes/left/resolution/1", 16.5, "/eyes/left/resolution/1: must be an integer"},
    {"/eyes/left/resolution", json::array({1440}), "/eyes/left/resolution: must be an array"},
    {"/eyes/left/fov_deg/angleLeft", -95.0, "/eyes/left/fov_deg/angleLeft: must be in (-90, 90)"},
    {"/eyes/right/fov_deg/angleUp", 90.0, "/eyes/right/fov_deg/angleUp: must be in (-90, 90)"},
    {"/eyes/left/fov_deg/angleRight", -60.0,
     "/eyes/left/fov_deg: angleLeft must be less than angleRight"},
    {"/refresh_hz", "90", "/refresh_hz: must be a number"},
    {"/refresh_hz", 0.0, "/refresh_hz: must be in (0, 1000]"},
    {"/distortion/c1", std::nan(""), "/distortion/c1: must be finite"},
    {"/distortion/radius", -1.0, "/distortion/radius: must be in (0, 100]"},
    {"/distortion/lca_scale/2", 0.0, "/distortion/lca_scale/2: must be in [0.5, 2]"},
    {"/extra", 1, "/extra: unknown key"},
    {"/eyes/left/lens", 1, "/eyes/left/lens: unknown key"},
    {"/format", "vdfx.sidecar", "/format: must be \"vdfx.hmd\""},
    {"/version", 2, "/version: unsupported version 2"},
    {"/eyes/left/lens_centre/0", 0.5, "/eyes/left/lens_centre: disagrees with fov_deg"},
    {"/distortion/c1", -0.6, "/distortion: the distortion stops being monotonic"},
};

TEST(HmdProfile, RejectsBadFieldsSayingWhere) {
  for (const auto& row : kBadFields) {
    json doc = generic90_doc();
    const json::json_pointer ptr(row.pointer);
    if (row.value.is_null()) {
      doc[ptr.parent_pointer()].erase(ptr.back());
    } else {
      doc[ptr] = row.value;
    }
    if (std::string(row.pointer) == "/distortion/c1" && row.value == -0.6) {
      doc["/distortion/c2"_json_pointer] = 0.1;  // folds at r ~ 0.9, inside the FOV
    }
    try {
      parse_hmd_profile(doc, "test.json");
      ADD_FAILURE() << row.pointer << ": accepted";
    } catch (const io::InputError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find(std::string("test.json: ") + row.expect), std::string::npos)
          << row.pointer << " gave: " << msg;
    }
  }
}

TEST(HmdProfile, ReportsEveryProblemAtOnce) {
  json doc = generic90_doc();
  doc["/ipd_m"_json_pointer] = -1.0;
  doc["/eyes/right/resolution/1"_json_pointer] = 0;
  doc["/bogus"_json_pointer] = true;
  try {
    parse_hmd_profile(doc, "x.json");
    FAIL() << "accepted";
  } catch (const io::InputError& e) {
    const std::string msg = e.what();
    for (const char* part :
         {"x.json: /ipd_m", "x.json: /eyes/right/resolution/1", "x.json: /bogus"}) {
      EXPECT_NE(msg.find(part), std::string::npos) << msg;
    }
  }
}

TEST(HmdProfile, InvalidJsonNamesTheFile) {
  const std::filesystem::path f =
      std::filesystem::temp_directory_path() / "vdfx_hmd_profile_test_nan.json";
  std::ofstream(f) << R"({"format": "vdfx.hmd", "ipd_m": NaN})";
  try {
    load_hmd_profile(f.string());
    FAIL() << "accepted";
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find(f.string() + ": line 1, column 33: invalid JSON"),
              std::string::npos)
        << e.what();
  }
  std::filesystem::remove(f);
}

TEST(HmdProfile, TakesOnlyARegularFileWithinItsLimit) {
  // Issue 11, classes 2 and 6: a pipe would block the reader, a folder or /dev/zero made it
  // fail with an internal error or read without end.
  const std::filesystem::path dir =
      std::filesystem::path(VDFX_TEST_OUTPUT_DIR) / "hmd_profile_special";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "folder.json");
  ASSERT_EQ(::mkfifo((dir / "pipe.json").c_str(), 0600), 0);
  std::ofstream(dir / "big.json") << "{";
  std::filesystem::resize_file(dir / "big.json", kMaxHmdProfileBytes + 1);
  const struct {
    std::filesystem::path path;
    const char* says;
  } rows[] = {
      {dir / "folder.json", "is a folder, not an HMD profile"},
      {dir / "pipe.json", "is a named pipe (FIFO)"},
      {"/dev/zero", "is a character device"},
      {dir / "big.json", "more than the 1 MiB an HMD profile may be"},
  };
  for (const auto& row : rows) {
    try {
      load_hmd_profile(row.path.string());
      ADD_FAILURE() << row.path << ": accepted";
    } catch (const io::InputError& e) {
      EXPECT_EQ(std::string(e.what()).find(row.path.string() + ": "), 0u) << e.what();
      EXPECT_NE(std::string(e.what()).find(row.says), std::string::npos) << e.what();
    }
  }
}

TEST(HmdProfile, DuplicateKeysAreRefusedAsInASidecar) {
  // Issue 11, class 8: nlohmann kept the last of two keys silently; the sidecar reader refused.
  const std::filesystem::path f =
      std::filesystem::path(VDFX_TEST_OUTPUT_DIR) / "hmd_duplicate.json";
  std::ifstream in(hmd_profile_dir() / "generic90.json");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.replace(text.find("\"name\""), 6, "\"ipd_m\": 0.05, \"name\"");
  std::ofstream(f) << text;
  try {
    load_hmd_profile(f.string());
    FAIL() << "accepted";
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find(f.string() + ": /ipd_m: duplicate key"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace vdfx::xr
