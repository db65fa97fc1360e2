// Single-edge Greedy-Refine (Theorem 2): the greedy end, subsegment emptiness and the greedy count.
#include "greedy_edge.h"

#include <gtest/gtest.h>

#include <vector>

#include "refine2d_fixtures.h"
#include "refine2d_state_fixtures.h"

namespace nonobtuse::refine2d {
namespace {

// Figure 3: from s = (0,0) along e = (0,0) -> (100,0), t(q) = |q|^2 / (100 q.x): q1 = (17, 15) gives
// 514 / 1700 = 0.3024, q2 = (39, 30.7) gives 2463.49 / 3900 = 0.6317; q1 blocks first. [0, 30] is empty (its disk,
// centre 15, r^2 225, misses q1: 2^2 + 15^2 = 229), [0, 31] is not (centre 15.5, r^2 240.25: 1.5^2 + 225 = 227.25).
TEST(GreedyEdge, Figure3GreedyEndAndEmptiness) {
  testing::OwningState st(testing::half_disk({{17, 15}, {39, 30.7}}));
  const Side e{st.v(200), st.v(0)};
  DiskWalk w = walk_diametral_disk(st, e);
  const Encroachers q = with_points(w.encroachers, e.s->point(), e.e->point());
  Vertex_handle blocker;
  for (Sight sight : {Sight{}, Sight{&w.obstacles}}) {
    EXPECT_NEAR(greedy_parameter(st, e, e.s->point(), e.e->point(), q, sight, &blocker), 514.0 / 1700,
                1e-15);
    EXPECT_EQ(blocker, st.v(201));
    EXPECT_TRUE(subsegment_is_empty(st, e, Point(0, 0), Point(30, 0), q, sight));
    EXPECT_FALSE(subsegment_is_empty(st, e, Point(0, 0), Point(31, 0), q, sight));
  }
  EXPECT_EQ(greedy_count(st, e, w), 1);
}

// Figure 4: (20,2), (50,2), (80,2) need 3 greedy points (worked out in greedy_refine_test.cpp); from x = 50.2 on,
// (20, 2) no longer encroaches (keep_encroaching drops it) but (50, 2) and (80, 2) still do.
TEST(GreedyEdge, Figure4CountsThreePoints) {
  testing::OwningState st(testing::half_disk({{20, 2}, {50, 2}, {80, 2}}));
  const Side e{st.v(200), st.v(0)};
  DiskWalk w = walk_diametral_disk(st, e);
  ASSERT_EQ(w.encroachers.size(), 3u);
  EXPECT_EQ(greedy_count(st, e, w), 3);
  Encroachers q = with_points(w.encroachers, e.s->point(), e.e->point());
  keep_encroaching(Point(20.2, 0), Point(100, 0), q);
  ASSERT_EQ(q.items.size(), 2u);
  EXPECT_EQ(q.items[0].v, st.v(202));
  EXPECT_EQ(q.items[1].v, st.v(203));
  EXPECT_EQ(q.items[1].p, Point(80, 2));
}

// Figure 4 turned upright: the edge (0,0) -> (0,100) extends along y, so the encroachers are sorted by y, and
// keep_encroaching from x = (0, 20.2) keeps (-2, 50) and (-2, 80), drops (-2, 20) (behind x) and (-2, 100.5) (past
// e: outside the disk's span along y), exactly as testing each one would.
TEST(GreedyEdge, UprightEdgeSortsAlongYAndKeepsTheSameEncroachers) {
  const Point s(0, 0), e(0, 100);
  Encroachers q;
  q.axis = 1;
  for (Point p : {Point(-2, 20), Point(-2, 50), Point(-2, 80), Point(-2, 100.5)}) q.items.push_back({p, {}});
  keep_encroaching(Point(0, 20.2), e, q);
  ASSERT_EQ(q.items.size(), 2u);
  EXPECT_EQ(q.items[0].p, Point(-2, 50));
  EXPECT_EQ(q.items[1].p, Point(-2, 80));
  EXPECT_EQ(with_points({}, s, e).axis, 1);
  EXPECT_EQ(with_points({}, s, Point(100, 99)).axis, 0);
}

}  // namespace
}  // namespace nonobtuse::refine2d
