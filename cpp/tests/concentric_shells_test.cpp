#include "concentric_shells.h"

#include <gtest/gtest.h>

#include "refine2d_state_fixtures.h"

namespace nonobtuse::refine2d {
namespace {

// shell_at_or_before: the largest power of two <= t |e - s|, as a parameter of [s, e].
TEST(ConcentricShells, ShellParameterRoundsDownToAPowerOfTwo) {
  const Point s(0, 0), e(6, 0);
  EXPECT_EQ(shell_at_or_before(s, e, 1.01 / 6), 1.0 / 6);   // 1.01 -> 1
  EXPECT_EQ(shell_at_or_before(s, e, 3.0 / 6), 2.0 / 6);    // 3 -> 2
  EXPECT_EQ(shell_at_or_before(s, e, 4.0 / 6), 4.0 / 6);    // a power of two stays
  EXPECT_EQ(shell_at_or_before(s, e, 0.3 / 6), 0.25 / 6);   // 0.3 -> 2^-2
  EXPECT_EQ(shell_at_or_before(Point(1, 1), Point(4, 5), 0.5), 2.0 / 5);  // |e - s| = 5: 2.5 -> 2
}

// v = (0, 0) with an interface to (6, 0) and one at 10 degrees, in a box; (0, 0)-(6, 0) is acute at v because of
// the other interface (angle 10 < 90), not at (6, 0) (no other constraint there). A boundary corner alone (two
// boundary edges at 90 degrees) is not a junction for the shells.
TEST(ConcentricShells, AcuteJunctionNeedsAnInteriorConstraint) {
  Domain2 d;
  d.points = {{-10, -10}, {10, -10}, {10, 10}, {-10, 10}, {0, 0}, {6, 0}, {5.9088, 1.0419}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {4, 6}};
  testing::OwningState st(std::move(d));
  EXPECT_TRUE(is_acute_junction(st, st.v(4), st.v(5)));
  EXPECT_TRUE(is_acute_junction(st, st.v(4), st.v(6)));
  EXPECT_FALSE(is_acute_junction(st, st.v(5), st.v(4)));
  EXPECT_FALSE(is_acute_junction(st, st.v(0), st.v(1)));
  // The sweep of (6, 0) -> (0, 0) starts at the junction instead (its reverse is a domain side too).
  Side anchored = shell_anchor(st, {st.v(5), st.v(4)});
  EXPECT_EQ(anchored.s, st.v(4));
  EXPECT_EQ(anchored.e, st.v(5));
}

}  // namespace
}  // namespace nonobtuse::refine2d
