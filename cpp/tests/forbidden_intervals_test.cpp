// Forbidden intervals (paper 4.2, Figure 5).
#include "forbidden_intervals.h"

#include <gtest/gtest.h>

#include "refine2d_fixtures.h"
#include "refine2d_state_fixtures.h"

namespace nonobtuse::refine2d {
namespace {

// Figure 5's quadrilateral (refine2d_fixtures.h): plain greedy on (a, d) would stop at x = 94.44, inside the disk
// of (d, c) (centre (95, 10), r^2 125: 0.31 + 100 < 125), whose triangle (a, d, c) would get it as apex: it breaks
// (d, c), the only side it breaks. The interval of (a, d) with respect to (d, c) is where the line y = 0 crosses
// that circle: (x - 95)^2 + 100 = 125, x = 90 and 100, t = 0.9 and 1. x = 89 breaks nothing; x = 90 is on the
// circle (a right angle at it: in the closed disk, not the open one).
TEST(ForbiddenIntervals, Figure5IntervalOfTheNeighbouringSide) {
  testing::OwningState st(testing::figure5_quadrilateral());
  const Side ad{st.v(0), st.v(1)}, dc{st.v(1), st.v(2)};
  std::vector<Side> broken = sides_broken_by(st, ad, Point(94.44, 0));
  ASSERT_EQ(broken.size(), 1u);
  EXPECT_TRUE(same_side(broken[0], dc));
  ASSERT_TRUE(forbidder(st, ad, Point(94.44, 0)).has_value());
  EXPECT_FALSE(forbidder(st, ad, Point(89, 0)).has_value());
  EXPECT_FALSE(forbidder(st, ad, Point(90, 0)).has_value());
  auto [t1, t2] = forbidden_interval(Point(0, 0), Point(100, 0), dc);
  EXPECT_NEAR(t1, 0.9, 1e-15);
  EXPECT_NEAR(t2, 1.0, 1e-15);
  EXPECT_TRUE(in_closed_disk(Point(90, 0), dc));
  EXPECT_TRUE(in_closed_disk(Point(100, 0), dc));  // an end of dc itself
  EXPECT_FALSE(in_closed_disk(Point(0, 0), dc));
}

}  // namespace
}  // namespace nonobtuse::refine2d
