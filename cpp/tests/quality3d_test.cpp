#include "nonobtuse/quality3d.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

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
  // Its stand-in lies high in that face's sphere, on the tet's side: center (-1/3, -1/3, -1/3), radius
  // sqrt(24) / 3, direction (1, 1, 1) / sqrt(3), height 15/16 of the radius (inside the tet: x + y + z > -1 and
  // the other three faces' inequalities hold at 0.55 per coordinate).
  ASSERT_EQ(blocked.stand_ins.size(), 1u);
  const double expected = -1.0 / 3 + std::sqrt(24.0) / 3 * 15.0 / 16 / std::sqrt(3.0);
  EXPECT_NEAR(blocked.stand_ins[0].x, expected, 1e-12);
  EXPECT_NEAR(blocked.stand_ins[0].y, expected, 1e-12);
  EXPECT_NEAR(blocked.stand_ins[0].z, expected, 1e-12);
  bounds.max_points = 0;  // the budget is a status
  EXPECT_EQ(refine_interior(m, bounds).status, "budget_exhausted");
}

TEST(RefineInterior, RemovedPointLeavesItsStarToOneTetAndCompactsIndices) {
  // A regular tet split at an interior point into four; removing the point leaves the one tet of the corners,
  // labelled as the star was, and the point's index gone.
  InteriorMesh m;
  m.points = {{1, 1, 1}, {0.25, 0.5, -0.25}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  m.tets = {{1, 2, 3, 4}, {0, 1, 3, 4}, {0, 2, 1, 4}, {0, 2, 3, 1}};
  m.tet_labels = {0, 0, 0, 0};
  m.faces = {{2, 3, 4}};
  m.remove = {1};
  InteriorBounds bounds;
  bounds.volume_bounds = {100.0};
  auto r = refine_interior(m, bounds);
  ASSERT_EQ(r.status, "converged");
  ASSERT_EQ(r.points.size(), 4u);
  EXPECT_EQ(r.points[1].x, 1.0);  // the old point 2
  ASSERT_EQ(r.tets.size(), 1u);
  auto corners = r.tets[0];
  std::sort(corners.begin(), corners.end());
  EXPECT_EQ(corners, (std::array<int, 4>{0, 1, 2, 3}));
  EXPECT_EQ(r.tet_labels, std::vector<int>{0});
  m.remove = {2};  // a corner of a face
  EXPECT_THROW(refine_interior(m, bounds), InvalidInput);
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
