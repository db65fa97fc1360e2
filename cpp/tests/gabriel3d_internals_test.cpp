// Internals of the 3D Gabriel refinement: rounded_circumcenter (subfacet split points, needles too), the edges the
// kept tetrahedralization lacks, PointIndex and the repair order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "gabriel3d_index.h"
#include "gabriel3d_refiner.h"

namespace nonobtuse::gabriel3d {
namespace {

TEST(Gabriel3DCircumcenter, NeedleTriangleGetsTheExactCenterRounded) {
  // Apex 1e-200 above the midpoint of a unit base: the floating-point construction divides by
  // 2 |(b - a) x (c - a)|^2 = 2e-400, which underflows to 0 (before the fix: NaN coordinates, and GMP raised SIGFPE
  // when the facet's exact 2D triangulation read them). The exact center: x = 0.5 and, from
  // 0.25 + y^2 = (y - h)^2, y = (h^2 - 0.25) / (2 h) = -1.25e199 for h = 1e-200 (to rounding).
  const double h = 1e-200;
  const P3 a(0, 0, 0), b(1, 0, 0), c(0.5, h, 0);
  double num_x, num_y, num_z, den;  // the floating-point construction's denominator (CGAL::circumcenter's)
  CGAL::determinants_for_circumcenterC3(a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), c.x(), c.y(), c.z(), num_x, num_y,
                                        num_z, den);
  ASSERT_EQ(den, 0.0);
  auto center = rounded_circumcenter(a, b, c);
  ASSERT_TRUE(center.has_value());
  EXPECT_EQ(center->x(), 0.5);
  EXPECT_NEAR(center->y() / (-0.25 / (2 * h)), 1.0, 1e-12);
  EXPECT_EQ(center->z(), 0.0);
}

TEST(Gabriel3DCircumcenter, CollinearHasNone) {
  EXPECT_FALSE(rounded_circumcenter(P3(0, 0, 0), P3(1, 1, 1), P3(2, 2, 2)).has_value());
}

TEST(Gabriel3DCircumcenter, OrdinaryTriangleUsesTheFloatingPointCenter) {
  // Right triangle: the center is the hypotenuse's midpoint (0.5, 0.5, 0), exact in doubles.
  auto center = rounded_circumcenter(P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0));
  ASSERT_TRUE(center.has_value());
  EXPECT_EQ(*center, P3(0.5, 0.5, 0));
}

TEST(Gabriel3DDelaunayRounds, MissingEdgesAreTheDiagonalTheCosphericalChoiceLeftOut) {
  // A square pyramid: the base's four corners are cocircular, so the tetrahedralization has one of its two
  // diagonals (CGAL's symbolic perturbation chooses); the base's sides and the pyramid's edges are all edges.
  PLC3 plc;
  plc.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}};
  plc.triangles = {{0, 2, 1}, {0, 3, 2}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  plc.facet_ids = {0, 0, 1, 2, 3, 4};
  const PlcState s = build_plc_state(plc);
  DelaunayRounds delaunay;
  delaunay.restrict(s, plc);
  const std::vector<Key> diagonals{key(0, 2), key(1, 3)};
  const std::vector<Key> missing = delaunay.missing_edges(diagonals);
  ASSERT_EQ(missing.size(), 1u);
  EXPECT_TRUE(missing[0] == diagonals[0] || missing[0] == diagonals[1]);
  EXPECT_TRUE(delaunay.missing_edges({key(0, 1), key(1, 2), key(2, 3), key(0, 3), key(0, 4), key(2, 4)}).empty());
}

}  // namespace
}  // namespace nonobtuse::gabriel3d

namespace nonobtuse::gabriel3d {
namespace {

TEST(Gabriel3DPointIndex, GrowingIndexFindsWhatBruteForceFinds) {
  // Points added one at a time across several rebuilds (pending list > max(256, 4 sqrt(n))); every query must
  // visit each point strictly within the ball (it may visit a few more just outside: the caller decides exactly).
  std::vector<P3> points;
  auto next = [state = 12345u]() mutable {
    state = state * 1103515245u + 12345u;
    return (state >> 8) / double(1 << 24);
  };
  for (int i = 0; i < 64; ++i) points.emplace_back(next(), next(), next());
  points.reserve(6000);
  PointIndex index(points);
  for (int i = 64; i < 6000; ++i) {
    points.emplace_back(next(), next(), next());
    index.add(i);
    if (i % 500 != 0) continue;
    SearchBall ball{{next(), next(), next()}, 0.2, false};
    std::vector<bool> seen(points.size(), false);
    index.for_each_in(ball, [&](int t) { seen[t] = true; });
    const P3 c(ball.center[0], ball.center[1], ball.center[2]);
    for (std::size_t t = 0; t < points.size(); ++t)
      if (CGAL::compare_squared_distance(points[t], c, 0.04) == CGAL::SMALLER) EXPECT_TRUE(seen[t]) << t;
  }
}

}  // namespace
}  // namespace nonobtuse::gabriel3d

namespace nonobtuse::gabriel3d {
namespace {

// The faces of scattered_order's result as sorted corner triples, in its order.
std::vector<Triangle> in_scattered_order(const std::vector<Triangle>& faces) {
  std::vector<Triangle> out;
  for (std::size_t i : scattered_order(faces)) {
    Triangle t = faces[i];
    std::sort(t.begin(), t.end());
    out.push_back(t);
  }
  return out;
}

TEST(Gabriel3DRepairOrder, DependsOnTheSetOfFacesAlone) {
  // The two triangles of every square of a 12 x 12 grid of points (index 13 i + j).
  std::vector<Triangle> faces;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) {
      const int p = 13 * i + j;
      faces.push_back({p, p + 1, p + 14});
      faces.push_back({p, p + 14, p + 13});
    }
  const std::vector<std::size_t> order = scattered_order(faces);
  std::vector<std::size_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);  // a permutation
  // The same faces in reverse row order, each row rotated (as another cell order would give them) or reversed.
  std::vector<Triangle> other(faces.rbegin(), faces.rend());
  for (std::size_t i = 0; i < other.size(); ++i) {
    Triangle& t = other[i];
    if (i % 3 == 1) t = {t[1], t[2], t[0]};
    if (i % 3 == 2) t = {t[2], t[1], t[0]};
  }
  EXPECT_EQ(in_scattered_order(other), in_scattered_order(faces));
  // Scattered: not the order of the smallest corner, which keeps the faces around a point together.
  const std::vector<Triangle> result = in_scattered_order(faces);
  EXPECT_FALSE(std::is_sorted(result.begin(), result.end()));
}

}  // namespace
}  // namespace nonobtuse::gabriel3d
