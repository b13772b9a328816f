/// @file
/// @brief Loading and validating HMD profiles (format: docs/hmd-profiles.md).
#include "xr/headset/hmd_profile.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "effects/coords.h"
#include "io/excerpt.h"
#include "io/input_error.h"
#include "io/input_file.h"
#include "io/json_text.h"

namespace vdfx::xr {
namespace {

using nlohmann::json;

/// The lens centre in the file must match the one implied by the FOV to this much (viewport
/// units; the bundled files carry 5 decimals).
constexpr double kLensCentreTolerance = 5e-4;

/// Collects every problem of one file so the user sees them all at once.
class Checker {
 public:
  explicit Checker(std::string source) : source_(std::move(source)) {}

  void fail(const std::string& pointer, const std::string& what) {
    problems_.push_back(source_ + ": " + (pointer.empty() ? "/" : pointer) + ": " + what);
  }

  /// The object at `pointer`, checking for unknown and missing keys; nullptr when not an object.
  const json* object(const json& parent, const std::string& key, const std::string& pointer,
                     std::initializer_list<const char*> keys, bool required = true) {
    const json* j = child(parent, key, pointer, required);
    if (!j) return nullptr;
    if (!j->is_object()) {
      fail(pointer, "must be an object");
      return nullptr;
    }
    expect_keys(*j, pointer, keys);
    return j;
  }

  void expect_keys(const json& j, const std::string& pointer,
                   std::initializer_list<const char*> keys) {
    const std::set<std::string> known(keys.begin(), keys.end());
    for (const auto& [k, v] : j.items()) {
      if (!known.count(k))
        fail(pointer + "/" + io::excerpt(io::json_pointer_token(k)), "unknown key");
    }
  }

  const json* child(const json& parent, const std::string& key, const std::string& pointer,
                    bool required = true) {
    if (!parent.contains(key)) {
      if (required) fail(pointer, "missing");
      return nullptr;
    }
    return &parent.at(key);
  }

  /// A finite number in [lo, hi] (open ends when the flags say so).
  double number(const json& parent, const std::string& key, const std::string& pointer, double lo,
                double hi, bool open_lo = false, bool open_hi = false) {
    const json* j = child(parent, key, pointer);
    if (!j) return std::nan("");
    return number_value(*j, pointer, lo, hi, open_lo, open_hi);
  }

  double number_value(const json& j, const std::string& pointer, double lo, double hi,
                      bool open_lo = false, bool open_hi = false) {
    if (!j.is_number()) {
      fail(pointer, "must be a number");
      return std::nan("");
    }
    const double v = j.get<double>();
    const bool below = open_lo ? !(v > lo) : !(v >= lo);
    const bool above = open_hi ? !(v < hi) : !(v <= hi);
    if (!std::isfinite(v)) {
      fail(pointer, "must be finite");
    } else if (below || above) {
      std::ostringstream s;
      s << "must be in " << (open_lo ? "(" : "[") << lo << ", " << hi << (open_hi ? ")" : "]")
        << ", got " << v;
      fail(pointer, s.str());
    }
    return v;
  }

  /// A JSON array of exactly n entries, or nullptr.
  const json* array(const json& parent, const std::string& key, const std::string& pointer,
                    size_t n) {
    const json* j = child(parent, key, pointer);
    if (!j) return nullptr;
    if (!j->is_array() || j->size() != n) {
      fail(pointer, "must be an array of " + std::to_string(n) + " numbers");
      return nullptr;
    }
    return j;
  }

  std::string string(const json& parent, const std::string& key, const std::string& pointer,
                     bool required = true) {
    const json* j = child(parent, key, pointer, required);
    if (!j) return {};
    if (!j->is_string()) {
      fail(pointer, "must be a string");
      return {};
    }
    return j->get<std::string>();
  }

  void throw_if_any() const {
    if (problems_.empty()) return;
    std::string msg;
    for (const auto& p : problems_) msg += (msg.empty() ? "" : "\n") + p;
    throw io::InputError(msg);
  }

  bool ok() const { return problems_.empty(); }

