#include "nonobtuse/quality3d.h"

#include <gtest/gtest.h>

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
