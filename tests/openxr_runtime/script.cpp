/// @file
/// @brief Reading a vdfx recording as the runtime's script. The checks follow the recording
/// reader of docs/input.md (a test compares both on the committed recordings), so a file vdfx
/// accepts plays here and a broken one is refused with its line.
#include "tests/openxr_runtime/script.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>

namespace vdfx::test_runtime {
namespace {

using nlohmann::json;

/// As vdfx's reader: quaternions this far from unit length are refused.
constexpr double kUnitTolerance = 1e-3;

class LineReader {
 public:
  LineReader(std::string path, int line) : path_(std::move(path)), line_(line) {}

  [[noreturn]] void fail(const std::string& pointer, const std::string& what) const {
    throw std::runtime_error(path_ + ":" + std::to_string(line_) + ": " +
                             (pointer.empty() ? "/" : pointer) + ": " + what);
  }

  const json& member(const json& obj, const char* key, const std::string& at) const {
    if (!obj.contains(key)) fail(at + "/" + key, "missing");
    return obj.at(key);
  }

  void only_keys(const json& obj, const std::string& at,
                 std::initializer_list<const char*> keys) const {
    if (!obj.is_object()) fail(at, "must be an object");
    const std::set<std::string> known(keys.begin(), keys.end());
    for (const auto& item : obj.items()) {
      if (!known.count(item.key())) fail(at + "/" + item.key(), "unknown field");
    }
  }

  double number(const json& obj, const char* key, const std::string& at, double lo,
                double hi) const {
    const json& v = member(obj, key, at);
    if (!v.is_number()) fail(at + "/" + key, "must be a number");
    const double d = v.get<double>();
    if (!std::isfinite(d) || d < lo || d > hi) {
      fail(at + "/" + key, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    }
    return d;
  }

  bool boolean(const json& obj, const char* key, const std::string& at) const {
    const json& v = member(obj, key, at);
    if (!v.is_boolean()) fail(at + "/" + key, "must be true or false");
    return v.get<bool>();
  }

  template <std::size_t N>
  std::array<double, N> numbers(const json& obj, const char* key, const std::string& at, double lo,
                                double hi) const {
    const json& v = member(obj, key, at);
    const std::string here = at + "/" + key;
    if (!v.is_array() || v.size() != N) fail(here, "must be an array of " + std::to_string(N));
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i) {
      if (!v[i].is_number()) fail(here + "/" + std::to_string(i), "must be a number");
      out[i] = v[i].get<double>();
      if (!std::isfinite(out[i]) || out[i] < lo || out[i] > hi) {
        fail(here + "/" + std::to_string(i), "out of range");
      }
    }
    return out;
  }

  ScriptPose pose(const json& obj, const std::string& at) const {
    only_keys(obj, at, {"q", "p"});
    ScriptPose p;
    p.q = numbers<4>(obj, "q", at, -2.0, 2.0);
    const double norm =
        std::sqrt(p.q[0] * p.q[0] + p.q[1] * p.q[1] + p.q[2] * p.q[2] + p.q[3] * p.q[3]);
    if (std::abs(norm - 1.0) > kUnitTolerance) fail(at + "/q", "not a unit quaternion");
    for (double& c : p.q) c /= norm;
    p.p = numbers<3>(obj, "p", at, -1e6, 1e6);
    return p;
  }

  ScriptHand hand(const json& obj, const std::string& at, bool left) const {
    only_keys(obj, at, {"aim", "trigger", "squeeze", "stick", "buttons"});
    ScriptHand h;
    h.aim = pose(member(obj, "aim", at), at + "/aim");
    h.trigger = number(obj, "trigger", at, 0.0, 1.0);
    h.squeeze = number(obj, "squeeze", at, 0.0, 1.0);
    h.stick = numbers<2>(obj, "stick", at, -1.0, 1.0);
    const json& b = member(obj, "buttons", at);
    const std::string bat = at + "/buttons";
    if (left) {
      only_keys(b, bat, {"x", "y", "menu", "stick"});
      h.primary = boolean(b, "x", bat);
      h.secondary = boolean(b, "y", bat);
      h.menu = boolean(b, "menu", bat);
    } else {
      only_keys(b, bat, {"a", "b", "stick"});
      h.primary = boolean(b, "a", bat);
      h.secondary = boolean(b, "b", bat);
    }
    h.stick_click = boolean(b, "stick", bat);
    return h;
  }

