/// @file
/// @brief Issue 11, class 8 in the readers: what a message quotes of the user's text is cut
/// short (a 10 MB number made a 10 MB error line) with control bytes spelled out, and NUL bytes
/// are reported as such (nlohmann took one for the end of the input: the rest of the file was
/// ignored, or the message said "unexpected end of input").
#include <gtest/gtest.h>

#include <sstream>

#include "io/excerpt.h"
#include "io/input_error.h"
#include "io/json_text.h"
#include "io/recording.h"
#include "io/sidecar_validate.h"

namespace vdfx::io {
namespace {

TEST(Messages, ExcerptsAreShortAndSpellOutControlBytes) {
  EXPECT_EQ(excerpt("plain"), "plain");
  EXPECT_EQ(excerpt(std::string("a\0b\n", 4)), "a\\x00b\\x0a");
  EXPECT_EQ(excerpt(std::string(100, '7'), 10), "7777777777... (100 bytes)");
  // Never cut inside a UTF-8 sequence: "é" is two bytes.
  EXPECT_EQ(excerpt("aaaaaaaaa\xc3\xa9zz", 10), "aaaaaaaaa... (13 bytes)");
  EXPECT_EQ(excerpt_quoted("number overflow parsing '" + std::string(1000, '9') + "'", 5),
            "number overflow parsing '99999... (1000 bytes)'");
}

TEST(Messages, ANulByteIsNamedWhereItIs) {
  const std::string valid = R"({"format": "vdfx.sidecar"})";
  // After a complete document: the rest of the file used to be ignored silently.
  const JsonText after = parse_json_text(valid + std::string("\0garbage", 8));
  ASSERT_EQ(after.errors.size(), 1u);
  EXPECT_TRUE(after.value.is_discarded());
  EXPECT_EQ(after.errors[0].column, valid.size() + 1);
  EXPECT_NE(after.errors[0].message.find("NUL byte"), std::string::npos);
  // Inside it: was "unexpected end of input".
  const JsonText inside = parse_json_text(std::string("{\n \"a\":\0 1}", 11));
  ASSERT_EQ(inside.errors.size(), 1u);
  EXPECT_EQ(inside.errors[0].line, 2u);
  EXPECT_EQ(inside.errors[0].column, 6u);
  EXPECT_EQ(inside.errors[0].message.find("unexpected end"), std::string::npos);
}

TEST(Messages, SidecarMessagesQuoteAtMostAFewDozenBytes) {
  const std::string big_number = "1" + std::string(10'000'000, '0');
  const std::string huge_key(1'000'000, 'k');
  const struct {
    std::string text;
    const char* says;
  } rows[] = {
      {R"({"format": "vdfx.sidecar", "version": )" + big_number + "}", "number overflow"},
      {R"({"format": "vdfx.sidecar", "version": 1, ")" + huge_key + R"(": 1})", "unknown field"},
      {R"({"format": ")" + huge_key + R"(", "version": 1})", "expected \"vdfx.sidecar\""},
      {R"({"a": 1, "a": 2, ")" + huge_key + R"(": 1, ")" + huge_key + R"(": 2})", "duplicate key"},
  };
  for (const auto& row : rows) {
    const SidecarReport r = validate_sidecar_text(row.text, "s.vdfx.json");
    ASSERT_FALSE(r.ok());
    const std::string all = r.to_string();
    EXPECT_NE(all.find(row.says), std::string::npos) << all.substr(0, 300);
    for (const Problem& p : r.problems)
      EXPECT_LT(p.to_string().size(), 400u) << p.to_string().substr(0, 300);
  }
}

TEST(Messages, RecordingLinesAreReadLikeSidecars) {
  const std::string header =
      R"({"format":"vdfx.recording","version":1,"hmd":"sim","video":null,"note":""})";
  const struct {
    std::string line;
    const char* says;
  } rows[] = {
      {std::string(R"({"t_ns":1,"head":{"q":[1,0,0,0],"p":[0,0,0]}})") + std::string("\0x", 2),
       "r:2: bad JSON at column 46: a NUL byte"},
      {R"({"t_ns":1,"t_ns":2,"head":{"q":[1,0,0,0],"p":[0,0,0]}})", "r:2: /t_ns: duplicate key"},
      {R"({"t_ns":1,"head":{"q":[1,0,0,0],"p":[0,0,)" + std::string(100000, '9') + "e999]}}",
       "number overflow parsing '99999"},
  };
  for (const auto& row : rows) {
    std::istringstream in(header + "\n" + row.line + "\n");
    try {
      parse_recording(in, "r");
      ADD_FAILURE() << row.says;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(row.says), std::string::npos) << e.what();
      EXPECT_LT(std::string(e.what()).size(), 300u);
    }
  }
}

}  // namespace
}  // namespace vdfx::io