 private:
  std::string source_;
  std::vector<std::string> problems_;
};

void parse_eye(Checker& check, const json& eyes, Eye e, EyeProfile& out) {
  const std::string ptr = std::string("/eyes/") + std::string(eye_name(e));
  const json* eye =
      check.object(eyes, std::string(eye_name(e)), ptr, {"resolution", "fov_deg", "lens_centre"});
  if (!eye) return;
  if (const json* res = check.array(*eye, "resolution", ptr + "/resolution", 2)) {
    int* dims[2] = {&out.width, &out.height};
    for (int k = 0; k < 2; ++k) {
      const json& v = (*res)[k];
      const std::string p = ptr + "/resolution/" + std::to_string(k);
      if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > 16384) {
        check.fail(p, "must be an integer in [1, 16384] (pixels)");
      } else {
        *dims[k] = v.get<int>();
      }
    }
  }
  const std::string fp = ptr + "/fov_deg";
  if (const json* fov =
          check.object(*eye, "fov_deg", fp, {"angleLeft", "angleRight", "angleUp", "angleDown"})) {
    FovDeg& f = out.fov;
    f.angle_left = check.number(*fov, "angleLeft", fp + "/angleLeft", -90, 90, true, true);
    f.angle_right = check.number(*fov, "angleRight", fp + "/angleRight", -90, 90, true, true);
    f.angle_up = check.number(*fov, "angleUp", fp + "/angleUp", -90, 90, true, true);
    f.angle_down = check.number(*fov, "angleDown", fp + "/angleDown", -90, 90, true, true);
    if (f.angle_left >= f.angle_right) check.fail(fp, "angleLeft must be less than angleRight");
    if (f.angle_down >= f.angle_up) check.fail(fp, "angleDown must be less than angleUp");
  }
  const std::string lp = ptr + "/lens_centre";
  if (const json* lc = check.array(*eye, "lens_centre", lp, 2)) {
    for (int k = 0; k < 2; ++k) {
      out.lens_centre[k] = check.number_value((*lc)[k], lp + "/" + std::to_string(k), -1, 2);
    }
  }
}

/// Cross-field checks once every field parsed: lens centre against FOV, folding inside the FOV.
void check_consistency(Checker& check, const HmdProfile& p) {
  const effects::LensModel lens(p.lens);
  for (const Eye e : kEyes) {
    const std::string ptr = std::string("/eyes/") + std::string(eye_name(e));
    const effects::EyeLens eye = p.eye_lens(e);
    const Eigen::Vector2d centre = eye.tan_to_uv({0.0, 0.0});
    const EyeProfile& ep = p.eye(e);
    if (std::abs(centre.x() - ep.lens_centre[0]) > kLensCentreTolerance ||
        std::abs(centre.y() - ep.lens_centre[1]) > kLensCentreTolerance) {
      std::ostringstream s;
      s.precision(6);
      s << "disagrees with fov_deg, which puts the optical centre at [" << centre.x() << ", "
        << centre.y() << "]";
      check.fail(ptr + "/lens_centre", s.str());
    }
    const effects::TanRect t = eye.fov;
    const double corner = std::hypot(std::max(-t.left, t.right), std::max(t.up, -t.down));
    const double r_corner = corner / p.lens.radius;
    if (r_corner >= lens.max_undistorted_radius()) {
      std::ostringstream s;
      s << "the distortion stops being monotonic at r = " << lens.max_undistorted_radius()
        << " (normalised), inside the " << eye_name(e)
        << " eye's field of view (corner at r = " << r_corner << "): the image would fold";
      check.fail("/distortion", s.str());
    }
  }
}

}  // namespace

std::string_view eye_name(Eye eye) {
  return eye == Eye::Left ? "left" : "right";
}

effects::TanRect FovDeg::tangents() const {
  const auto t = [](double deg) { return std::tan(deg * effects::kDegToRad); };
  return {t(angle_left), t(angle_right), t(angle_up), t(angle_down)};
}

effects::EyeLens HmdProfile::eye_lens(Eye e) const {
  effects::EyeLens out;
  out.width = eye(e).width;
  out.height = eye(e).height;
  out.fov = eye(e).fov.tangents();
  out.lens = effects::LensModel(lens);
  return out;
}

