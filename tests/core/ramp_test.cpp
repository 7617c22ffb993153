// The schedule of a ramp: piecewise linear between its points, held before the first and after
// the last, its extremes over an interval, and its refusals.
#include "core/ramp.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "core/analytic_model.hpp"

namespace fl {
namespace {

const Ramp kUpDown({{0.0, 100.0}, {60.0, 1600.0}, {120.0, 100.0}});

TEST(Ramp, LinearBetweenPointsAndHeldOutside) {
  EXPECT_DOUBLE_EQ(kUpDown.at(0.0), 100.0);
  EXPECT_DOUBLE_EQ(kUpDown.at(30.0), 850.0);   // halfway up
  EXPECT_DOUBLE_EQ(kUpDown.at(60.0), 1600.0);  // the top
  EXPECT_DOUBLE_EQ(kUpDown.at(90.0), 850.0);   // halfway down
  EXPECT_DOUBLE_EQ(kUpDown.at(120.0), 100.0);
  EXPECT_DOUBLE_EQ(kUpDown.at(500.0), 100.0);  // held after the last point
  const Ramp late({{10.0, 5.0}, {20.0, 7.0}});
  EXPECT_DOUBLE_EQ(late.at(0.0), 5.0);  // held before the first
  EXPECT_DOUBLE_EQ(late.at(12.5), 5.5);
}

TEST(Ramp, SlopeOfEachSegment) {
  EXPECT_DOUBLE_EQ(kUpDown.slope(10.0), 25.0);
  EXPECT_DOUBLE_EQ(kUpDown.slope(60.0), -25.0);  // at a point: the segment after it
  EXPECT_DOUBLE_EQ(kUpDown.slope(119.0), -25.0);
  EXPECT_DOUBLE_EQ(kUpDown.slope(120.0), 0.0);  // held
  EXPECT_DOUBLE_EQ(Ramp({{0.0, 3.0}}).slope(1.0), 0.0);
}

TEST(Ramp, ExtremesOverAnInterval) {
  EXPECT_DOUBLE_EQ(kUpDown.largest(), 1600.0);
  EXPECT_DOUBLE_EQ(kUpDown.smallest(), 100.0);
  EXPECT_DOUBLE_EQ(kUpDown.largest(0.0, 30.0), 850.0);  // the top is not reached by 30 s
  EXPECT_DOUBLE_EQ(kUpDown.largest(30.0, 100.0), 1600.0);
  EXPECT_DOUBLE_EQ(kUpDown.smallest(30.0, 90.0), 850.0);
  EXPECT_DOUBLE_EQ(kUpDown.smallest(30.0, 200.0), 100.0);
}

TEST(Ramp, RefusesPointsThatMakeNoSchedule) {
  EXPECT_THROW(Ramp({}), DomainError);
  EXPECT_THROW(Ramp({{0.0, 1.0}, {0.0, 2.0}}), DomainError);  // times must increase
  EXPECT_THROW(Ramp({{5.0, 1.0}, {2.0, 2.0}}), DomainError);  // backwards
  EXPECT_THROW(Ramp({{-1.0, 1.0}}), DomainError);             // before the start
  EXPECT_THROW(Ramp({{0.0, std::nan("")}}), DomainError);     // not a number
}

}  // namespace
}  // namespace fl
