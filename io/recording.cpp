/// @file
/// @brief Recording reader (validating, line-numbered errors) and incremental writer.
#include "io/recording.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "io/excerpt.h"
#include "io/input_error.h"
#include "io/input_file.h"
#include "io/json_text.h"
#include "io/output_path.h"

namespace vdfx::io {

namespace {

using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

// [SECTION] Validation helpers: every failure names file, line and JSON pointer.

struct Where {
  const std::string& file;
  int line;
  [[noreturn]] void fail(const std::string& pointer, const std::string& what) const {
    std::ostringstream msg;
    msg << file << ":" << line << ": " << (pointer.empty() ? "" : pointer + ": ") << what;
    throw InputError(msg.str());
  }
};

const Json& field(const Where& w, const Json& obj, const std::string& ptr, const char* key) {
  auto it = obj.find(key);
  if (it == obj.end()) w.fail(ptr, std::string("missing field \"") + key + "\"");
  return *it;
}

void reject_unknown(const Where& w, const Json& obj, const std::string& ptr,
                    std::initializer_list<const char*> known) {
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    bool ok = false;
    for (const char* k : known) ok = ok || it.key() == k;
    if (!ok) w.fail(ptr, "unknown field \"" + excerpt(it.key()) + "\"");
  }
}

double number(const Where& w, const Json& v, const std::string& ptr, double lo, double hi) {
  if (!v.is_number()) w.fail(ptr, "expected a number, got " + std::string(v.type_name()));
  const double d = v.get<double>();
  if (!std::isfinite(d)) w.fail(ptr, "not a finite number");
  if (d < lo || d > hi) {
    std::ostringstream msg;
    msg << "value " << d << " outside [" << lo << ", " << hi << "]";
    w.fail(ptr, msg.str());
  }
  return d;
}

bool boolean(const Where& w, const Json& v, const std::string& ptr) {
  if (!v.is_boolean()) w.fail(ptr, "expected true or false, got " + std::string(v.type_name()));
  return v.get<bool>();
}

template <std::size_t N>
std::array<double, N> numbers(const Where& w, const Json& v, const std::string& ptr, double lo,
                              double hi) {
  if (!v.is_array() || v.size() != N) {
    w.fail(ptr, "expected an array of " + std::to_string(N) + " numbers");
  }
  std::array<double, N> out{};
  for (std::size_t i = 0; i < N; ++i)
    out[i] = number(w, v[i], ptr + "/" + std::to_string(i), lo, hi);
  return out;
}

constexpr double kHuge = 1e300;  // positions are only checked for being finite

RecordedPose parse_pose(const Where& w, const Json& v, const std::string& ptr) {
  if (!v.is_object()) w.fail(ptr, "expected an object with \"q\" and \"p\"");
  reject_unknown(w, v, ptr, {"q", "p"});
  RecordedPose pose;
  pose.q = numbers<4>(w, field(w, v, ptr, "q"), ptr + "/q", -kHuge, kHuge);
  pose.p = numbers<3>(w, field(w, v, ptr, "p"), ptr + "/p", -kHuge, kHuge);
  const double norm = std::sqrt(pose.q[0] * pose.q[0] + pose.q[1] * pose.q[1] +
                                pose.q[2] * pose.q[2] + pose.q[3] * pose.q[3]);
  if (std::abs(norm - 1.0) > kRecordingUnitTolerance) {
    std::ostringstream msg;
    msg << "quaternion norm " << norm << " is not 1 (tolerance " << kRecordingUnitTolerance << ")";
    w.fail(ptr + "/q", msg.str());
  }
  return pose;
}

RecordedHand parse_hand(const Where& w, const Json& v, const std::string& ptr, bool left) {
  if (!v.is_object()) w.fail(ptr, "expected an object");
  reject_unknown(w, v, ptr, {"aim", "trigger", "squeeze", "stick", "buttons"});
  RecordedHand h;
  h.aim = parse_pose(w, field(w, v, ptr, "aim"), ptr + "/aim");
  h.trigger = number(w, field(w, v, ptr, "trigger"), ptr + "/trigger", 0.0, 1.0);
  h.squeeze = number(w, field(w, v, ptr, "squeeze"), ptr + "/squeeze", 0.0, 1.0);
  h.stick = numbers<2>(w, field(w, v, ptr, "stick"), ptr + "/stick", -1.0, 1.0);
  const Json& b = field(w, v, ptr, "buttons");
  const std::string bp = ptr + "/buttons";
  if (!b.is_object()) w.fail(bp, "expected an object");
  if (left) {
    reject_unknown(w, b, bp, {"x", "y", "menu", "stick"});
    h.primary = boolean(w, field(w, b, bp, "x"), bp + "/x");
    h.secondary = boolean(w, field(w, b, bp, "y"), bp + "/y");
    h.menu = boolean(w, field(w, b, bp, "menu"), bp + "/menu");
  } else {
    reject_unknown(w, b, bp, {"a", "b", "stick"});
    h.primary = boolean(w, field(w, b, bp, "a"), bp + "/a");
    h.secondary = boolean(w, field(w, b, bp, "b"), bp + "/b");
  }
  h.stick_click = boolean(w, field(w, b, bp, "stick"), bp + "/stick");
  return h;
}

std::int64_t parse_time(const Where& w, const Json& obj) {
  const Json& t = field(w, obj, "", "t_ns");
  if (!t.is_number_integer()) w.fail("/t_ns", "expected an integer number of nanoseconds");
  // nlohmann keeps 2^63 and above as unsigned; read as int64 they wrapped to negative times that
  // a first sample had nothing to be compared with.
  if (t.is_number_unsigned() && t.get<std::uint64_t>() > static_cast<std::uint64_t>(INT64_MAX))
    w.fail("/t_ns", "time " + t.dump() + " is beyond the largest time, 2^63 - 1 ns (292 years)");
  return t.get<std::int64_t>();
}

RecordedHid parse_hid(const Where& w, const Json& obj, std::int64_t t) {
  reject_unknown(w, obj, "", {"t_ns", "hid"});
  const Json& h = obj["hid"];
  if (!h.is_object()) w.fail("/hid", "expected an object");
  RecordedHid out;
  out.t_ns = t;
  const Json& dev = field(w, h, "/hid", "device");
  if (!dev.is_string() || dev.get<std::string>().empty()) {
    w.fail("/hid/device", "expected a non-empty string");
  }
  out.device = dev.get<std::string>();
  const bool has_report = h.contains("report");
  const bool has_desc = h.contains("descriptor");
  if (has_report == has_desc) w.fail("/hid", "needs exactly one of \"report\" or \"descriptor\"");
  reject_unknown(w, h, "/hid", {"device", "report", "descriptor"});
  out.is_descriptor = has_desc;
  const char* key = has_desc ? "descriptor" : "report";
  const Json& hex = h[key];
  const std::string ptr = std::string("/hid/") + key;
  if (!hex.is_string()) w.fail(ptr, "expected a hex string");
  try {
    out.bytes = from_hex(hex.get<std::string>());
  } catch (const std::invalid_argument& e) {
    w.fail(ptr, e.what());
  }
  return out;
}

/// The next line into `line` (without its newline), read in small pieces and never past
/// kMaxRecordingLineBytes + 1 bytes; `terminated` says whether a newline ended it. False at the
/// end of the input.
bool read_line(std::istream& in, std::string& line, bool& terminated) {
  line.clear();
  char piece[4096];
  while (true) {
    in.getline(piece, sizeof piece);
    const auto got = static_cast<std::size_t>(in.gcount());
    if (in.bad()) throw InputError("read error");
    if (in.eof()) {  // the input ended before a newline
      line.append(piece, got);
      terminated = false;
      return !line.empty();
    }
    if (!in.fail()) {  // the newline ended the line (it is counted in gcount, not stored)
      line.append(piece, got - 1);
      terminated = true;
      return true;
    }
    line.append(piece, got);  // the piece filled up: the line goes on
    in.clear();
    if (line.size() > kMaxRecordingLineBytes) return true;  // the caller reports it
  }
}

RecordedSample parse_sample(const Where& w, const Json& obj, std::int64_t t) {
  reject_unknown(w, obj, "", {"t_ns", "head", "left", "right"});
  RecordedSample s;
  s.t_ns = t;
  s.head = parse_pose(w, field(w, obj, "", "head"), "/head");
  if (obj.contains("left")) s.left = parse_hand(w, obj["left"], "/left", true);
  if (obj.contains("right")) s.right = parse_hand(w, obj["right"], "/right", false);
  return s;
}

RecordingHeader parse_header(const Where& w, const Json& obj) {
  if (!obj.is_object()) w.fail("", "the first line must be the recording header object");
  const Json& format = field(w, obj, "", "format");
  if (format != "vdfx.recording") {
    w.fail("/format", "expected \"vdfx.recording\", got " + excerpt(format.dump()));
  }
  const Json& version = field(w, obj, "", "version");
  if (!version.is_number_integer()) w.fail("/version", "expected an integer");
  if (version.get<long long>() != 1) {
    w.fail("/version",
           "unsupported version " + excerpt(version.dump()) + " (this build reads version 1)");
  }
  reject_unknown(w, obj, "", {"format", "version", "hmd", "video", "note", "desktop"});
  RecordingHeader h;
  const Json& hmd = field(w, obj, "", "hmd");
  if (!hmd.is_string()) w.fail("/hmd", "expected a string");
  h.hmd = hmd.get<std::string>();
  const Json& video = field(w, obj, "", "video");
  if (!video.is_null() && !video.is_string()) w.fail("/video", "expected a string or null");
  if (video.is_string()) h.video = video.get<std::string>();
  const Json& note = field(w, obj, "", "note");
  if (!note.is_string()) w.fail("/note", "expected a string");
  h.note = note.get<std::string>();
  if (obj.contains("desktop")) {
    const Json& d = obj["desktop"];
    if (!d.is_object()) w.fail("/desktop", "expected an object");
    reject_unknown(w, d, "/desktop", {"width", "height", "hfov_deg"});
    RecordedDesktopView v;
    const auto size = [&](const char* key) {
      const Json& n = field(w, d, "/desktop", key);
      if (!n.is_number_integer() || n.get<long long>() < 1 || n.get<long long>() > 16384)
        w.fail(std::string("/desktop/") + key, "expected an integer in [1, 16384]");
      return static_cast<int>(n.get<long long>());
    };
    v.width = size("width");
    v.height = size("height");
    const Json& f = field(w, d, "/desktop", "hfov_deg");
    if (!f.is_number() || !(f.get<double>() > 0.0 && f.get<double>() < 180.0))
      w.fail("/desktop/hfov_deg", "expected a number in (0, 180)");
    v.hfov_deg = f.get<double>();
    h.desktop = v;
  }
  return h;
}

// [SECTION] Writing

OrderedJson pose_json(const RecordedPose& p) {
  return OrderedJson{{"q", OrderedJson::array({p.q[0], p.q[1], p.q[2], p.q[3]})},
                     {"p", OrderedJson::array({p.p[0], p.p[1], p.p[2]})}};
}

OrderedJson hand_json(const RecordedHand& h, bool left) {
  OrderedJson j;
  j["aim"] = pose_json(h.aim);
  j["trigger"] = h.trigger;
  j["squeeze"] = h.squeeze;
  j["stick"] = OrderedJson::array({h.stick[0], h.stick[1]});
  OrderedJson b;
  if (left) {
    b["x"] = h.primary;
    b["y"] = h.secondary;
    b["menu"] = h.menu;
  } else {
    b["a"] = h.primary;
    b["b"] = h.secondary;
  }
  b["stick"] = h.stick_click;
  j["buttons"] = b;
  return j;
}

}  // namespace

