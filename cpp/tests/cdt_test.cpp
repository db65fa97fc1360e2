#include "cdt.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <utility>
#include <vector>

#include "nonobtuse/triangulate.h"

namespace nonobtuse {
namespace {

Domain2 square_with_hole() {
  Domain2 d;
  d.points = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {3, 1}, {3, 3}, {1, 3}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  d.holes = {{2, 2}};
  return d;
}

// is_simple_pslg, hand-worked on the square with a hole (simple) and with one change each: a segment through a hole
// corner ((0, 0)-(3, 3) passes (1, 1)), the hole's two diagonals (they cross at (2, 2)), a point inside the side
// (0, 0)-(4, 0), that side repeated (reversed); one diagonal alone and a free point in the hole stay simple.
TEST(Cdt, IsSimplePslg) {
  const Domain2 d = square_with_hole();
  EXPECT_TRUE(cdt::is_simple_pslg(d.points, d.segments));
  auto with = [&](std::vector<Point2> extra_points, std::vector<Segment> extra) {
    Domain2 e = d;
    e.points.insert(e.points.end(), extra_points.begin(), extra_points.end());
    e.segments.insert(e.segments.end(), extra.begin(), extra.end());
    return cdt::is_simple_pslg(e.points, e.segments);
  };
  EXPECT_FALSE(with({}, {{0, 6}}));
  EXPECT_FALSE(with({}, {{5, 7}, {4, 6}}));
  EXPECT_FALSE(with({{2, 0}}, {}));
  EXPECT_FALSE(with({}, {{1, 0}}));
  EXPECT_TRUE(with({}, {{5, 7}}));
  EXPECT_TRUE(with({{2, 2}}, {}));
}

// The curve's first 4^8 cells fill the 256 x 256 corner at the origin, each next to the one before; it ends at
// (2^16 - 1, 0).
TEST(HilbertIndex, ConsecutiveCellsAreNeighbours) {
  std::vector<std::pair<int, int>> cell(1 << 16, {-1, -1});
  for (int x = 0; x < 256; ++x)
    for (int y = 0; y < 256; ++y) {
      std::uint32_t d = cdt::hilbert_index(x, y);
      ASSERT_LT(d, cell.size()) << x << " " << y;
      ASSERT_EQ(cell[d].first, -1) << d;
      cell[d] = {x, y};
    }
  for (std::size_t d = 1; d < cell.size(); ++d)
    ASSERT_EQ(std::abs(cell[d].first - cell[d - 1].first) + std::abs(cell[d].second - cell[d - 1].second), 1) << d;
  EXPECT_EQ(cdt::hilbert_index(0, 0), 0u);
  EXPECT_EQ(cdt::hilbert_index(65535, 0), 0xffffffffu);
}

TEST(Triangulate, SquareWithHoleKeepsOnlyTheRing) {
  Mesh2 m = triangulate(square_with_hole());
  EXPECT_EQ(m.points.size(), 8u);
  EXPECT_EQ(m.triangles.size(), 8u);  // a ring of 8 vertices, 2 loops: 8 triangles
  EXPECT_EQ(m.segments.size(), 8u);
  for (const auto& t : m.triangles) {
    const auto &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]];
    EXPECT_GT((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x), 0.0) << "triangles are counter-clockwise";
  }
}

TEST(Triangulate, InnerLoopWithoutHoleSeedIsARegion) {
  Domain2 d = square_with_hole();
  d.holes.clear();
  d.regions = {{{2, 2}, 7.0}, {{0.5, 0.5}, 3.0}};
  Mesh2 m = triangulate(d);
  EXPECT_EQ(m.triangles.size(), 10u);
  int inner = 0;
  for (double r : m.triangle_region) inner += r == 7.0;
  EXPECT_EQ(inner, 2);
  for (double r : m.triangle_region) EXPECT_TRUE(r == 7.0 || r == 3.0);
}

TEST(Triangulate, PointSetUsesConvexHull) {
  Domain2 d;
  d.points = {{0, 0}, {2, 0}, {1, 0.2}, {1, 1}, {0.5, 0.4}};
  d.convex_hull_boundary = true;
  Mesh2 m = triangulate(d);
  EXPECT_EQ(m.triangles.size(), 5u);  // n = 5 points, h = 3 on the hull: 2n - h - 2 triangles
  EXPECT_EQ(m.segments.size(), 3u);   // the hull edges became boundary segments
}

TEST(Triangulate, CollinearPointsWithAHoleSeedHaveNoTriangle) {
  Domain2 d;
  d.points = {{0, 0}, {1, 1}, {2, 2}};
  d.holes = {{0.5, 0.5}};
  d.convex_hull_boundary = true;
  EXPECT_THROW(triangulate(d), InvalidInput);
}

TEST(Triangulate, CrossingSegmentsAreRefused) {
  Domain2 d;
  d.points = {{0, 0}, {1, 1}, {0, 1}, {1, 0}};
  d.segments = {{0, 1}, {2, 3}};
  EXPECT_THROW(triangulate(d), InvalidInput);
}

TEST(Triangulate, DuplicatePointsAreRefused) {
  Domain2 d;
  d.points = {{0, 0}, {1, 0}, {0, 1}, {1, 0}};
  d.convex_hull_boundary = true;
  EXPECT_THROW(triangulate(d), InvalidInput);
}

}  // namespace
}  // namespace nonobtuse
