// The lower bound per input edge.
#include "lower_bound.h"

#include <gtest/gtest.h>

#include "refine2d_fixtures.h"
#include "refine2d_state_fixtures.h"

namespace nonobtuse::refine2d {
namespace {

// The hexagon of greedy_refine_test.cpp (LowerBoundNotAttainedUnderInterference): only (v4, v0) is encroached
// (by v1, v2, v3, v5); alone one point clears it (from v4, v5 blocks at t = 9241 / 15338 = 0.6025 and [t, 1] is
// then empty), so its bound is 1 and every other edge's 0; one thread or two, the same bounds.
TEST(LowerBound, HexagonOnePointOnOneEdge) {
  Domain2 d;
  d.points = {{-987, -162}, {-784, -620}, {-316, -949}, {-185, -983}, {995, 101}, {1000, 5}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 5}, {5, 4}, {4, 0}};
  for (int threads : {1, 2}) {
    State st(d, 10);
    lower_bound_per_edge(st, threads);
    ASSERT_EQ(st.edges().size(), 6u);
    for (const auto& e : st.edges())
      EXPECT_EQ(e.lower_bound, (e.edge == Segment{4, 0} ? 1 : 0)) << e.edge[0] << "-" << e.edge[1];
  }
}

// Figure 4 (three points in a row under e): the bound on e is greedy's count, 3, and the arc edges' 0.
TEST(LowerBound, Figure4BoundIsTheGreedyCount) {
  testing::OwningState st(testing::half_disk({{20, 2}, {50, 2}, {80, 2}}));
  lower_bound_per_edge(st, 1);
  long long total = 0;
  for (const auto& e : st.edges()) total += e.lower_bound;
  EXPECT_EQ(total, 3);
}

}  // namespace
}  // namespace nonobtuse::refine2d