std::string to_hex(const std::vector<std::uint8_t>& bytes) {
  static const char* digits = "0123456789abcdef";
  std::string s;
  s.reserve(bytes.size() * 2);
  for (std::uint8_t b : bytes) {
    s.push_back(digits[b >> 4]);
    s.push_back(digits[b & 15]);
  }
  return s;
}

std::vector<std::uint8_t> from_hex(const std::string& hex) {
  if (hex.size() % 2 != 0) throw std::invalid_argument("odd number of hex digits");
  auto nibble = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    throw std::invalid_argument("not a hex digit: '" + excerpt(std::string(1, c)) + "'");
  };
  std::vector<std::uint8_t> out(hex.size() / 2);
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = static_cast<std::uint8_t>(nibble(hex[2 * i]) * 16 + nibble(hex[2 * i + 1]));
  }
  return out;
}

Recording parse_recording(std::istream& in, const std::string& name) {
  Recording rec;
  rec.name = name;
  int line_no = 0;
  bool have_header = false;
  std::int64_t last_t = 0;
  std::optional<std::int64_t> last_sample_t;
  bool any_line = false;
  // One line at a time, never more than the limit: a file without newlines (or /dev/zero) is
  // refused at its first line instead of being read whole.
  std::string line;
  bool terminated = false;
  while (read_line(in, line, terminated)) {
    if (line.size() > kMaxRecordingLineBytes)
      Where{name, line_no + 1}.fail("", "line longer than " +
                                            byte_size_text(kMaxRecordingLineBytes) +
                                            " (the limit of a recording line)");
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const Where w{name, line_no};
    if (line.empty()) w.fail("", "empty line");
    // As the sidecar's reader: NUL bytes, duplicate keys and overflowing numbers are errors, and
    // what the message quotes of the line is cut short.
    JsonText parsed = parse_json_text(line);
    if (!parsed.errors.empty()) {
      const JsonTextError& e = parsed.errors.front();
      const std::string what = e.line == 0 ? e.message
                                           : "bad JSON at column " + std::to_string(e.column) +
                                                 ": " + e.message.substr(e.message.find(": ") + 2);
      if (!terminated && have_header && e.code >= 100 && e.code < 200) {
        // A crash while writing leaves a partial last line; the rest is still good.
        rec.warnings.push_back(name + ":" + std::to_string(line_no) +
                               ": truncated last line ignored (" + what + ")");
        break;
      }
      w.fail(e.pointer, what);
    }
    const Json& obj = parsed.value;
    if (!have_header) {
      rec.header = parse_header(w, obj);
      have_header = true;
      continue;
    }
    if (!obj.is_object()) w.fail("", "expected a JSON object");
    const std::int64_t t = parse_time(w, obj);
    if (any_line && t < last_t) {
      w.fail("/t_ns", "time " + std::to_string(t) + " is before the previous line's " +
                          std::to_string(last_t) + " (timestamps must not decrease)");
    }
    RecordingLine out;
    out.line_number = line_no;
    if (obj.contains("hid")) {
      out.value = parse_hid(w, obj, t);
    } else {
      if (last_sample_t && t <= *last_sample_t) {
        w.fail("/t_ns", "sample time " + std::to_string(t) +
                            " is not after the previous sample's " +
                            std::to_string(*last_sample_t) + " (must strictly increase)");
      }
      out.value = parse_sample(w, obj, t);
      last_sample_t = t;
    }
    last_t = t;
    any_line = true;
    rec.lines.push_back(std::move(out));
  }
  if (!have_header) Where{name, 1}.fail("", "empty file: missing the recording header");
  return rec;
}

