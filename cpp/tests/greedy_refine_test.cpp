// Sensitive Greedy-Refine: paper Figures 3 (greedy side), 4 and 5, and a lower bound it cannot attain.
#include <gtest/gtest.h>

#include "refine2d_fixtures.h"

namespace nonobtuse {
namespace {

using testing::half_disk;
using testing::run;

// Figure 3: q1 = (17, 15) and q2 = (39, 30.7) are inside e's disk (|q - (50,0)|^2 = 1314 and 1063.49 < 2500).
// Greedy from (0,0): t(q) = |q|^2 / (100 q.x): q1 514/1700 = 0.3024, q2 2463.49/3900 = 0.6317; one point at
// x = 30.24, after which [30.24, 100] (centre 65.12, r^2 1216.6) misses q2 ((26.12)^2 + 30.7^2 = 1624.8): 1 point.
// Projection: feet 17 and 39, both needed: 2 points.
// Project-Flip: the apex of e is the vertex with the larger angle: cos at q1 = -1186 / (22.67 * 84.34) = -0.620,
// at q2 = -1436.5 / (49.63 * 68.29) = -0.424, so q1; its foot 17 leaves [17, 100] (centre 58.5, r^2 1722.25)
// encroached by q2 ((39 - 58.5)^2 + 30.7^2 = 1322.7): a second point at the foot 39. 2 points.
TEST(GreedyRefine, Figure3OnePoint) {
  Domain2 d = half_disk({{17, 15}, {39, 30.7}});
  Refine2DResult g = run(d, RefineStrategy::Greedy);
  EXPECT_EQ(g.steiner_points, 1);
  EXPECT_EQ(g.lower_bound, 1);
  EXPECT_EQ(g.optimal, 1);
  EXPECT_NEAR(g.mesh.points.back().x, 514.0 / 17, 1e-9);
}

// Figure 4: the greedy grabs the largest empty disk from its current end. Points (20,2), (50,2), (80,2):
// x1 = (20^2 + 2^2) / 20 = 20.2; from x1, q = (50,2) is at (29.8, 2): x2 = 20.2 + 29.8 + 4 / 29.8 = 50.134228;
// from x2, (80,2) is at (29.865772, 2): x3 = 80 + 4 / 29.865772 = 80.133933; then nothing is ahead. 3 points,
// which is the lower bound (Theorem 2: greedy is optimal for one edge).
TEST(GreedyRefine, Figure4Walk) {
  Domain2 d = half_disk({{20, 2}, {50, 2}, {80, 2}});
  Refine2DResult g = run(d, RefineStrategy::Greedy);
  ASSERT_EQ(g.steiner_points, 3);
  EXPECT_EQ(g.lower_bound, 3);
  std::size_t n = d.points.size();
  EXPECT_NEAR(g.mesh.points[n].x, 20.2, 1e-9);
  EXPECT_NEAR(g.mesh.points[n + 1].x, 50 + 4 / 29.8, 1e-9);
  EXPECT_NEAR(g.mesh.points[n + 2].x, 80 + 4 / (30 - 4 / 29.8), 1e-9);
  for (std::size_t i = n; i < n + 3; ++i) EXPECT_EQ(g.mesh.points[i].y, 0.0);  // exactly on the axis
}

// Figure 5 (interference): convex quadrilateral a(0,0), d(100,0), c(90,20), b(0,60). Only c encroaches (a,d)
// ((90-50)^2 + 20^2 = 2000 < 2500); (a,b), (b,c), (c,d) are empty. Plain greedy from a would stop at
// t = |c|^2 / (100 * 90) = 8500 / 9000 -> x = 94.44, inside the disk of (c,d) (centre (95,10), r^2 125:
// 0.31 + 100 < 125), breaking (c,d). The disk of (c,d) meets (a,d) in (90, 100) (Thales: 90 is the foot of c),
// so sensitive greedy puts the point at the interval's start, x = 90: [0,90] and [90,100] both see c at a
// right angle. 1 point, the lower bound.
TEST(GreedyRefine, Figure5AvoidsForbiddenInterval) {
  Domain2 d = testing::figure5_quadrilateral();
  Refine2DResult g = run(d, RefineStrategy::Greedy);
  ASSERT_EQ(g.steiner_points, 1);
  EXPECT_EQ(g.mesh.points[4].x, 90.0);
  EXPECT_EQ(g.mesh.points[4].y, 0.0);
  EXPECT_EQ(g.optimal, 1);
}

// The lower bound is not always attained. Hexagon (CCW) v0(-987,-162) v1(-784,-620) v2(-316,-949) v3(-185,-983)
// v5(1000,5) v4(995,101); only (v4, v0) is encroached (by v1, v2, v3, v5). Alone, one point suffices (lower
// bound 1): from v4, v5 blocks at t = |v5 - v4|^2 / ((v5 - v4).d) = 9241 / 15338 = 0.6025, and t = 0.6025 leaves
// [t, 1] empty. But the disk of (v3, v5), empty, covers t in (0.0396, 0.6206) of (v4, v0), so a point there
// forces another on (v3, v5), and a point at t <= 0.0396 leaves [t, 1] encroached by v1 (foot at 0.9295).
// Either way 2 points: greedy places 2, optimal by Theorem 3 (convex polygon).
TEST(GreedyRefine, LowerBoundNotAttainedUnderInterference) {
  Domain2 d;
  d.points = {{-987, -162}, {-784, -620}, {-316, -949}, {-185, -983}, {995, 101}, {1000, 5}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 5}, {5, 4}, {4, 0}};
  Refine2DResult g = run(d, RefineStrategy::Greedy);
  EXPECT_EQ(g.lower_bound, 1);
  EXPECT_EQ(g.steiner_points, 2);
  EXPECT_EQ(g.optimal, 1);
}

}  // namespace
}  // namespace nonobtuse
