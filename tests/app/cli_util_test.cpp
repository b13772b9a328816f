#include "app/cli_util.h"

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

}  // namespace
}  // namespace vdfx::app
