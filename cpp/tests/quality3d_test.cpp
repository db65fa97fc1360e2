#include "nonobtuse/quality3d.h"

#include "nonobtuse/gabriel3d.h"
#include "quality3d_shape.h"
#include "quality3d_small_angle.h"
#include "quality3d_spheres.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace nonobtuse {
namespace {

// The right triangle (0,0,0), (2,0,0), (0,2,0): its diametral sphere has center (1,1,0) and radius sqrt(2).
const std::vector<Point3> kCorners = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
const std::vector<Triangle> kFace = {{0, 1, 2}};

TEST(ClosedDiametralSphereHits, PointsOnTheSphereCountAndPointsOutsideDoNot) {
  // (1,1,sqrt 2) is not exact in doubles; (2,2,0) and (1,1,0) +- (0,0,sqrt 2) are replaced by points whose squared
  // distance to (1,1,0) is exactly 2: (2,2,0) (on), (1,1,1) (inside: 1 < 2), (2,2,1) (outside: 3 > 2).
  std::vector<Point3> candidates = {{2, 2, 0}, {1, 1, 1}, {2, 2, 1}, {0, 0, 0}};
  auto hits = closed_diametral_sphere_hits(kCorners, kFace, {}, candidates);
  ASSERT_EQ(hits.closed_face.size(), 4u);
  EXPECT_EQ(hits.closed_face[0], 0);   // on the sphere
  EXPECT_EQ(hits.closed_face[1], 0);   // inside
  EXPECT_EQ(hits.closed_face[2], -1);  // outside
  EXPECT_EQ(hits.closed_face[3], 0);   // a corner is on its sphere
  for (int s : hits.closed_segment) EXPECT_EQ(s, -1);
}

TEST(ClosedDiametralSphereHits, SegmentSphereHasTheSegmentAsDiameter) {
  // Segment (0,0,0)-(2,0,0): center (1,0,0), radius 1. (1,1,0) is on it, (1,1,1e-9) just outside, (1,0.5,0) inside.
  std::vector<Segment> segment = {{0, 1}};
  std::vector<Point3> candidates = {{1, 1, 0}, {1, 1, 1e-9}, {1, 0.5, 0}};
  auto hits = closed_diametral_sphere_hits(kCorners, {}, segment, candidates);
  EXPECT_EQ(hits.closed_segment[0], 0);
  EXPECT_EQ(hits.closed_segment[1], -1);
  EXPECT_EQ(hits.closed_segment[2], 0);
  for (int f : hits.closed_face) EXPECT_EQ(f, -1);
}

TEST(ClosedDiametralSphereHits, ReportsTheFirstRowAndRejectsBadSimplices) {
  std::vector<Triangle> twice = {{0, 1, 2}, {0, 1, 2}};
  auto hits = closed_diametral_sphere_hits(kCorners, twice, {}, {{1, 1, 0}});
  EXPECT_EQ(hits.closed_face[0], 0);
  EXPECT_THROW(closed_diametral_sphere_hits(kCorners, {{0, 1, 3}}, {}, {}), InvalidInput);
  EXPECT_THROW(closed_diametral_sphere_hits({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 1, 2}}, {}, {}), InvalidInput);
  EXPECT_THROW(closed_diametral_sphere_hits(kCorners, {}, {{1, 1}}, {}), InvalidInput);
}

}  // namespace
}  // namespace nonobtuse