HmdProfile parse_hmd_profile(const json& doc, const std::string& source) {
  Checker check(source);
  HmdProfile p;
  p.source = source;
  if (!doc.is_object()) {
    check.fail("", "an HMD profile must be a JSON object");
    check.throw_if_any();
  }
  check.expect_keys(
      doc, "",
      {"format", "version", "name", "description", "refresh_hz", "ipd_m", "distortion", "eyes"});
  if (const std::string f = check.string(doc, "format", "/format"); !f.empty() && f != "vdfx.hmd") {
    check.fail("/format", "must be \"vdfx.hmd\", got \"" + io::excerpt(f) + "\"");
  }
  if (const json* v = check.child(doc, "version", "/version"); v && *v != 1) {
    check.fail("/version",
               "unsupported version " + io::excerpt(v->dump()) + " (this vdfx reads version 1)");
  }
  p.name = check.string(doc, "name", "/name");
  if (doc.contains("name") && doc["name"].is_string() && p.name.empty()) {
    check.fail("/name", "must not be empty");
  }
  p.description = check.string(doc, "description", "/description", false);
  p.refresh_hz = check.number(doc, "refresh_hz", "/refresh_hz", 0, 1000, true);
  p.ipd_m = check.number(doc, "ipd_m", "/ipd_m", 0, 0.2, true);
  if (const json* d =
          check.object(doc, "distortion", "/distortion", {"c1", "c2", "radius", "lca_scale"})) {
    p.lens.c1 = check.number(*d, "c1", "/distortion/c1", -10, 10);
    p.lens.c2 = check.number(*d, "c2", "/distortion/c2", -10, 10);
    p.lens.radius = check.number(*d, "radius", "/distortion/radius", 0, 100, true);
    if (const json* lca = check.array(*d, "lca_scale", "/distortion/lca_scale", 3)) {
      for (int c = 0; c < 3; ++c) {
        p.lens.lca_scale[c] =
            check.number_value((*lca)[c], "/distortion/lca_scale/" + std::to_string(c), 0.5, 2.0);
      }
    }
  }
  if (const json* eyes = check.object(doc, "eyes", "/eyes", {"left", "right"})) {
    for (const Eye e : kEyes) parse_eye(check, *eyes, e, p.eyes[static_cast<int>(e)]);
  }
  // Cross-field checks need every field sound first.
  if (check.ok()) check_consistency(check, p);
  check.throw_if_any();
  return p;
}

HmdProfile parse_hmd_profile_text(std::string_view text, const std::string& source) {
  io::JsonText parsed = io::parse_json_text(text);
  if (!parsed.errors.empty()) {
    std::string msg;
    for (const io::JsonTextError& e : parsed.errors)
      msg += (msg.empty() ? "" : "\n") + source + ": " + e.place() + ": " + e.message;
    throw io::InputError(msg);
  }
  return parse_hmd_profile(parsed.value, source);
}

std::filesystem::path hmd_profile_dir() {
  if (const char* env = std::getenv("VDFX_HMD_PROFILE_DIR"); env && *env) return env;
  return std::filesystem::path(VDFX_SOURCE_DIR) / "xr" / "headset" / "profiles";
}

std::vector<std::string> list_hmd_profiles() {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(hmd_profile_dir(), ec)) {
    if (entry.is_regular_file() && entry.path().extension() == ".json") {
      names.push_back(entry.path().stem().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

HmdProfile load_hmd_profile(std::string_view name_or_path) {
  const std::string arg(name_or_path);
  std::filesystem::path path(arg);
  const bool is_path = arg.find('/') != std::string::npos || path.extension() == ".json" ||
                       std::filesystem::is_regular_file(path);
  if (!is_path) {
    path = hmd_profile_dir() / (arg + ".json");
    if (!std::filesystem::is_regular_file(path)) {
      std::string known;
      for (const auto& n : list_hmd_profiles()) known += (known.empty() ? "" : ", ") + n;
      throw io::InputError("unknown HMD profile '" + io::excerpt(arg) + "' (in " +
                           hmd_profile_dir().string() + ": " + (known.empty() ? "none" : known) +
                           ")");
    }
  }
  // Bounded and non-blocking (a pipe or /dev/zero named as a profile is refused); the JSON is
  // parsed like a sidecar's: line and column of a syntax error, duplicate keys refused.
  return parse_hmd_profile_text(io::read_input_file(path, kMaxHmdProfileBytes, "an HMD profile"),
                                path.string());
}

}  // namespace vdfx::xr
