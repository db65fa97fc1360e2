// nonobtuse::refine: budget and status.
#include <gtest/gtest.h>

#include "refine2d_fixtures.h"

namespace nonobtuse {
namespace {

using testing::half_disk;

TEST(Refine2d, BudgetExhaustedReturnsPartialMesh) {
  Domain2 d = half_disk({{17, 15}, {39, 30.7}});
  Refine2DResult r = refine(d, {RefineStrategy::Greedy, 0});
  EXPECT_EQ(r.status, RefineStatus::BudgetExhausted);
  EXPECT_EQ(r.steiner_points, 0);
  EXPECT_EQ(r.obtuse_boundary_sides, 1);  // the triangle on e, obtuse at q1
  EXPECT_EQ(r.mesh.points.size(), d.points.size());
  EXPECT_EQ(default_steiner_budget(7), 1070);
}

}  // namespace
}  // namespace nonobtuse
