// Project-Flip baseline (paper 3.3).
#include <gtest/gtest.h>

#include "refine2d_fixtures.h"

namespace nonobtuse {
namespace {

using testing::half_disk;
using testing::run;

// Figure 3 (worked out in greedy_refine_test.cpp): the apex of e is q1 (the larger angle, cos -0.620 against
// -0.424 at q2); its foot 17 leaves [17, 100] encroached by q2, whose foot 39 is the second point: 2 points where
// greedy needs 1.
TEST(ProjectFlip, Figure3TwoPoints) {
  Refine2DResult r = run(half_disk({{17, 15}, {39, 30.7}}), RefineStrategy::ProjectFlip);
  EXPECT_EQ(r.steiner_points, 2);
  EXPECT_EQ(r.lower_bound, 1);
}

// Figure 5's quadrilateral: the triangle on (a, d) is (a, d, c), obtuse at c = (90, 20); its foot (90, 0) is the
// one point, as for greedy (the foot of an apex is never inside the other edges' disks of that triangle).
TEST(ProjectFlip, Figure5FootOfTheApex) {
  Domain2 d = testing::figure5_quadrilateral();
  Refine2DResult r = run(d, RefineStrategy::ProjectFlip);
  ASSERT_EQ(r.steiner_points, 1);
  EXPECT_EQ(r.mesh.points[4].x, 90.0);
  EXPECT_EQ(r.mesh.points[4].y, 0.0);
}

}  // namespace
}  // namespace nonobtuse
