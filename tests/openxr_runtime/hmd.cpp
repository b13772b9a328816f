/// @file
/// @brief Reading the simulated headset from a vdfx HMD profile. The runtime is test code that
/// must load into any process (hello_xr too), so it reads the JSON itself instead of linking
/// vdfx's libraries; it checks what it uses and leaves the lens to vdfx's own loader.
#include "tests/openxr_runtime/hmd.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace vdfx::test_runtime {
namespace {

using nlohmann::json;
constexpr double kPi = 3.14159265358979323846;

std::filesystem::path profile_dir() {
  if (const char* env = std::getenv("VDFX_HMD_PROFILE_DIR"); env && *env) return env;
  return std::filesystem::path(VDFX_SOURCE_DIR) / "xr" / "headset" / "profiles";
}

[[noreturn]] void fail(const std::string& source, const std::string& pointer,
                       const std::string& what) {
  throw std::runtime_error(source + ": " + pointer + ": " + what);
}

double number(const json& parent, const char* key, const std::string& pointer,
              const std::string& source, double lo, double hi) {
  const std::string at = pointer + "/" + key;
  if (!parent.is_object() || !parent.contains(key)) fail(source, at, "missing");
  const json& v = parent.at(key);
  if (!v.is_number()) fail(source, at, "must be a number");
  const double d = v.get<double>();
  if (!std::isfinite(d) || d <= lo || d > hi) {
    std::ostringstream s;
    s << "must be in (" << lo << ", " << hi << "], is " << d;
    fail(source, at, s.str());
  }
  return d;
}

HmdEye read_eye(const json& eyes, const char* name, const std::string& source) {
  const std::string at = std::string("/eyes/") + name;
  if (!eyes.is_object() || !eyes.contains(name) || !eyes.at(name).is_object()) {
    fail(source, at, "missing or not an object");
  }
  const json& e = eyes.at(name);
  HmdEye eye;
  const json* res = e.contains("resolution") ? &e.at("resolution") : nullptr;
  if (!res || !res->is_array() || res->size() != 2 || !(*res)[0].is_number_integer() ||
      !(*res)[1].is_number_integer()) {
    fail(source, at + "/resolution", "must be [width, height], whole numbers");
  }
  eye.width = (*res)[0].get<int>();
  eye.height = (*res)[1].get<int>();
  if (eye.width < 1 || eye.width > 16384 || eye.height < 1 || eye.height > 16384) {
    fail(source, at + "/resolution", "each must be in [1, 16384]");
  }
  const std::string fov_at = at + "/fov_deg";
  if (!e.contains("fov_deg")) fail(source, fov_at, "missing");
  const json& fov = e.at("fov_deg");
  const double to_rad = kPi / 180.0;
  eye.angle_left = (number(fov, "angleLeft", fov_at, source, -90.0, 90.0)) * to_rad;
  eye.angle_right = (number(fov, "angleRight", fov_at, source, -90.0, 90.0)) * to_rad;
  eye.angle_up = (number(fov, "angleUp", fov_at, source, -90.0, 90.0)) * to_rad;
  eye.angle_down = (number(fov, "angleDown", fov_at, source, -90.0, 90.0)) * to_rad;
  if (eye.angle_left >= eye.angle_right) fail(source, fov_at, "angleLeft must be < angleRight");
  if (eye.angle_down >= eye.angle_up) fail(source, fov_at, "angleDown must be < angleUp");
  return eye;
}

}  // namespace

std::int64_t Hmd::period_ns() const {
  return std::llround(1e9 / refresh_hz);
}

Hmd load_hmd(const std::string& name_or_path) {
  std::filesystem::path path(name_or_path);
  const bool is_path = name_or_path.find('/') != std::string::npos || path.extension() == ".json" ||
                       std::filesystem::is_regular_file(path);
  if (!is_path) path = profile_dir() / (name_or_path + ".json");
  const std::string source = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in || !std::filesystem::is_regular_file(path)) {
    throw std::runtime_error("HMD profile '" + name_or_path + "': cannot read " + source +
                             (is_path ? ""
                                      : " (names are looked up in $VDFX_HMD_PROFILE_DIR, "
                                        "else the source tree's xr/headset/profiles)"));
  }
  std::stringstream text;
  text << in.rdbuf();
  json doc;
  try {
    doc = json::parse(text.str());
  } catch (const json::parse_error& e) {
    throw std::runtime_error(source + ": not JSON: " + e.what());
  }
  if (!doc.is_object() || doc.value("format", "") != "vdfx.hmd" || doc.value("version", 0) != 1) {
    fail(source, "/format", "not a vdfx.hmd profile of version 1");
  }
  Hmd hmd;
  hmd.source = source;
  hmd.name = doc.contains("name") && doc.at("name").is_string() ? doc.at("name").get<std::string>()
                                                                : path.stem().string();
  hmd.refresh_hz = number(doc, "refresh_hz", "", source, 0.0, 1000.0);
  hmd.ipd_m = number(doc, "ipd_m", "", source, 0.0, 0.2);
  if (!doc.contains("eyes")) fail(source, "/eyes", "missing");
  hmd.eyes[0] = read_eye(doc.at("eyes"), "left", source);
  hmd.eyes[1] = read_eye(doc.at("eyes"), "right", source);
  return hmd;
}

}  // namespace vdfx::test_runtime