Recording read_recording(const std::filesystem::path& path) {
  check_input_file(path, kMaxRecordingBytes, "a recording");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot open the recording");
  return parse_recording(in, path.string());
}

std::string format_header_line(const RecordingHeader& header) {
  OrderedJson j;
  j["format"] = "vdfx.recording";
  j["version"] = 1;
  j["hmd"] = header.hmd;
  j["video"] = header.video ? OrderedJson(*header.video) : OrderedJson(nullptr);
  j["note"] = header.note;
  if (header.desktop)
    j["desktop"] = OrderedJson{{"width", header.desktop->width},
                               {"height", header.desktop->height},
                               {"hfov_deg", header.desktop->hfov_deg}};
  return j.dump();
}

std::string format_sample_line(const RecordedSample& s) {
  OrderedJson j;
  j["t_ns"] = s.t_ns;
  j["head"] = pose_json(s.head);
  if (s.left) j["left"] = hand_json(*s.left, true);
  if (s.right) j["right"] = hand_json(*s.right, false);
  return j.dump();
}

std::string format_hid_line(const RecordedHid& h) {
  OrderedJson j;
  j["t_ns"] = h.t_ns;
  j["hid"] = OrderedJson{{"device", h.device},
                         {h.is_descriptor ? "descriptor" : "report", to_hex(h.bytes)}};
  return j.dump();
}

