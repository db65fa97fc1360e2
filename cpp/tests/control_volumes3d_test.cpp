#include "nonobtuse/control_volumes3d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace nonobtuse {
namespace {

// The unit cube cut into the six Kuhn tets around the diagonal 0 -> 7 (vertex v at (v & 1, v >> 1 & 1, v >> 2 & 1)).
// Its eight vertices are cospherical, so the Voronoi faces dual to the face diagonals and the long diagonal are
// single points: area exactly 0. Each cube edge's dual face, clipped to the cube, is a quarter square: > 0.
std::vector<Point3> cube_points() {
  std::vector<Point3> p;
  for (int v = 0; v < 8; ++v) p.push_back({double(v & 1), double(v >> 1 & 1), double(v >> 2 & 1)});
  return p;
}

double orientation(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  double u[3] = {b.x - a.x, b.y - a.y, b.z - a.z}, v[3] = {c.x - a.x, c.y - a.y, c.z - a.z},
         w[3] = {d.x - a.x, d.y - a.y, d.z - a.z};
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

std::vector<std::array<int, 4>> kuhn_tets(const std::vector<Point3>& p) {
  // The paths 0 -> 7 along the axes in every order: 0, e_a, e_a + e_b, 7 (vertex ids are coordinate bit sets).
  const int axes[6][2] = {{1, 2}, {1, 4}, {2, 1}, {2, 4}, {4, 1}, {4, 2}};
  std::vector<std::array<int, 4>> tets;
  for (const auto& a : axes) {
    std::array<int, 4> t = {0, a[0], a[0] + a[1], 7};
    // Integer coordinates: the determinant is exact, so this orients every tet positively.
    if (orientation(p[t[0]], p[t[1]], p[t[2]], p[t[3]]) < 0) std::swap(t[1], t[2]);
    tets.push_back(t);
  }
  return tets;
}

TEST(ControlVolumes3D, CubeDiagonalsAreExactlyZeroAndCubeEdgesPositive) {
  auto p = cube_points();
  auto r = control_volumes3d(p, kuhn_tets(p));
  ASSERT_EQ(r.edges.size(), 19u);  // 12 cube edges, 6 face diagonals, 1 long diagonal
  int zeros = 0;
  for (std::size_t e = 0; e < r.edges.size(); ++e) {
    int differ = __builtin_popcount(r.edges[e][0] ^ r.edges[e][1]);  // coordinates in which the ends differ
    EXPECT_EQ(r.signs[e], differ == 1 ? 1 : 0) << "edge " << r.edges[e][0] << "-" << r.edges[e][1];
    zeros += r.signs[e] == 0;
  }
  EXPECT_EQ(zeros, 7);
  EXPECT_GE(r.exact_evaluations, 7);  // an interval cannot prove a zero
}

TEST(ControlVolumes3D, CornerTetHasNegativeDualAreasOnTheEncroachedFace) {
  // Tet (0, e_x, e_y, e_z): vertex 0 lies inside the diametral sphere of the face (e_x, e_y, e_z) (distance
  // sqrt(1/3) from its circumcenter, radius sqrt(2/3)). The tet's circumcenter (1/2, 1/2, 1/2) lies beyond that
  // face. By hand, for the edge e_x -> e_y: M = C(0, e_x, e_y) = (1/2, 1/2, 0), so the piece is the triangle
  // (M, C_T, centroid of the face) and ((C_T - M) x (centroid - M)) . (e_y - e_x) = -1/6 < 0. Each axis edge
  // gets a quarter square (area 1/4 > 0).
  std::vector<Point3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  auto r = control_volumes3d(p, {{0, 1, 2, 3}});
  ASSERT_EQ(r.edges.size(), 6u);
  for (std::size_t e = 0; e < r.edges.size(); ++e)
    EXPECT_EQ(r.signs[e], r.edges[e][0] == 0 ? 1 : -1) << "edge " << r.edges[e][0] << "-" << r.edges[e][1];
  EXPECT_EQ(r.exact_evaluations, 0);
}

TEST(ControlVolumes3D, InvertedOrFlatTetIsInvalidInput) {
  std::vector<Point3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
  EXPECT_THROW(control_volumes3d(p, {{0, 2, 1, 3}}), InvalidInput);
  EXPECT_THROW(control_volumes3d(p, {{0, 1, 2, 4}}), InvalidInput);
  EXPECT_THROW(control_volumes3d(p, {{0, 1, 2, 5}}), InvalidInput);
  EXPECT_THROW(dual_area_signs(p, {{0, 2, 1, 3}}), InvalidInput);
  EXPECT_THROW(dual_area_signs(p, {{0, 1, 2, 5}}), InvalidInput);
}

TEST(ControlVolumes3D, FarFromTheOriginTheSignsAreUnchanged) {
  // Translating by 2^40 keeps every coordinate exact, so the exact signs must not move.
  auto p = cube_points();
  auto tets = kuhn_tets(p);
  auto near = control_volumes3d(p, tets);
  for (auto& q : p) q = {q.x + std::ldexp(1.0, 40), q.y - std::ldexp(1.0, 40), q.z + std::ldexp(1.0, 40)};
  auto far = control_volumes3d(p, tets);
  EXPECT_EQ(near.signs, far.signs);
  EXPECT_EQ(near.edges, far.edges);
}

TEST(ExactTetCircumspheres, RoundsEachNumberFromItsExactValue) {
  // The corner tet: center (1/2, 1/2, 1/2), squared radius 3/4 (exact in doubles), volume 1/6 (rounded: the double
  // nearest to 1/6 is 1.0 / 6.0, a correctly rounded division). Then the same corner with the apex 1e-310 over
  // the base plane instead of 1 (circumradius about 1e309: beyond the double range) and a coplanar tet.
  std::vector<Point3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.3, 0.3, 1e-310}, {1, 1, 0}};
  const auto r = exact_tet_circumspheres(p, {{0, 1, 2, 3}, {0, 1, 2, 4}, {0, 1, 2, 5}});
  EXPECT_EQ(r.centers[0].x, 0.5);
  EXPECT_EQ(r.centers[0].y, 0.5);
  EXPECT_EQ(r.centers[0].z, 0.5);
  EXPECT_EQ(r.squared_radii[0], 0.75);
  EXPECT_EQ(r.volumes[0], 1.0 / 6.0);
  EXPECT_EQ(r.squared_radii[1], std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::isinf(r.centers[1].z));
  EXPECT_GT(r.volumes[1], 0.0);
  EXPECT_LT(r.volumes[1], 1e-310);
  EXPECT_EQ(r.squared_radii[2], std::numeric_limits<double>::infinity());
  EXPECT_EQ(r.volumes[2], 0.0);
  EXPECT_THROW(exact_tet_circumspheres(p, {{0, 1, 2, 6}}), InvalidInput);
}

