#include "nonobtuse/refine2d_diagnosis.h"

#include <gtest/gtest.h>

#include "refine2d_fixtures.h"

namespace nonobtuse {
namespace {

// Rectangle [0, 8]^2 cut by the interface y = 4, with q1 = (2, 4.5) above and q2 = (6, 3.5) below it (see
// tests/test_pslg.py for the hand computation): 2 Steiner points on the interface, both sides checked.
Domain2 rectangle_with_interface() {
  Domain2 d;
  d.points = {{0, 0}, {8, 0}, {8, 4}, {8, 8}, {0, 8}, {0, 4}, {2, 4.5}, {6, 3.5}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 0}, {5, 2}};
  return d;
}

TEST(Refine2dDiagnosis, InterfaceRefinedOnBothSidesWithOneCause) {
  Refine2DResult r = testing::run(rectangle_with_interface(), RefineStrategy::Greedy);
  EXPECT_EQ(r.status, RefineStatus::Converged);
  EXPECT_EQ(r.obtuse_boundary_sides, 0);
  EXPECT_EQ(r.steiner_points, 2);
  EXPECT_EQ(r.lower_bound, 2);
  // Both sides of the interface are violated at the start; the sweep of the first one refines both, so the
  // second is no longer violated when popped: one cause, one input edge, two splits.
  EXPECT_EQ(r.diagnosis.initial_violations, 1);
  EXPECT_EQ(r.diagnosis.propagation_depth, 1);
  EXPECT_EQ(r.diagnosis.propagation_splits, 2);
  // Each point goes to the nearer end of the interface: x = 2.1 or 1.9 near (0, 4) = point 5, x = 6.1 or 5.9 near
  // (8, 4) = point 2; both ends are junctions of 3 constraints at 90 degrees.
  ASSERT_EQ(r.diagnosis.junctions.size(), 2u);
  for (const auto& j : r.diagnosis.junctions) {
    EXPECT_TRUE(j.vertex == 2 || j.vertex == 5);
    EXPECT_EQ(j.constraints, 3);
    EXPECT_NEAR(j.min_angle_degrees, 90.0, 1e-9);
    EXPECT_EQ(j.steiner_points, 1);
  }
}

}  // namespace
}  // namespace nonobtuse
