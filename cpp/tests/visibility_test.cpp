// Visibility from a subsegment: the walk over its diametral disk and exact shading (covered_from).
#include "visibility.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "refine2d_fixtures.h"
#include "greedy_edge.h"
#include "refine2d_state_fixtures.h"

namespace nonobtuse::refine2d {
namespace {

// segments_meet, hand-worked: crossing, disjoint with overlapping boxes, touching at an end or at an inner point,
// sharing an end, collinear overlapping, collinear apart (overlapping in x only), and parallel.
TEST(Visibility, SegmentsMeetHandCases) {
  EXPECT_TRUE(segments_meet(Point(0, 0), Point(2, 2), Point(0, 2), Point(2, 0)));
  EXPECT_FALSE(segments_meet(Point(0, 0), Point(4, 4), Point(3, 0), Point(4, 2)));
  EXPECT_TRUE(segments_meet(Point(0, 0), Point(4, 4), Point(2, 2), Point(5, 0)));
  EXPECT_TRUE(segments_meet(Point(0, 0), Point(4, 0), Point(2, 0), Point(2, 3)));
  EXPECT_TRUE(segments_meet(Point(0, 0), Point(4, 0), Point(4, 0), Point(5, 7)));
  EXPECT_TRUE(segments_meet(Point(0, 0), Point(4, 0), Point(3, 0), Point(6, 0)));
  EXPECT_FALSE(segments_meet(Point(0, 0), Point(1, 1), Point(2, 2), Point(3, 3)));
  EXPECT_FALSE(segments_meet(Point(0, 0), Point(4, 0), Point(0, 1), Point(4, 1)));
}

// Walked::Seen on random star polygons (bench_scaling's family, seeded): for every side, its encroachers are among
// Reach's, greedy_count (the lower bound, exact sight) is the same on either walk, and over all sides the Seen
// walks keep fewer obstacles (the spikes behind the side's walls are skipped).
TEST(Visibility, SeenWalkKeepsTheLowerBound) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(0, 6.283185307179586), radius(0.5, 1.0);
  std::size_t all_reach = 0, all_seen = 0;
  for (int n : {60, 200, 600}) {
    std::vector<double> a(n);
    for (double& x : a) x = angle(rng);
    std::sort(a.begin(), a.end());
    Domain2 d;
    for (int i = 0; i < n; ++i) {
      const double r = radius(rng);
      d.points.push_back({r * std::cos(a[i]), r * std::sin(a[i])});
      d.segments.push_back({i, (i + 1) % n});
    }
    testing::OwningState st(std::move(d));
    std::size_t reach_obstacles = 0, seen_obstacles = 0;
    for (const Side& side : st.boundary_sides()) {
      const DiskWalk reach = walk_diametral_disk(st, side), seen = walk_diametral_disk(st, side, 0, Walked::Seen);
      for (Vertex_handle v : seen.encroachers)
        ASSERT_NE(std::find(reach.encroachers.begin(), reach.encroachers.end(), v), reach.encroachers.end());
      ASSERT_EQ(greedy_count(st, side, seen), greedy_count(st, side, reach)) << "n " << n << " side " << side.s->info();
      reach_obstacles += reach.obstacles.size();
      seen_obstacles += seen.obstacles.size();
    }
    EXPECT_LE(seen_obstacles, reach_obstacles) << "n " << n;
    all_reach += reach_obstacles;
    all_seen += seen_obstacles;
  }
  EXPECT_LT(all_seen, all_reach);  // the small walks are not pruned (kFreeFaces), the large ones are
}

// Figure 3 (greedy_refine_test.cpp): the walk over the disk of e = (0,0) -> (100,0) finds exactly the two inner
// points q1 (index 201) and q2 (202), by index; the arc vertices lie outside the disk (radius 50 (1 + 1e-6)).
// Both are seen from e (nothing between), so sees holds for either sight.
TEST(Visibility, DiskWalkFindsTheEncroachersOfFigure3) {
  testing::OwningState st(testing::half_disk({{17, 15}, {39, 30.7}}));
  const Side e{st.v(200), st.v(0)};
  DiskWalk w = walk_diametral_disk(st, e);
  ASSERT_EQ(w.encroachers.size(), 2u);
  EXPECT_EQ(w.encroachers[0], st.v(201));
  EXPECT_EQ(w.encroachers[1], st.v(202));
  for (Vertex_handle q : w.encroachers) {
    EXPECT_TRUE(sees(st, e, e.s->point(), e.e->point(), q, Sight{}));
    EXPECT_TRUE(sees(st, e, e.s->point(), e.e->point(), q, Sight{&w.obstacles}));
  }
  EXPECT_TRUE(walk_diametral_disk(st, {st.v(0), st.v(1)}).encroachers.empty());  // an arc edge: a tiny empty disk
}

// A dangling segment hides a vertex: the square [0, 10]^2 with the dangling segment (2, 3)-(8, 3) and the point
// (5, 4) above it. (5, 4) is inside the disk of the bottom edge ((5 - 5)^2 + 4^2 < 25), but the sight line to
// (x, 0) crosses y = 3 at 5 + (x - 5) / 4, inside [2, 8] for every x in (0, 10): hidden. The walk may reach it
// around the segment's free ends (both inside the disk); exact sight, against the obstacles the walk met, does not
// count it.
TEST(Visibility, ADanglingSegmentHidesAVertex) {
  Domain2 d;
  d.points = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {2, 3}, {8, 3}, {5, 4}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}};
  testing::OwningState st(std::move(d));
  const Side bottom{st.v(0), st.v(1)};
  DiskWalk w = walk_diametral_disk(st, bottom);
  EXPECT_FALSE(sees(st, bottom, Point(0, 0), Point(10, 0), st.v(6), Sight{&w.obstacles}));
  EXPECT_FALSE(covered_from(Point(5, 4), Point(0, 0), Point(10, 0), {}));
  EXPECT_TRUE(covered_from(Point(5, 4), Point(0, 0), Point(10, 0), {{Point(2, 3), Point(8, 3)}}));
}

}  // namespace
}  // namespace nonobtuse::refine2d
