#include "app/cli/cli_util.h"

#include <gtest/gtest.h>

namespace vdfx::app {
namespace {

TEST(CliUtil, ParsesViews) {
  const ViewSpec v = parse_view("36.5,-8,15");
  EXPECT_DOUBLE_EQ(v.direction.azimuth_deg, 36.5);
  EXPECT_DOUBLE_EQ(v.direction.altitude_deg, -8.0);
  EXPECT_DOUBLE_EQ(v.roll_deg, 15.0);
  EXPECT_DOUBLE_EQ(parse_view("-180,0").direction.azimuth_deg, 180.0);  // wraps into (-180, 180]
  EXPECT_DOUBLE_EQ(parse_view("370,0").direction.azimuth_deg, 10.0);
}

TEST(CliUtil, ParsesEvalPointsAndSizes) {
  const EvalPoint p = parse_eval_point("30,0,75");
  EXPECT_DOUBLE_EQ(p.direction.azimuth_deg, 30.0);
  EXPECT_EQ(p.frame, 75);
  const ImageSize s = parse_size("1280x720", "--size");
  EXPECT_EQ(s.width, 1280);
  EXPECT_EQ(s.height, 720);
}

const char* const kBadViews[] = {"", "1", "1,2,3,4", "a,b", "1,,2", "0,91", "nan,0", "1e999,0"};
const char* const kBadPoints[] = {"1,2", "1,2,-1", "1,2,1.5", "1,2,x", "0,-95,3"};
const char* const kBadSizes[] = {"0x10", "10", "10x", "x10", "10x10x10", "1.5x2", "99999x2"};

TEST(CliUtil, RejectsMalformedValues) {
  for (const char* t : kBadViews) EXPECT_THROW(parse_view(t), CLI::ValidationError) << t;
  for (const char* t : kBadPoints) EXPECT_THROW(parse_eval_point(t), CLI::ValidationError) << t;
  for (const char* t : kBadSizes)
    EXPECT_THROW(parse_size(t, "--window"), CLI::ValidationError) << t;
  try {
    parse_size("10x", "--bake");
    ADD_FAILURE() << "accepted 10x";
  } catch (const CLI::ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("--bake"), std::string::npos) << e.what();
  }
}

TEST(CliUtil, SizesStayWithinTheirDocumentedLimits) {
  // Issue 11, class 3: 16384x16384 used to be taken and allocated 8.5 GB (24 GB for --bake).
  EXPECT_EQ(parse_size("8192x8192").width, 8192);
  EXPECT_EQ(parse_size("16384x4096").width, 16384);
  EXPECT_EQ(parse_size("4096x2048", "--bake", kBakeSizeLimit).height, 2048);
  const struct {
    const char* text;
    const char* option;
    SizeLimit limit;
    const char* says;
  } rows[] = {
      {"16384x16384", "--size", kOutputSizeLimit,
       "268435456 pixels, more than the 67108864 allowed (8192x8192)"},
      {"16385x1", "--size", kOutputSizeLimit, "each side must be at most 16384"},
      {"100000x1", "--window", kOutputSizeLimit, "each side must be at most 16384"},
      {"16384x16384", "--bake", kBakeSizeLimit, "each side must be at most 4096"},
      {"4096x4096", "--bake", kBakeSizeLimit, "more than the 8388608 allowed (4096x2048)"},
  };
  for (const auto& row : rows) {
    try {
      parse_size(row.text, row.option, row.limit);
      ADD_FAILURE() << row.text << " accepted";
    } catch (const CLI::ValidationError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find(row.option), std::string::npos) << msg;
      EXPECT_NE(msg.find(row.says), std::string::npos) << msg;
    }
  }
}

TEST(CliUtil, NumericOptionsRefuseNanOverflowAndSayTheRangeShortly) {
  // Issue 11, classes 6 and 7: CLI11's checks let --fov nan through, read --frame 2^63 as
  // 2^63 - 1, and printed --frame -1's range with 309 digits.
  const struct {
    CLI::Validator check;
    std::string text;
    std::string says;  //!< "" when accepted
  } rows[] = {
      {finite_range(1, 179), "90", ""},
      {finite_range(1, 179), "nan", "'nan' is not a finite number"},
      {finite_range(1, 179), "inf", "'inf' is not a finite number"},
      {finite_range(1, 179), "1e999", "'1e999' is not a finite number"},
      {finite_range(1, 179), "0.5", "'0.5' is out of range [1, 179]"},
      {finite_range(1, 179), "90x", "'90x' is not a finite number"},
      {whole_range(0, INT64_MAX), "9223372036854775807", ""},
      {whole_range(0, INT64_MAX), "9223372036854775808",
       "is out of range [0, 9223372036854775807]"},
      {whole_range(0, INT64_MAX), "-1", "'-1' is out of range [0, 9223372036854775807]"},
      {whole_range(0, INT64_MAX), "1.5", "'1.5' is not a whole number"},
      {whole_range(0, INT64_MAX), "", "'' is not a whole number"},
  };
  for (auto row : rows) {
    std::string text = row.text;
    const std::string why = row.check(text);
    if (row.says.empty()) {
      EXPECT_EQ(why, "") << row.text;
    } else {
      EXPECT_NE(why.find(row.says), std::string::npos) << row.text << ": " << why;
      EXPECT_LT(why.size(), 120u) << why;
    }
  }
  // FRAME of --at is read as an integer, exactly.
  EXPECT_EQ(parse_eval_point("0,0,9007199254740993").frame, 9007199254740993);
  EXPECT_THROW(parse_eval_point("0,0,9223372036854775808"), CLI::ValidationError);
}

}  // namespace
}  // namespace vdfx::app
