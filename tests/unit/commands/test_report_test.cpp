// The error of a TEST_RESU / TEST_TABLE check: absolute, relative, and relative on the scale
// of ORDRE_GRANDEUR for a reference smaller than it.
#include <gtest/gtest.h>

#include "commands/test_report.hpp"

using lunaster::cmd::check_difference;

TEST(TestReport, RelativeAndAbsoluteErrors) {
  EXPECT_DOUBLE_EQ(check_difference(101.0, 100.0, true, 0.0), 0.01);
  EXPECT_DOUBLE_EQ(check_difference(101.0, 100.0, false, 0.0), 1.0);
  // A zero reference without ORDRE_GRANDEUR: the absolute difference.
  EXPECT_DOUBLE_EQ(check_difference(2e-3, 0.0, true, 0.0), 2e-3);
  // ORDRE_GRANDEUR does not change a reference larger than it.
  EXPECT_DOUBLE_EQ(check_difference(101.0, 100.0, true, 10.0), 0.01);
}

TEST(TestReport, RoundOffIsComparedOnTheScaleOfTheQuantity) {
  // A resultant zero in theory (axis_thick_cylinder's radial stress on a free face, or a
  // reaction sum in reactions_tables) computed as round-off on two machines: relative to its
  // own round-off the two differ by 100 %, on the scale of the load (1e5) by 1e-17.
  const double here = 1.818989404e-12, there = 9.094947018e-13;
  EXPECT_GT(check_difference(there, here, true, 0.0), 0.4);
  EXPECT_LT(check_difference(there, here, true, 1e5), 1e-16);
  EXPECT_DOUBLE_EQ(check_difference(3.0, 0.0, true, 1e5), 3e-5);
  // A real change of the quantity still fails the default TOLE_MACHINE (1e-6).
  EXPECT_GT(check_difference(0.5, here, true, 1e5), 1e-6);
}