TEST(ExactTetCircumspheres, NearTheTopOfTheDoubleRangeRoundsToFiniteBelowAndInfAbove) {
  // A tet with a corner on each axis at distance s from the origin has its circumcenter at (s/2, s/2, s/2) and
  // squared radius 3 s^2 / 4: just below the largest double for the first s (finite, within 2^-50 of it), four
  // times that for 2 s (inf, where the rounding stopped at the largest double before).
  const double max = std::numeric_limits<double>::max();
  const double s = std::sqrt(max) / std::sqrt(0.75) * (1 - 0x1p-52);
  std::vector<Point3> p = {{0, 0, 0}, {s, 0, 0}, {0, s, 0}, {0, 0, s}, {2 * s, 0, 0}, {0, 2 * s, 0}, {0, 0, 2 * s}};
  const auto r = exact_tet_circumspheres(p, {{0, 1, 2, 3}, {0, 4, 5, 6}});
  EXPECT_TRUE(std::isfinite(r.squared_radii[0]));
  EXPECT_GT(r.squared_radii[0], (1 - 0x1p-50) * max);
  EXPECT_EQ(r.squared_radii[1], std::numeric_limits<double>::infinity());
  EXPECT_EQ(r.centers[1].x, s);  // (2 s) / 2, exact
}

}  // namespace
}  // namespace nonobtuse