  std::int64_t time(const json& obj) const {
    const json& t = member(obj, "t_ns", "");
    if (!t.is_number_integer() ||
        (t.is_number_unsigned() &&
         t.get<std::uint64_t>() >
             static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))) {
      fail("/t_ns", "must be a whole number of nanoseconds below 2^63");
    }
    const std::int64_t v = t.get<std::int64_t>();
    if (v < 0) fail("/t_ns", "must not be negative");
    return v;
  }

 private:
  std::string path_;
  int line_;
};

void read_header(const std::string& text, const std::string& path, Script& script) {
  LineReader r(path, 1);
  json h;
  try {
    h = json::parse(text);
  } catch (const json::parse_error& e) {
    r.fail("", std::string("not JSON: ") + e.what());
  }
  r.only_keys(h, "", {"format", "version", "hmd", "video", "note", "desktop"});
  if (r.member(h, "format", "") != "vdfx.recording") r.fail("/format", "must be vdfx.recording");
  if (r.member(h, "version", "") != 1) r.fail("/version", "must be 1");
  const json& hmd = r.member(h, "hmd", "");
  if (!hmd.is_string()) r.fail("/hmd", "must be a string");
  script.hmd = hmd.get<std::string>();
  const json& video = r.member(h, "video", "");
  if (!video.is_string() && !video.is_null()) r.fail("/video", "must be a string or null");
  if (!r.member(h, "note", "").is_string()) r.fail("/note", "must be a string");
}

}  // namespace

const ScriptSample* Script::at(std::int64_t t_ns) const {
  const auto it =
      std::upper_bound(samples.begin(), samples.end(), t_ns,
                       [](std::int64_t t, const ScriptSample& s) { return t < s.t_ns; });
  return it == samples.begin() ? nullptr : &*(it - 1);
}

Script read_script(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open the script (VDFX_TEST_RUNTIME_SCRIPT)");
  Script script;
  script.path = path;
  std::vector<std::string> lines;
  std::string line;
  bool last_had_newline = true;
  while (std::getline(in, line)) {
    last_had_newline = !in.eof();
    lines.push_back(line);
  }
  if (lines.empty()) throw std::runtime_error(path + ":1: /: empty file, no header");
  read_header(lines[0], path, script);
  std::int64_t previous = -1;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const int number = static_cast<int>(i) + 1;
    LineReader r(path, number);
    if (lines[i].empty()) r.fail("", "blank line");
    json j;
    try {
      j = json::parse(lines[i]);
    } catch (const json::parse_error& e) {
      if (i + 1 == lines.size() && !last_had_newline) {
        script.warnings.push_back(path + ":" + std::to_string(number) +
                                  ": truncated last line dropped");
        break;
      }
      r.fail("", std::string("not JSON: ") + e.what());
    }
    if (!j.is_object()) r.fail("", "must be an object");
    const std::int64_t t = r.time(j);
    if (j.contains("hid")) {
      r.only_keys(j, "", {"t_ns", "hid"});
      if (t < previous) r.fail("/t_ns", "before the line above");
      previous = t;
      continue;
    }
    r.only_keys(j, "", {"t_ns", "head", "left", "right"});
    if (!script.samples.empty() && t <= script.samples.back().t_ns) {
      r.fail("/t_ns", "samples must be strictly increasing in time");
    }
    if (t < previous) r.fail("/t_ns", "before the line above");
    previous = t;
    ScriptSample s;
    s.t_ns = t;
    s.head = r.pose(r.member(j, "head", ""), "/head");
    if (j.contains("left")) s.left = r.hand(j.at("left"), "/left", true);
    if (j.contains("right")) s.right = r.hand(j.at("right"), "/right", false);
    script.samples.push_back(s);
  }
  if (script.samples.empty()) {
    throw std::runtime_error(path + ": no sample lines: the runtime needs at least one");
  }
  return script;
}

}  // namespace vdfx::test_runtime
