/// @file
/// @brief The one interpolation-settings check: its ranges, its messages, and that the RBF kernel
/// rejects exactly what it rejects.
#include "effects/interpolation_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "effects/rbf_kernel.h"

namespace vdfx::effects {
namespace {

InterpolationSettings with(double exponent, double time_scale) {
  InterpolationSettings s;
  s.exponent = exponent;
  s.time_scale = time_scale;
  return s;
}

TEST(InterpolationCheck, AcceptsTheContractsRanges) {
  for (double a : {1e-9, 1.0, 1.5, 2.0, 3.999}) EXPECT_FALSE(exponent_problem(a)) << a;
  for (double c : {1e-9, 1.0, 1000.0}) EXPECT_FALSE(time_scale_problem(c)) << c;
  EXPECT_FALSE(interpolation_problem(InterpolationSettings{}));
}

TEST(InterpolationCheck, RejectsTheEndsAndNaNWithTheRangeInTheMessage) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double a : {0.0, -1.0, 4.0, 5.0, nan}) {
    const auto p = exponent_problem(a);
    ASSERT_TRUE(p) << a;
    EXPECT_NE(p->find("exponent"), std::string::npos) << *p;
    EXPECT_NE(p->find("out of range (0, 4)"), std::string::npos) << *p;
  }
  for (double c : {0.0, -2.0, 1000.5, nan}) {
    const auto p = time_scale_problem(c);
    ASSERT_TRUE(p) << c;
    EXPECT_NE(p->find("out of range (0, 1000]"), std::string::npos) << *p;
  }
  EXPECT_EQ(*exponent_problem(5.0), "exponent 5 is out of range (0, 4)");
  EXPECT_EQ(*time_scale_problem(0.25e4), "time_scale 2500 is out of range (0, 1000]");
}

TEST(InterpolationCheck, ReachIsPositiveAndFiniteWhenSet) {
  for (double r : {1e-9, 0.5, 3600.0, 1e7}) EXPECT_FALSE(reach_problem(r)) << r;
  for (double r : {0.0, -1.0, 1.5e7, std::numeric_limits<double>::infinity(), std::nan("")})
    EXPECT_TRUE(reach_problem(r)) << r;
  EXPECT_EQ(*reach_problem(0.0), "reach_s 0 is out of range (0, 1e+07]");
  InterpolationSettings s;
  EXPECT_FALSE(interpolation_problem(s));  // absent: automatic
  s.reach_s = -3.0;
  EXPECT_EQ(*interpolation_problem(s), *reach_problem(-3.0));
  EXPECT_THROW(RbfKernel::from(s, 30.0), std::invalid_argument);
}

TEST(InterpolationCheck, NamesTheFirstBadSettingAndEnumsOutsideTheirValues) {
  EXPECT_EQ(*interpolation_problem(with(4.0, 0.0)), *exponent_problem(4.0));
  EXPECT_EQ(*interpolation_problem(with(1.0, 0.0)), *time_scale_problem(0.0));
  InterpolationSettings s;
  s.outside = static_cast<TimeOutside>(7);
  ASSERT_TRUE(interpolation_problem(s));
  EXPECT_NE(interpolation_problem(s)->find("outside_span"), std::string::npos);
  s = {};
  s.distance = static_cast<AngularDistance>(-1);
  ASSERT_TRUE(interpolation_problem(s));
  EXPECT_NE(interpolation_problem(s)->find("distance"), std::string::npos);
}

TEST(InterpolationCheck, TheKernelRejectsWhatTheCheckRejects) {
  for (const auto& s : {with(0.0, 1.0), with(4.0, 1.0), with(1.0, 0.0), with(1.0, 1001.0)}) {
    try {
      (void)RbfKernel::from(s, 30.0);
      ADD_FAILURE() << "accepted exponent " << s.exponent << ", time_scale " << s.time_scale;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), "RbfKernel: " + *interpolation_problem(s));
    }
  }
  EXPECT_NO_THROW((void)RbfKernel::from(with(3.5, 1000.0), 30.0));
}

}  // namespace
}  // namespace vdfx::effects