namespace nonobtuse {
namespace {

// The unit cube split into 6 tets around the diagonal (0,0,0)-(1,1,1), with its 12 boundary triangles and
// 12 + 6 edges as segments: a fixed boundary and a coarse interior.
InteriorMesh cube_mesh() {
  InteriorMesh m;
  for (int i = 0; i < 8; ++i) m.points.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  m.tets = {{0, 1, 3, 7}, {0, 1, 7, 5}, {0, 2, 7, 3}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 7, 6}};
  m.tet_labels.assign(m.tets.size(), 0);
  m.faces = {{0, 1, 3}, {0, 3, 2}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
             {2, 3, 7}, {2, 7, 6}, {0, 2, 6}, {0, 6, 4}, {1, 3, 7}, {1, 7, 5}};
  return m;
}

// Balls of radii spread over nine orders of magnitude (a few large ones among many small, as the small-angle
// guards of u.off): for points at and around the balls, BallClasses offers a ball that holds the point whenever
// one does (exact distances decide), class by class.
TEST(BallClasses, OffersEveryBallHoldingThePointAcrossRadii) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), exponent(-6.0, 3.0);
  std::vector<gabriel3d::P3> centers;
  std::vector<double> radii;
  quality3d::BallClasses balls;
  for (int i = 0; i < 400; ++i) {
    centers.emplace_back(10 * unit(rng), 10 * unit(rng), 10 * unit(rng));
    radii.push_back(std::pow(10.0, exponent(rng)));
    balls.add({{centers[i].x(), centers[i].y(), centers[i].z()}, radii[i], false}, i);
  }
  balls.build();
  auto holds = [&](int i, const gabriel3d::P3& q) {
    return CGAL::compare_squared_distance(q, centers[i], radii[i] * radii[i]) != CGAL::LARGER;
  };
  int held = 0;
  for (int i = 0; i < 4000; ++i) {
    const int b = i % 400;  // about a ball: inside, near its sphere or outside, in a random direction
    const double d = radii[b] * (i % 3 == 0 ? 0.5 : i % 3 == 1 ? 0.999 : 1.2);
    gabriel3d::P3 q(unit(rng), unit(rng), unit(rng));
    const double n = std::sqrt(q.x() * q.x() + q.y() * q.y() + q.z() * q.z());
    q = gabriel3d::P3(centers[b].x() + d * q.x() / n, centers[b].y() + d * q.y() / n, centers[b].z() + d * q.z() / n);
    bool any = false;
    for (int j = 0; j < 400; ++j) any = any || holds(j, q);
    const int found = balls.first(q, [&](int j) { return holds(j, q); });
    held += any;
    ASSERT_EQ(found != quality3d::BallClasses::kNone, any) << "query " << i;
    if (any) EXPECT_TRUE(holds(found, q));
  }
  EXPECT_GT(held, 2000);  // the queries inside and near the spheres are held (the small balls lie far apart)
}

TEST(RefineInterior, CospherialCubeIsNotConformingAndChangesNothing) {
  // The cube's 8 corners are cospherical: the Delaunay tetrahedralization need not hold these face diagonals, and
  // every tet's circumcenter (the cube's center) lies in the faces' diametral spheres anyway.
  InteriorBounds bounds;
  bounds.volume_bounds = {0.01};
  auto r = refine_interior(cube_mesh(), bounds);
  EXPECT_EQ(r.inserted, 0);
  EXPECT_EQ(r.points.size(), 8u);
  EXPECT_TRUE(r.status == "not_conforming" || r.status == "blocked") << r.status;
}

TEST(RefineInterior, CenterInAFacesSphereIsBlockedAndElsewhereInserted) {
  // A regular tet of edge 2 sqrt 2: its circumcenter is its centroid (0,0,0), inside it, at distance 0.82 from each
  // face's circumcenter, inside that face's diametral sphere (radius 1.63).
  InteriorMesh m;
  m.points = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  m.tets = {{0, 1, 2, 3}};
  m.tet_labels = {0};
  InteriorBounds bounds;
  bounds.volume_bounds = {0.5};  // the tet's volume is 8/3, the four around its center 2/3 each
  // Without boundary faces the center is inserted; the new tets' centers lie outside the domain: blocked.
  auto free = refine_interior(m, bounds);
  ASSERT_EQ(free.inserted, 1);
  EXPECT_EQ(free.points.back().x, 0.0);
  EXPECT_EQ(free.tets.size(), 4u);
  EXPECT_EQ(free.status, "blocked");
  EXPECT_EQ(free.blocked_rows.size(), 4u);
  // With a face whose closed diametral sphere holds the center, nothing is inserted and the tet is blocked.
  m.faces = {{1, 2, 3}};
  auto blocked = refine_interior(m, bounds);
  EXPECT_EQ(blocked.inserted, 0);
  EXPECT_EQ(blocked.status, "blocked");
  ASSERT_EQ(blocked.blocked_rows.size(), 1u);
  EXPECT_NEAR(blocked.blocked_centers[0].x, 0.0, 1e-12);
  bounds.max_points = 0;  // the budget is a status
  EXPECT_EQ(refine_interior(m, bounds).status, "budget_exhausted");
}