RecordingWriter::RecordingWriter(const std::filesystem::path& path, const RecordingHeader& header)
    : path_(path) {
  // Through a link to its file; a device or pipe is refused, never replaced or blocked on.
  fd_ = ::open(resolve_output_path(path).c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd_ < 0)
    throw InputError(path.string() + ": cannot create the recording (" + std::strerror(errno) +
                     ")");
  write_line(format_header_line(header));
}

RecordingWriter::~RecordingWriter() {
  if (fd_ >= 0) ::close(fd_);
}

void RecordingWriter::write(const RecordedSample& sample) {
  write_line(format_sample_line(sample));
}
void RecordingWriter::write(const RecordedHid& hid) {
  write_line(format_hid_line(hid));
}

void RecordingWriter::write_line(const std::string& text) {
  if (fd_ < 0)
    throw InputError(path_.string() + ": the recording stopped after line " +
                     std::to_string(lines_) + " (an earlier write failed)");
  const std::string line = text + '\n';
  std::size_t done = 0;
  while (done < line.size()) {
    const ssize_t n = ::write(fd_, line.data() + done, line.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      // The user chose where to record, so a full disk is their input's problem (exit 1). The
      // part of this line that did get out is cut off again: a partial line followed by more
      // lines would make the whole file unreadable.
      const std::string why = n < 0 ? std::strerror(errno) : "nothing written";
      const bool cut = ::ftruncate(fd_, static_cast<off_t>(whole_)) == 0;
      ::close(fd_);
      fd_ = -1;
      throw InputError(path_.string() + ": cannot write the recording (" + why + "); its first " +
                       std::to_string(lines_) + " lines are kept" +
                       (cut ? "" : " (the last one may be cut short: the reader drops it)"));
    }
    done += static_cast<std::size_t>(n);
  }
  whole_ += line.size();
  ++lines_;
}

}  // namespace vdfx::io
