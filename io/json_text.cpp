/// @file
/// @brief parse_json_text: nlohmann's DOM builder behind a SAX shim that keeps positions and keys.
#include "io/json_text.h"

#include <set>
#include <utility>

#include "io/excerpt.h"

namespace vdfx::io {

std::string json_pointer_token(std::string_view key) {
  std::string out;
  for (const char c : key) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

std::string JsonTextError::place() const {
  if (line == 0) return pointer.empty() ? std::string("(document)") : pointer;
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

namespace {

using json = nlohmann::json;

/// 1-based line and column (in bytes) of byte offset `at`.
std::pair<std::size_t, std::size_t> line_and_column(std::string_view text, std::size_t at) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < at && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return {line, column};
}

/// Forwards every event to nlohmann's own DOM builder and tracks where it is, so that a
/// duplicate key can be named by pointer and a parse error by line and column.
class TrackingSax {
 public:
  TrackingSax(json& root, std::string_view text, std::vector<JsonTextError>& errors)
      : dom_(root, /*allow_exceptions=*/false), text_(text), errors_(errors) {}

  bool null() { return begin_value() && dom_.null(); }
  bool boolean(bool v) { return begin_value() && dom_.boolean(v); }
  bool number_integer(json::number_integer_t v) { return begin_value() && dom_.number_integer(v); }
  bool number_unsigned(json::number_unsigned_t v) {
    return begin_value() && dom_.number_unsigned(v);
  }
  bool number_float(json::number_float_t v, const std::string& s) {
    return begin_value() && dom_.number_float(v, s);
  }
  bool string(json::string_t& v) { return begin_value() && dom_.string(v); }
  bool binary(json::binary_t& v) { return begin_value() && dom_.binary(v); }
  bool start_object(std::size_t n) {
    begin_value();
    stack_.push_back({});
    return dom_.start_object(n);
  }
  bool key(json::string_t& k) {
    Level& top = stack_.back();
    top.key = k;
    if (!top.seen.insert(k).second)
      errors_.push_back(
          {0, 0, pointer(), "duplicate key \"" + excerpt(k) + "\" (a reader would drop one)"});
    return dom_.key(k);
  }
  bool end_object() {
    stack_.pop_back();
    return dom_.end_object();
  }
  bool start_array(std::size_t n) {
    begin_value();
    stack_.push_back({true, 0, {}, {}, 0});
    return dom_.start_array(n);
  }
  bool end_array() {
    stack_.pop_back();
    return dom_.end_array();
  }
  bool parse_error(std::size_t position, const std::string& token,
                   const nlohmann::detail::exception& ex) {
    // `position` counts the bytes read: the last one is where the syntax broke. A number that
    // overflows (error 406) is only known once read whole: name where it starts.
    std::size_t at = position > 0 ? position - 1 : 0;
    if (ex.id == 406) at = position > token.size() ? position - token.size() : 0;
    if (at > text_.size()) at = text_.size();
    const auto [line, column] = line_and_column(text_, at);
    std::string msg = ex.what();
    // Drop nlohmann's "[json.exception.parse_error.101] parse error at line 1, column 2: "
    // prefix: the place is given by our own line and column.
    if (const auto p = msg.find("]"); p != std::string::npos) msg = msg.substr(p + 1);
    if (const auto p = msg.find(": "); p != std::string::npos && msg.find("parse error") < p)
      msg = msg.substr(p + 2);
    while (!msg.empty() && msg.front() == ' ') msg.erase(msg.begin());
    // nlohmann quotes what it read: a 10 MB number made a 10 MB line.
    errors_.push_back({line, column, {}, "invalid JSON: " + excerpt_quoted(msg), ex.id});
    return false;
  }

 private:
  struct Level {
    bool array = false;
    std::int64_t next_index = 0;
    std::string key;
    std::set<std::string> seen;
    std::int64_t current = 0;
  };

  bool begin_value() {
    if (!stack_.empty() && stack_.back().array) stack_.back().current = stack_.back().next_index++;
    return true;
  }
  std::string pointer() const {
    std::string p;
    for (const Level& l : stack_)
      p += "/" + (l.array ? std::to_string(l.current) : excerpt(json_pointer_token(l.key)));
    return p;
  }

  nlohmann::detail::json_sax_dom_parser<json> dom_;
  std::string_view text_;
  std::vector<JsonTextError>& errors_;
  std::vector<Level> stack_;
};

}  // namespace

JsonText parse_json_text(std::string_view text) {
  JsonText out;
  // nlohmann takes a NUL byte for the end of the input: text after it was silently ignored, and
  // one inside the document read as "unexpected end of input". JSON text never holds one.
  if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos) {
    const auto [line, column] = line_and_column(text, nul);
    out.errors.push_back({line,
                          column,
                          {},
                          "invalid JSON: a NUL byte (\\x00); JSON text cannot "
                          "contain one (a binary or damaged file?)"});
    out.value = json(json::value_t::discarded);
    return out;
  }
  TrackingSax sax(out.value, text, out.errors);
  const bool ok = json::sax_parse(text.begin(), text.end(), &sax);
  if (!ok) out.value = json(json::value_t::discarded);
  return out;
}

}  // namespace vdfx::io