// The regular tet of edge 2 sqrt 2 as a closed boundary: four facets of one face each, six subsegments.
InteriorMesh regular_tet_boundary() {
  InteriorMesh m;
  m.points = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  m.tets = {{0, 1, 2, 3}};
  m.tet_labels = {0};
  m.faces = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  m.face_facets = {0, 1, 2, 3};
  m.segments = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  return m;
}

double det3(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const double u[3] = {b.x - a.x, b.y - a.y, b.z - a.z}, v[3] = {c.x - a.x, c.y - a.y, c.z - a.z},
               w[3] = {d.x - a.x, d.y - a.y, d.z - a.z};
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

TEST(RefineInterior, BlockedCenterSplitsTheBoundaryAndTheResultStaysGabriel) {
  // The center (0,0,0) lies in every face's diametral sphere. Each face is equilateral, so its circumcenter lies in
  // the diametral spheres of its three edges (0.29 of the edge from their midpoints, radius 0.5 of it): Shewchuk's
  // rule splits the edges at their midpoints instead of inserting it.
  InteriorMesh m = regular_tet_boundary();
  InteriorBounds bounds;
  bounds.volume_bounds = {0.5};
  // the small-angle rule off: it would leave the tet alone (70.5 degree dihedrals, edges 54.7 degrees over faces)
  bounds.sharp_dihedral_degrees = bounds.small_apex_degrees = 0;
  auto r = refine_interior(m, bounds);
  ASSERT_EQ(r.status, "converged");
  EXPECT_GE(r.boundary_rounds, 1);
  EXPECT_GE(r.boundary_points, 6);
  for (const auto& [i, j] : m.segments) {
    const Point3 mid{(m.points[i].x + m.points[j].x) / 2, (m.points[i].y + m.points[j].y) / 2,
                     (m.points[i].z + m.points[j].z) / 2};
    EXPECT_TRUE(std::any_of(r.points.begin(), r.points.end(),
                            [&](const Point3& p) { return p.x == mid.x && p.y == mid.y && p.z == mid.z; }))
        << "midpoint of " << i << ", " << j;
  }
  // The boundary as returned: Gabriel (exact), its subfacets oriented away from the tet's inside, covering the
  // surface; the tets fill the tet's volume 8/3 and meet the bound.
  const GabrielReport report = check_gabriel(r.points, r.faces, r.segments);
  EXPECT_TRUE(report.faces.empty() && report.segments.empty());
  ASSERT_EQ(r.face_facets.size(), r.faces.size());
  double volume = 0;
  for (const auto& t : r.tets) {
    const double v = det3(r.points[t[0]], r.points[t[1]], r.points[t[2]], r.points[t[3]]) / 6;
    EXPECT_LE(v, 0.5);
    volume += v;
  }
  EXPECT_NEAR(volume, 8.0 / 3, 1e-12);
  for (const auto& f : r.faces) EXPECT_LT(det3(r.points[f[0]], r.points[f[1]], r.points[f[2]], {0, 0, 0}), 0);
  // Without facet ids the boundary is fixed: the tet stays, blocked.
  m.face_facets.clear();
  auto fixed = refine_interior(m, bounds);
  EXPECT_EQ(fixed.status, "blocked");
  EXPECT_EQ(fixed.points.size(), 4u);
  m.face_facets = {0, 1};
  EXPECT_THROW(refine_interior(m, bounds), InvalidInput);
}

TEST(RefineInterior, SameOutputOnEveryCallInOneProcess) {
  // Boundary points on the hull make infinite cells; their labels were left as the allocator's memory had them, so a
  // second identical call (memory reused) could take an infinite cell for the domain side of a subfacet and orient
  // it the wrong way. Every call: the same rows, every subfacet facing away from the tet's inside (the origin).
  InteriorBounds bounds;
  bounds.volume_bounds = {0.5};
  bounds.sharp_dihedral_degrees = bounds.small_apex_degrees = 0;
  const auto first = refine_interior(regular_tet_boundary(), bounds);
  for (int call = 0; call < 3; ++call) {
    const auto r = refine_interior(regular_tet_boundary(), bounds);
    EXPECT_EQ(r.faces, first.faces);
    EXPECT_EQ(r.tets, first.tets);
    for (const auto& f : r.faces) EXPECT_LT(det3(r.points[f[0]], r.points[f[1]], r.points[f[2]], {0, 0, 0}), 0);
  }
}

InteriorMesh wedge_tet_boundary() {
  // A wedge: edge 0-1 of length 2 on the x axis, edge 2-3 of length 0.2 across it. Circumcenter (0, 0.005, 0),
  // circumradius 1.0000, radius-edge ratio 5.0; the center lies in the diametral sphere of edge 0-1 (the origin,
  // radius 1), where faces 0-1-2 and 0-1-3 meet at 11.4 degrees. Every face's diametral sphere is empty (the
  // boundary is Gabriel: for face 0-1-2, point 3 is 1.0001 from its center, radius 1.00001).
  InteriorMesh m = regular_tet_boundary();  // its faces, facets and segments, with these corners
  m.points = {{-1, 0, 0}, {1, 0, 0}, {0, 1, -0.1}, {0, 1, 0.1}};
  return m;
}

// The single tet of a four-point input left alone by the small-angle rule: counted, nothing added.
void expect_the_one_tet_left_alone(const InteriorRefinement& r) {
  EXPECT_EQ(r.status, "converged");
  EXPECT_EQ(r.points.size(), 4u);
  EXPECT_EQ(r.boundary_points, 0);
  EXPECT_EQ(r.blocked_rows, std::vector<int>{0});
  EXPECT_EQ(r.small_angle_rows, std::vector<int>{0});
}

TEST(RefineInterior, SmallAngleRuleLeavesTheTetAloneAndCountsIt) {
  // Over the radius-edge bound alone, its center in the spheres of edge 0-1 and of the faces through it: the split it
  // asks for is edge 0-1's midpoint, on a sharp segment and in its protecting region. Left alone, counted, nothing
  // added.
  InteriorMesh m = wedge_tet_boundary();
  InteriorBounds bounds;
  bounds.radius_edge = 2;
  bounds.volume_bounds = {std::numeric_limits<double>::infinity()};
  expect_the_one_tet_left_alone(refine_interior(m, bounds));
  // With the clauses off (the dihedral one below 11.4 degrees) the edge is split, and the two facets at 11.4
  // degrees encroach each other's pieces until min_length refuses a split: what the rule is for.
  bounds.sharp_dihedral_degrees = 5;
  bounds.small_apex_degrees = 0;
  bounds.min_length = 0.05;
  auto split = refine_interior(m, bounds);
  EXPECT_EQ(split.status, "boundary_stopped");
  EXPECT_GE(split.boundary_points, 1);
  EXPECT_GE(split.refused_splits, 1);
  EXPECT_TRUE(split.small_angle_rows.empty());
}

TEST(RefineInterior, SmallAngleRuleForATetOverTheVolumeBoundTakesOnlyAnglesBelow60) {
  // The regular tet: its facets meet at dihedral angles of acos(1/3) = 70.53 degrees (below the default 85: every
  // edge is sharp) and each edge leans over the facets through its ends at acos(1/sqrt 3) = 54.74 degrees (below
  // 60: every corner is a sharp apex). Its center (0,0,0) is in every face's diametral sphere and every split it
  // asks for lies at a sharp feature and in its protecting region: over the volume bound, it is left alone, counted,
  // nothing is added.
  InteriorMesh m = regular_tet_boundary();
  InteriorBounds bounds;
  bounds.volume_bounds = {0.5};
  expect_the_one_tet_left_alone(refine_interior(m, bounds));
  // The apex clause at 50 degrees: the 70.53-degree edges are sharp under the dihedral clause's 85, but for a tet
  // over the volume bound only angles below volume_sharp_degrees (59.99) count: the tet is split for, every tet
  // ends within the bound.
  bounds.small_apex_degrees = 50;
  auto split = refine_interior(m, bounds);
  EXPECT_EQ(split.status, "converged");
  EXPECT_GE(split.boundary_points, 6);
  EXPECT_TRUE(split.small_angle_rows.empty());
  for (const auto& t : split.tets)
    EXPECT_LE(std::abs(det3(split.points[t[0]], split.points[t[1]], split.points[t[2]], split.points[t[3]])) / 6,
              0.5);
  // With volume_sharp_degrees at 85 as well, the dihedral clause leaves it alone again.
  bounds.volume_sharp_degrees = 85;
  EXPECT_EQ(refine_interior(m, bounds).small_angle_rows, std::vector<int>{0});
}

TEST(RefineInterior, RefusedBoundarySplitsLeaveTheTetsBlocked) {
  // min_length longer than the edges: every split is refused and counted; nothing changes.
  InteriorMesh m = regular_tet_boundary();
  InteriorBounds bounds;
  bounds.volume_bounds = {0.5};
  bounds.sharp_dihedral_degrees = bounds.small_apex_degrees = 0;
  bounds.min_length = 10.0;
  auto r = refine_interior(m, bounds);
  EXPECT_EQ(r.status, "blocked");
  EXPECT_EQ(r.points.size(), 4u);
  EXPECT_GT(r.refused_splits, 0);
  EXPECT_EQ(r.boundary_points, 0);
}

TEST(RefineInterior, InsertsGivenPointsOnlyInsideTheDomainAndOutsideEverySphere) {
  InteriorMesh m;
  m.points = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  m.tets = {{0, 1, 2, 3}};
  m.tet_labels = {0};
  m.insert = {{0.1, 0.1, 0.1}, {5, 5, 5}, {1, 1, 1}};  // inside; outside the domain; a vertex
  InteriorBounds bounds;
  bounds.volume_bounds = {100.0};
  auto r = refine_interior(m, bounds);
  EXPECT_EQ(r.placed, 1);
  EXPECT_EQ(r.inserted, 0);
  ASSERT_EQ(r.points.size(), 5u);
  EXPECT_EQ(r.points[4].x, 0.1);
  EXPECT_EQ(r.tets.size(), 4u);
  // (0.1, 0.1, 0.1) is 0.75 from the face's sphere center (-1/3, -1/3, -1/3), radius 1.63: dropped
  m.faces = {{1, 2, 3}};
  EXPECT_EQ(refine_interior(m, bounds).placed, 0);
}

TEST(RefineInterior, RejectsLabelsWithoutBounds) {
  InteriorMesh m = cube_mesh();
  InteriorBounds bounds;  // no volume bound for label 0
  EXPECT_THROW(refine_interior(m, bounds), InvalidInput);
}

}  // namespace
}  // namespace nonobtuse

