#include "nonobtuse/plc_predicates.h"

#include <gtest/gtest.h>

#include "nonobtuse/types.h"

namespace nonobtuse {
namespace {

TEST(PlcPredicates, Orient3dSignsAndCoplanarity) {
  std::vector<PlcPoint> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.25, 0.25, 0}};
  // CGAL::orientation(p, q, r, s) has the sign of det[q-p, r-p, s-p]: det[(1,0,0),(0,1,0),(0,0,1)] = 1 > 0;
  // swapping q and r negates it; (0.25, 0.25, 0) lies in the plane z = 0.
  auto s = orient3d_signs(p, {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 1, 2, 4}});
  EXPECT_EQ(s[0], 1);
  EXPECT_EQ(s[1], -1);
  EXPECT_EQ(s[2], 0);
}

TEST(PlcPredicates, CollinearIsExact) {
  // 0.1 is not representable: (0,0,0), (0.1,0.1,0.1), (0.3,0.3,0.3) are still exactly collinear (equal
  // coordinates per point); (0,0,0), (1,1,1), (3, 3, 3 + 4.4e-16) is not.
  std::vector<PlcPoint> p = {{0, 0, 0}, {0.1, 0.1, 0.1}, {0.3, 0.3, 0.3}, {1, 1, 1}, {3, 3, 3 + 4.4e-16}};
  auto c = collinear_flags(p, {{0, 1, 2}, {0, 3, 4}});
  EXPECT_EQ(c[0], 1);
  EXPECT_EQ(c[1], 0);
}

TEST(PlcPredicates, SelfIntersectionsIgnoreSharedEdgesButSeeFolds) {
  // Two triangles sharing edge 0-1. Apex 2 above, apex 3 below: a proper fold, no intersection.
  // Apex 4 coplanar with 0,1,2 and on the same side as 2: the triangles overlap.
  std::vector<PlcPoint> p = {{0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {1, -1, 0.5}, {1, 0.5, 0}};
  EXPECT_TRUE(triangle_soup_self_intersections(p, {{0, 1, 2}, {1, 0, 3}}, 10).empty());
  auto pairs = triangle_soup_self_intersections(p, {{0, 1, 2}, {1, 0, 4}}, 10);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0][0], 0);
  EXPECT_EQ(pairs[0][1], 1);
}

TEST(PlcPredicates, SelfIntersectionsSharedVertexAndDisjoint) {
  // Triangle A in z=0; triangle B shares vertex 0 and pierces A: its opposite edge (5,6) goes through A's
  // interior at (0.5, 0.25, 0)... B = (0, (0.5,0.25,-1), (0.5,0.25,1)): the edge from 5 to 6 crosses z=0 at
  // (0.5, 0.25), inside A = (0,0,0),(2,0,0),(0,2,0). Triangle C = (7,8,9) far away.
  std::vector<PlcPoint> p = {{0, 0, 0},   {2, 0, 0},   {0, 2, 0},    {9, 9, 9}, {9, 9, 9},
                             {0.5, 0.25, -1}, {0.5, 0.25, 1}, {5, 5, 5}, {6, 5, 5}, {5, 6, 5}};
  auto pairs = triangle_soup_self_intersections(p, {{0, 1, 2}, {0, 5, 6}, {7, 8, 9}}, 10);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0][1], 1);
}

TEST(PlcPredicates, DelaunayOfACubeHasPositiveCellsAndRejectsDuplicates) {
  std::vector<PlcPoint> p;
  for (int i = 0; i < 8; ++i) p.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  auto cells = delaunay_tetrahedra(p);
  ASSERT_GE(cells.size(), 5u);  // a cube splits into 5 or 6 tetrahedra (co-spherical: either)
  auto s = orient3d_signs(p, cells);
  for (auto x : s) EXPECT_EQ(x, 1);
  p.push_back({1, 1, 1});
  EXPECT_THROW(delaunay_tetrahedra(p), InvalidInput);
}

}  // namespace
}  // namespace nonobtuse
