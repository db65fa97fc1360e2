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

// covered_from, hand-worked: v = (0, 4) above the open segment (-2, 0)-(2, 0); the sight line to (x, 0) crosses
// y = 2 at x / 2 and y = 1 at 3 x / 4. (-3, 2)-(3, 2) blocks every one; (-3, 2)-(0.9, 2) leaves 1.8 < x < 2 open;
// (0.5, 1)-(3, 1) blocks x >= 2/3 and closes that gap. Behind the segment, (-3, -1)-(3, -1) shades nothing, nor
// does one ending at v. From the end a = (-2, 0): to (-1, -3), behind, it shades nothing (counted, it would
// shade x <= -4/7 and close the gap x < -1 left by (-0.5, 2)-(3, 2)); to (3, 3), in front, every line crosses it.
TEST(Visibility, CoveredFromShadesOnlyInFront) {
  const Point v(0, 4), a(-2, 0), b(2, 0);
  EXPECT_FALSE(covered_from(v, a, b, {}));
  EXPECT_TRUE(covered_from(v, a, b, {{Point(-3, 2), Point(3, 2)}}));
  EXPECT_FALSE(covered_from(v, a, b, {{Point(-3, 2), Point(0.9, 2)}}));
  EXPECT_TRUE(covered_from(v, a, b, {{Point(-3, 2), Point(0.9, 2)}, {Point(0.5, 1), Point(3, 1)}}));
  EXPECT_FALSE(covered_from(v, a, b, {{Point(-3, -1), Point(3, -1)}, {v, Point(5, 0)}}));
  // Ending at the segment's end a: shades only when it enters v's side.
  EXPECT_FALSE(covered_from(v, a, b, {{a, Point(-1, -3)}, {Point(-0.5, 2), Point(3, 2)}}));
  EXPECT_TRUE(covered_from(v, a, b, {{a, Point(3, 3)}}));
}

// obstacles_near_triangle, hand-worked on the triangle v = (0, 4), s = (-2, 0), e = (2, 0) (margin 2^-30 * 4, about
// 4e-9): one crossing it, one ending at s and one 1e-12 below the line y = 0 (within the margin) are kept, in their
// order; one 1e-3 below it, one beyond the side v-e and one whose line leaves the whole triangle on one side are
// dropped.
TEST(Visibility, ObstaclesNearTriangleKeepsWhatMayLieInFront) {
  const Point v(0, 4), s(-2, 0), e(2, 0);
  const std::vector<Segment2> obstacles = {
      {Point(-3, 1), Point(3, 1)},         {Point(-3, -1e-3), Point(3, -1e-3)}, {s, Point(-5, 1)},
      {Point(3, 3), Point(4, 0)},          {Point(-1, -1e-12), Point(1, -1e-12)}, {Point(-10, 9), Point(10, 7)}};
  const std::vector<Segment2> kept = obstacles_near_triangle(v, s, e, obstacles);
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept[0], obstacles[0]);
  EXPECT_EQ(kept[1], obstacles[2]);
  EXPECT_EQ(kept[2], obstacles[4]);
}

// covered_from decides the same on obstacles_near_triangle(v, s, e, ·) as on all obstacles, for subsegments (a, b)
// of [s, e] (ends on a grid of parameters) and random obstacles around the triangle (seeded).
TEST(Visibility, ObstaclesNearTriangleKeepsCoveredFrom) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-4, 4);
  const Point s(-2, 0), e(2, 0);
  int covered = 0, open = 0;
  std::size_t dropped = 0;
  for (int round = 0; round < 200; ++round) {
    const Point v(coordinate(rng), std::abs(coordinate(rng)) + 0.1);
    std::vector<Segment2> obstacles;
    for (int k = 0; k < 6; ++k) {
      Point c1(coordinate(rng), std::abs(coordinate(rng))), c2(coordinate(rng), coordinate(rng));
      // Constraints never cross the side: keep those that do not.
      if (CGAL::do_intersect(K::Segment_2(c1, c2), K::Segment_2(s, e)) || c1 == v || c2 == v) continue;
      obstacles.emplace_back(c1, c2);
    }
    const std::vector<Segment2> kept = obstacles_near_triangle(v, s, e, obstacles);
    dropped += obstacles.size() - kept.size();
    for (int i = 0; i < 8; ++i)
      for (int j = i + 1; j <= 8; ++j) {
        const Point a(-2 + 0.5 * i, 0), b(-2 + 0.5 * j, 0);
        const bool all = covered_from(v, a, b, obstacles);
        ASSERT_EQ(covered_from(v, a, b, kept), all) << "round " << round << " a " << a << " b " << b;
        ++(all ? covered : open);
      }
  }
  EXPECT_GT(covered, 0);
  EXPECT_GT(open, 0);
  EXPECT_GT(dropped, 0u);
}

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

// segment_meets_triangle against CGAL's do_intersect on every segment between points of a 5 x 5 grid and a few
// triangles on it: ends on sides' lines, at corners, segments along sides, through a corner (the touching cases).
TEST(Visibility, SegmentMeetsTriangleAgreesWithDoIntersect) {
  std::vector<Point> grid;
  for (int x = 0; x < 5; ++x)
    for (int y = 0; y < 5; ++y) grid.emplace_back(x, y);
  const std::vector<std::array<Point, 3>> triangles = {
      {Point(1, 1), Point(3, 1), Point(1, 3)}, {Point(0, 0), Point(4, 2), Point(2, 4)}, {Point(1, 2), Point(3, 3), Point(2, 1)}};
  int meets = 0, misses = 0;
  for (const auto& [p, q, r] : triangles)
    for (const Point& c1 : grid)
      for (const Point& c2 : grid) {
        if (c1 == c2) continue;
        const bool expected = CGAL::do_intersect(K::Segment_2(c1, c2), K::Triangle_2(p, q, r));
        ASSERT_EQ(segment_meets_triangle(c1, c2, p, q, r), expected) << c1 << " " << c2 << " / " << p << " " << q << " " << r;
        ++(expected ? meets : misses);
      }
  EXPECT_GT(meets, 0);
  EXPECT_GT(misses, 0);
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
