// Orthogonal projection baseline (paper 4.1).
#include <gtest/gtest.h>

#include "refine2d_fixtures.h"

namespace nonobtuse {
namespace {

using testing::half_disk;
using testing::run;

// Figure 3 (the counts are worked out in greedy_refine_test.cpp): feet of q1 = (17, 15) and q2 = (39, 30.7) at
// x = 17 and 39, both needed since each q sits right above its foot afterwards (a right angle): 2 points where
// greedy needs 1. Figure 4: (20,2), (50,2), (80,2) project to 3 feet, the same count as greedy there.
TEST(ProjectionRefine, Figure3TwoPoints) {
  Refine2DResult r = run(half_disk({{17, 15}, {39, 30.7}}), RefineStrategy::Projection);
  EXPECT_EQ(r.steiner_points, 2);
  EXPECT_EQ(r.optimal, -1);  // not the bound (1), and the strategy is not greedy
}

TEST(ProjectionRefine, Figure4ThreeFeet) {
  Domain2 d = half_disk({{20, 2}, {50, 2}, {80, 2}});
  Refine2DResult r = run(d, RefineStrategy::Projection);
  ASSERT_EQ(r.steiner_points, 3);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(r.mesh.points[d.points.size() + i].x, 20.0 + 30 * i);  // exact feet
}

}  // namespace
}  // namespace nonobtuse