namespace nonobtuse {
namespace {

// A rectangle p0, p0 + u, p0 + v, p0 + u + v (u . v = 0) in a tilted plane: its corners rounded off the plane,
// floating point makes its circumcenter (0.225, 0.7, 0.55), far from the rectangle's center p0 + (u + v) / 2 =
// (0.3, 0.8, 0.4); the circumradius is half the diagonal, sqrt(0.14 + 0.10) / 2.
TEST(TetShape, FlatInFloatingPointIsExactAndFinite) {
  const quality3d::P3 a(0.1, 0.7, 0.3), u(0.1, 0.2, 0.3), v(0.3, 0.0, -0.1);
  const quality3d::P3 b(a.x() + u.x(), a.y() + u.y(), a.z() + u.z()), c(a.x() + v.x(), a.y() + v.y(), a.z() + v.z());
  const quality3d::P3 d(b.x() + v.x(), b.y() + v.y(), b.z() + v.z());
  const quality3d::TetShape shape = quality3d::tet_shape(a, b, c, d);
  EXPECT_TRUE(shape.exact);
  EXPECT_NEAR(shape.center.x(), 0.3, 1e-9);
  EXPECT_NEAR(shape.center.y(), 0.8, 1e-9);
  EXPECT_NEAR(shape.center.z(), 0.4, 1e-9);
  EXPECT_NEAR(shape.squared_radius, 0.24 / 4, 1e-12);
}

TEST(TetShape, AFullTetIsFloatingPoint) {
  const quality3d::TetShape shape = quality3d::tet_shape({0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2});
  EXPECT_FALSE(shape.exact);
  EXPECT_EQ(shape.center, quality3d::P3(1, 1, 1));
  EXPECT_DOUBLE_EQ(shape.squared_radius, 3.0);
}

}  // namespace
}  // namespace nonobtuse

