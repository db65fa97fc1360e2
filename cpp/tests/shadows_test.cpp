// Exact shading from a vertex: covered_from and ShadowIntervals, which must answer exactly as covered_from does.
#include "shadows.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <random>
#include <vector>

namespace nonobtuse::refine2d {
namespace {

// The obstacles at `which`, in that order.
std::vector<Segment2> pick(const std::vector<Segment2>& obstacles, std::initializer_list<int> which) {
  std::vector<Segment2> out;
  for (int k : which) out.push_back(obstacles[k]);
  return out;
}

// covered_from, hand-worked: v = (0, 4) above the open segment (-2, 0)-(2, 0); the sight line to (x, 0) crosses
// y = 2 at x / 2 and y = 1 at 3 x / 4. (-3, 2)-(3, 2) blocks every one; (-3, 2)-(0.9, 2) leaves 1.8 < x < 2 open;
// (0.5, 1)-(3, 1) blocks x >= 2/3 and closes that gap. Behind the segment, (-3, -1)-(3, -1) shades nothing, nor
// does one ending at v. From the end a = (-2, 0): to (-1, -3), behind, it shades nothing (counted, it would
// shade x <= -4/7 and close the gap x < -1 left by (-0.5, 2)-(3, 2)); to (3, 3), in front, every line crosses it.
TEST(Shadows, CoveredFromShadesOnlyInFront) {
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
TEST(Shadows, ObstaclesNearTriangleKeepsWhatMayLieInFront) {
  const Point v(0, 4), s(-2, 0), e(2, 0);
  const std::vector<Segment2> obstacles = {
      {Point(-3, 1), Point(3, 1)},         {Point(-3, -1e-3), Point(3, -1e-3)}, {s, Point(-5, 1)},
      {Point(3, 3), Point(4, 0)},          {Point(-1, -1e-12), Point(1, -1e-12)}, {Point(-10, 9), Point(10, 7)}};
  EXPECT_EQ(obstacles_near_triangle(v, s, e, obstacles), pick(obstacles, {0, 2, 4}));
}

// covered_from decides the same on obstacles_near_triangle(v, s, e, ·) as on all obstacles, for subsegments (a, b)
// of [s, e] (ends on a grid of parameters) and random obstacles around the triangle (seeded).
TEST(Shadows, ObstaclesNearTriangleKeepsCoveredFrom) {
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

// segment_meets_triangle against CGAL's do_intersect on every segment between points of a 5 x 5 grid and a few
// triangles on it: ends on sides' lines, at corners, segments along sides, through a corner (the touching cases).
TEST(Shadows, SegmentMeetsTriangleAgreesWithDoIntersect) {
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

// ShadowIntervals, hand-worked on covered_from's case (above): v = (0, 4) above the side (-2, 0)-(2, 0);
// the sight line to (x, 0) crosses y = 2 at x / 2 and y = 1 at 3 x / 4. (-3, 2)-(0.9, 2) shades x <= 1.8 and
// (0.5, 1)-(3, 1) shades x >= 2/3: both lie above the fat side, each strictly on the inner side of one line from v
// through an extreme corner of it (the first right of the one through (2, 0)'s corner, the second left of the one
// through (-2, 0)'s), so both are sure and merge into one interval covering the side. The first alone leaves
// 1.8 < x < 2 open: (-2, 0)-(1.5, 0) is covered, (1.9, 0)-(2, 0) and the whole side are not. An obstacle ending at
// s = (-2, 0) lies on the fat side's line, so it is a maybe obstacle, decided per question as covered_from does: to
// (3, 3), in front, it covers; to (-1, -3), behind, it does not.
TEST(Shadows, ShadowIntervalsHandWorked) {
  const Point v(0, 4), s(-2, 0), e(2, 0);
  const auto fat = fat_side(s, e);
  const ShadowIntervals both(v, fat, {{Point(-3, 2), Point(0.9, 2)}, {Point(0.5, 1), Point(3, 1)}});
  ASSERT_TRUE(both.prepared());
  EXPECT_EQ(both.intervals(), 1u);
  EXPECT_TRUE(both.covered(s, e));
  EXPECT_TRUE(both.covered(Point(1.9, 0), e));
  const ShadowIntervals first(v, fat, {{Point(-3, 2), Point(0.9, 2)}});
  EXPECT_EQ(first.intervals(), 1u);
  EXPECT_TRUE(first.covered(s, Point(1.5, 0)));
  EXPECT_FALSE(first.covered(Point(1.9, 0), e));
  EXPECT_FALSE(first.covered(s, e));
  const ShadowIntervals in_front(v, fat, {{s, Point(3, 3)}}), behind(v, fat, {{s, Point(-1, -3)}});
  EXPECT_EQ(in_front.intervals(), 0u);
  EXPECT_TRUE(in_front.covered(s, e));
  EXPECT_FALSE(behind.covered(s, e));
  // A vertex 1e-12 above the side lies within the fat side (margin 2^-30 * 2): no intervals, covered_from itself.
  const ShadowIntervals close(Point(0, 1e-12), fat, {{Point(-3, 2), Point(0.9, 2)}});
  EXPECT_FALSE(close.prepared());
  EXPECT_FALSE(close.covered(s, e));
}

// ShadowIntervals(v, ...).covered(a, b) == covered_from(v, a, b, ·) on random vertices and obstacles around the
// side (-2, 0)-(2, 0) (seeded; obstacles never cross the side, as constraints do not), for subsegments with ends on a
// grid of parameters, some moved a few ulps off the side's line, as rounded Steiner points are.
TEST(Shadows, ShadowIntervalsAgreeWithCoveredFrom) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coordinate(-4, 4), length(0.05, 1.5);
  std::uniform_int_distribution<int> ulps(-3, 3);
  const Point s(-2, 0), e(2, 0);
  const auto fat = fat_side(s, e);
  // A few ulps (of the coordinates, about 2) above or below the line y = 0.
  auto off_line = [&](double x) { return Point(x, ulps(rng) * 0x1p-51); };
  int covered = 0, open = 0, prepared = 0, merged = 0;
  for (int round = 0; round < 300; ++round) {
    const Point v(coordinate(rng), std::abs(coordinate(rng)) + 0.05);
    std::vector<Segment2> obstacles;
    for (int k = 0; k < 14; ++k) {
      const Point c1(coordinate(rng), k < 4 ? coordinate(rng) : std::abs(coordinate(rng)) * 0.7);
      const double angle = coordinate(rng), l = length(rng);
      const Point c2(c1.x() + l * std::cos(angle), c1.y() + l * std::sin(angle));
      if (CGAL::do_intersect(K::Segment_2(c1, c2), K::Segment_2(s, e)) || c1 == v || c2 == v) continue;
      obstacles.emplace_back(c1, c2);
    }
    if (round % 5 == 0) obstacles.emplace_back(s, Point(coordinate(rng), std::abs(coordinate(rng))));
    const ShadowIntervals shadows(v, fat, obstacles);
    prepared += shadows.prepared();
    merged += shadows.intervals() > 1;
    for (int i = 0; i < 8; ++i)
      for (int j = i + 1; j <= 8; ++j) {
        const Point a = i == 0 ? s : off_line(-2 + 0.5 * i), b = j == 8 ? e : off_line(-2 + 0.5 * j);
        const bool expected = covered_from(v, a, b, obstacles);
        ASSERT_EQ(shadows.covered(a, b), expected) << "round " << round << " v " << v << " a " << a << " b " << b;
        ++(expected ? covered : open);
      }
  }
  EXPECT_GT(covered, 1000);
  EXPECT_GT(open, 1000);
  EXPECT_GT(prepared, 250);
  EXPECT_GT(merged, 50);
}

// unshaded_obstacles, hand-worked on the side (-2, 0)-(2, 0) and the long A = (-3, 1)-(3, 1): the lines from the
// side's ends (+-2, 0) to (+-1, 2) and to (+-4, 3) cross y = 1 within |x| <= 2.67 < 3, so (-1, 2)-(1, 2) and
// (-4, 3)-(4, 3) lie wholly behind A and go; the line from (-2, 0) to (-6, 3) crosses y = 1 at x = -3.33, beside A, so
// (-6, 3)-(-5, 3) stays, and so does (2.5, 0.5)-(3.5, 0.5), nearer than A. Kept in their input order.
TEST(Shadows, UnshadedObstaclesDropWhatIsBehindAnother) {
  const Point s(-2, 0), e(2, 0);
  const auto fat = fat_side(s, e);
  const std::vector<Segment2> obstacles = {{Point(-1, 2), Point(1, 2)},
                                           {Point(-3, 1), Point(3, 1)},
                                           {Point(-4, 3), Point(4, 3)},
                                           {Point(2.5, 0.5), Point(3.5, 0.5)},
                                           {Point(-6, 3), Point(-5, 3)}};
  EXPECT_TRUE(in_umbra(fat, Point(1, 2), obstacles[1]));
  EXPECT_FALSE(in_umbra(fat, Point(-6, 3), obstacles[1]));
  EXPECT_EQ(unshaded_obstacles(fat, s, e, obstacles), pick(obstacles, {1, 3, 4}));
}

// ObstaclesInFront::covered == covered_from on random vertices (of a triangulation: it keys them by vertex) and
// obstacles above the side (-2, 0)-(2, 0), many behind others (seeded).
TEST(Shadows, ObstaclesInFrontAgreeWithCoveredFrom) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> coordinate(-4, 4), height(0.1, 4), length(0.1, 2);
  const Point s(-2, 0), e(2, 0);
  int covered = 0, open = 0;
  for (int round = 0; round < 40; ++round) {
    std::vector<Segment2> obstacles;
    for (int k = 0; k < 30; ++k) {
      const Point c1(coordinate(rng), height(rng));
      const double angle = coordinate(rng), l = length(rng);
      const Point c2(c1.x() + l * std::cos(angle), std::max(0.05, c1.y() + l * std::sin(angle)));
      obstacles.emplace_back(c1, c2);
    }
    const ObstaclesInFront in_front(s, e, obstacles);
    CDT cdt;
    for (int k = 0; k < 10; ++k) {
      const Vertex_handle v = cdt.insert(Point(coordinate(rng), height(rng)));
      v->info() = k;
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j <= 4; ++j) {
          const Point a(-2 + i, 0), b(-2 + j, 0);
          const bool expected = covered_from(v->point(), a, b, obstacles);
          ASSERT_EQ(in_front.covered(v, a, b), expected) << "round " << round << " v " << v->point();
          ++(expected ? covered : open);
        }
    }
  }
  EXPECT_GT(covered, 100);
  EXPECT_GT(open, 100);
}

}  // namespace
}  // namespace nonobtuse::refine2d
