// Segment collars of the protected Gabriel strategy: the collar point of a split point (hand-checked), and, for two
// facets through a segment at a 10 degree dihedral angle, collar points that stay out of every piece's diametral
// ball (exact predicates on the rounded points).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "gabriel3d_collar.h"

namespace nonobtuse::gabriel3d {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The `held` test of collar_split_point over the diametral balls of the subsegments in chain.
std::function<bool(const P3&)> held_by(const std::vector<Key>& chain, const std::vector<P3>& points) {
  return [&chain, &points](const P3& y) {
    return std::any_of(chain.begin(), chain.end(), [&](const Key& sub) {
      return CGAL::side_of_bounded_sphere(points[sub.first], points[sub.second], y) == CGAL::ON_BOUNDED_SIDE;
    });
  };
}

TEST(Gabriel3DCollar, MovesAPointOnTheRayFromTheMidpointOntoTheCircle) {
  const std::vector<P3> points{{0, 0, 0}, {1, 0, 0}};
  // m = (0.5, 0, 0), radius 0.5: (0.5, 0.25, 0) goes to (0.5, 0.5, 0); the ray through (0.75, 0, 0) ends at q.
  const std::vector<Key> chain{{0, 1}};
  const auto y = collar_split_point(points[0], points[1], P3(0.5, 0.25, 0), held_by(chain, points));
  ASSERT_TRUE(y);
  EXPECT_EQ(*y, P3(0.5, 0.5, 0));
  EXPECT_FALSE(collar_split_point(points[0], points[1], P3(0.75, 0, 0), held_by(chain, points)));  // q itself
  EXPECT_FALSE(collar_split_point(points[0], points[1], P3(0.5, 0, 0), held_by(chain, points)));   // the midpoint
}

TEST(Gabriel3DCollar, RefusesADirectionThatIsRoundingNoise) {
  // Segments from (1000, 1000, 1000) along x (a unit in the last place is 1.1e-13 there). 2e-8 long (radius 1e-8):
  // a point one unit in the last place above the midpoint, off the facet's plane z = 1000, gives a direction of
  // pure noise; before (only c within 2^-26 of the radius, 1.5e-16, was refused) it was moved onto the circle, 1e-8
  // off the plane. 2e-4 long (radius 1e-4): a point 1e-5 from the midpoint in the plane (far above 2^20 units in
  // the last place, 2.3e-7) is moved onto the circle, in the plane.
  const std::vector<P3> points{{1000, 1000, 1000}, {1000 + 2e-8, 1000, 1000}, {1000 + 2e-4, 1000, 1000}};
  const std::vector<Key> chain{{0, 1}, {0, 2}};
  const P3 m = CGAL::midpoint(points[0], points[1]);
  const P3 noise(m.x(), m.y(), std::nextafter(1000.0, 2000.0));
  EXPECT_TRUE(noisy_direction(m, noise, 1e-8));
  EXPECT_FALSE(collar_split_point(points[0], points[1], noise, held_by({chain[0]}, points)));
  const P3 wide = CGAL::midpoint(points[0], points[2]), c(wide.x(), wide.y() + 1e-5, wide.z());
  EXPECT_FALSE(noisy_direction(wide, c, 1e-4));
  const auto y = collar_split_point(points[0], points[2], c, held_by({chain[1]}, points));
  ASSERT_TRUE(y);
  EXPECT_EQ(y->z(), 1000.0);
  EXPECT_NEAR(y->y() - 1000.0, 1e-4, 1e-12);
}

TEST(Gabriel3DCollar, TheFacetsNormalKeepsTheMovedPointOnItsPlane) {
  // A subsegment 2e4 long at coordinates 1e6 (a unit in the last place is 1.2e-10 there) in the facet z = 1e6, and a
  // split point 1e-3 from its midpoint in the plane but one unit in the last place above it (as a rounded point
  // can be): the move onto the circle (radius 1e4) multiplies that by 1e7. Along c - m the point lands 1e-3 off the
  // plane; with the facet's normal the direction is projected onto the plane and the point stays on it.
  const std::vector<P3> points{{1e6, 1e6, 1e6}, {1e6 + 2e4, 1e6, 1e6}};
  const P3 m = CGAL::midpoint(points[0], points[1]);
  const P3 c(m.x(), m.y() + 1e-3, std::nextafter(1e6, 2e6));
  const std::vector<Key> chain{{0, 1}};
  const auto held = held_by(chain, points);
  ASSERT_FALSE(noisy_direction(m, c, 1e4));
  const auto along = collar_split_point(points[0], points[1], c, held);
  ASSERT_TRUE(along);
  EXPECT_GT(along->z() - 1e6, 1e-4);
  const std::array<double, 3> normal{0.0, 0.0, 1.0};
  const auto y = collar_split_point(points[0], points[1], c, held, &normal);
  ASSERT_TRUE(y);
  EXPECT_EQ(y->z(), 1e6);
  EXPECT_NEAR(y->y() - 1e6, 1e4, 1e-6);
}

TEST(Gabriel3DCollar, PointsOfTwoFacetsAtTenDegreesStayOutOfEveryPieceBall) {
  // The segment [0, 1] on the x axis cut into pieces at 0, 0.25, 0.375, 0.5, 1; facet F is the half-plane y > 0 of
  // z = 0, facet G the half-plane at 10 degrees from it. Split points strictly inside a piece's ball, in F or G.
  std::vector<P3> points;
  for (double x : {0.0, 0.25, 0.375, 0.5, 1.0}) points.emplace_back(x, 0, 0);
  std::vector<Key> chain;
  for (int i = 0; i + 1 < static_cast<int>(points.size()); ++i) chain.push_back({i, i + 1});
  const double t = 10.0 * kPi / 180.0;
  const K::Vector_3 in_f(0, 1, 0), in_g(0, std::cos(t), std::sin(t));
  std::mt19937_64 rng(20261202);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int placed = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Key piece = chain[trial % chain.size()];
    const P3 &p = points[piece.first], &q = points[piece.second];
    const double r = 0.5 * (q.x() - p.x()), angle = kPi * unit(rng), rho = r * unit(rng);
    const K::Vector_3 side = trial % 2 ? in_g : in_f;
    const P3 c = CGAL::midpoint(p, q) + K::Vector_3(rho * std::cos(angle), 0, 0) + side * (rho * std::sin(angle));
    if (CGAL::side_of_bounded_sphere(p, q, c) != CGAL::ON_BOUNDED_SIDE) continue;
    const auto y = collar_split_point(p, q, c, held_by(chain, points));
    if (!y) continue;
    ++placed;
    for (const auto& [a, b] : chain)
      EXPECT_NE(CGAL::side_of_bounded_sphere(points[a], points[b], *y), CGAL::ON_BOUNDED_SIDE)
          << "collar point " << *y << " inside the ball of piece " << a << "-" << b;
    // On the piece's circle (to rounding) and in the facet's plane (exactly for F: z stays 0).
    EXPECT_NEAR(std::sqrt(CGAL::to_double(CGAL::squared_distance(*y, CGAL::midpoint(p, q)))), r, 1e-15);
    if (trial % 2 == 0) EXPECT_EQ(y->z(), 0.0);
  }
  EXPECT_GT(placed, 1900);  // only split points on the segment itself (rho sin(angle) ~ 0) may be refused
}

}  // namespace
}  // namespace nonobtuse::gabriel3d