namespace nonobtuse {
namespace {

// A prism of length 8 and height 1 over a 10-degree wedge (apex edge x = y = 0, z in [0, 1]), its long sides in
// unit strips: the apex edge is the one sharp segment (10 degrees), its ends the sharp apexes. The protecting
// region holds the ball of radius 1 around the edge's midpoint, the balls of radius 1 around the apexes and the
// diametral spheres of the first strip's triangles (corners on the edge): (0.5, 0, 0.5) is in it, (5, 0, 0.5) is not
// (distance 4 from the first strip, whose corners have x <= 1).
TEST(SharpFeatures, TheProtectingRegionIsNearTheSharpEdgeOnly) {
  const double t = std::tan(5.0 * 3.14159265358979323846 / 180.0);
  PLC3 plc;
  plc.points = {{0, 0, 0}, {0, 0, 1}};
  auto side = [&](int i, int sign, int z) { return 2 + 4 * (i - 1) + 2 * (sign > 0) + z; };  // x = i, y = sign t i
  for (int i = 1; i <= 8; ++i)
    for (int sign : {-1, 1})
      for (int z = 0; z <= 1; ++z) plc.points.push_back({double(i), sign * t * i, double(z)});
  auto add = [&](int facet, Triangle tri) { plc.triangles.push_back(tri), plc.facet_ids.push_back(facet); };
  for (int z = 0; z <= 1; ++z) {  // bottom (0) and top (1): the apex triangle, then quads
    add(z, {z, side(1, -1, z), side(1, 1, z)});
    for (int i = 1; i < 8; ++i) {
      add(z, {side(i, -1, z), side(i + 1, -1, z), side(i + 1, 1, z)});
      add(z, {side(i, -1, z), side(i + 1, 1, z), side(i, 1, z)});
    }
  }
  for (int sign : {-1, 1}) {  // the long sides (2, 3): the first strip from the apex edge, then quads
    const int f = sign < 0 ? 2 : 3;
    add(f, {0, side(1, sign, 0), side(1, sign, 1)}), add(f, {0, side(1, sign, 1), 1});
    for (int i = 1; i < 8; ++i) {
      add(f, {side(i, sign, 0), side(i + 1, sign, 0), side(i + 1, sign, 1)});
      add(f, {side(i, sign, 0), side(i + 1, sign, 1), side(i, sign, 1)});
    }
  }
  add(4, {side(8, -1, 0), side(8, 1, 0), side(8, 1, 1)}), add(4, {side(8, -1, 0), side(8, 1, 1), side(8, -1, 1)});
  const gabriel3d::PlcState s = gabriel3d::build_plc_state(plc);
  const quality3d::SharpFeatures features(s, 85, 60);
  EXPECT_TRUE(features.sharp_subsegment(s, 0, 1));
  EXPECT_FALSE(features.sharp_subsegment(s, side(8, -1, 0), side(8, 1, 0)));
  EXPECT_TRUE(features.protects(s, {0.5, 0, 0.5}));
  EXPECT_FALSE(features.protects(s, {5, 0, 0.5}));
  EXPECT_FALSE(features.protects(s, {2.5, 0, 0.5}));
  // with the angle clauses off nothing is sharp or protected
  const quality3d::SharpFeatures none(s, 0, 0);
  EXPECT_FALSE(none.sharp_subsegment(s, 0, 1));
  EXPECT_FALSE(none.protects(s, {0.5, 0, 0.5}));
}

}  // namespace
}  // namespace nonobtuse
