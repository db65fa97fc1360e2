#include "nonobtuse/plc_predicates.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

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

// Two unit cubes side by side, [0,1]^3 and [1,2]x[0,1]^2, with the square x = 1 between them as an internal facet
// (facet 9). Point 4 * x + 2 * y + z for the corners at x = 0, 1, 2.
PLC3 two_cubes_sharing_a_face() {
  PLC3 plc;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 2; ++y)
      for (int z = 0; z < 2; ++z) plc.points.push_back({double(x), double(y), double(z)});
  auto id = [](int x, int y, int z) { return 4 * x + 2 * y + z; };
  auto square = [&](int a, int b, int c, int d, int facet) {
    plc.triangles.push_back({a, b, c});
    plc.triangles.push_back({a, c, d});
    plc.facet_ids.insert(plc.facet_ids.end(), {facet, facet});
  };
  int facet = 0;
  for (int x = 0; x < 2; ++x) {  // bottom, top, front, back of each cube
    square(id(x, 0, 0), id(x + 1, 0, 0), id(x + 1, 1, 0), id(x, 1, 0), facet++);
    square(id(x, 0, 1), id(x + 1, 0, 1), id(x + 1, 1, 1), id(x, 1, 1), facet++);
    square(id(x, 0, 0), id(x + 1, 0, 0), id(x + 1, 0, 1), id(x, 0, 1), facet++);
    square(id(x, 1, 0), id(x + 1, 1, 0), id(x + 1, 1, 1), id(x, 1, 1), facet++);
  }
  for (int x = 0; x < 3; ++x) square(id(x, 0, 0), id(x, 1, 0), id(x, 1, 1), id(x, 0, 1), facet++);  // 8, 9, 10
  return plc;
}

double tet_volume(const PLC3& plc, const Tetrahedron& t) {
  auto d = [&](int i, int k) { return (&plc.points[t[i]].x)[k] - (&plc.points[t[0]].x)[k]; };
  return (d(1, 0) * (d(2, 1) * d(3, 2) - d(2, 2) * d(3, 1)) - d(1, 1) * (d(2, 0) * d(3, 2) - d(2, 2) * d(3, 0)) +
          d(1, 2) * (d(2, 0) * d(3, 1) - d(2, 1) * d(3, 0))) / 6.0;
}

// The region of each tet by its centroid's x, and the total volume per region.
std::map<double, double> volume_per_region(const PLC3& plc, const PlcDelaunay& r, bool* regions_by_side) {
  std::map<double, double> out;
  std::map<double, std::set<int>> sides;  // region -> which cube (0: x < 1, 1: x > 1) its tets are in
  for (std::size_t i = 0; i < r.tets.size(); ++i) {
    double x = 0;
    for (int v : r.tets[i]) x += plc.points[v].x / 4;
    out[r.tet_regions[i]] += tet_volume(plc, r.tets[i]);
    sides[r.tet_regions[i]].insert(x < 1 ? 0 : 1);
  }
  *regions_by_side = true;
  for (const auto& [region, s] : sides) *regions_by_side = *regions_by_side && s.size() == 1;
  return out;
}

TEST(PlcDelaunay, AnInternalFacetSeparatesTwoSeededRegions) {
  PLC3 plc = two_cubes_sharing_a_face();
  plc.regions = {{0.5, 0.5, 0.5, 7.0}, {1.5, 0.5, 0.5, 9.0}};
  PlcDelaunay r = delaunay_restricted_to_plc(plc);
  EXPECT_TRUE(r.uncovered_facets.empty());
  bool by_side = false;
  auto volumes = volume_per_region(plc, r, &by_side);
  EXPECT_TRUE(by_side);
  ASSERT_EQ(volumes.size(), 2u);
  EXPECT_NEAR(volumes[7.0], 1.0, 1e-12);
  EXPECT_NEAR(volumes[9.0], 1.0, 1e-12);
  // 10 outer squares and the internal one, each as two faces, each once
  EXPECT_EQ(r.boundary_faces.size(), 22u);
  EXPECT_EQ(std::count(r.face_markers.begin(), r.face_markers.end(), 9), 2);
}

TEST(PlcDelaunay, WithoutSeedsRegionsAreNumberedByComponent) {
  PLC3 plc = two_cubes_sharing_a_face();
  PlcDelaunay r = delaunay_restricted_to_plc(plc);
  bool by_side = false;
  auto volumes = volume_per_region(plc, r, &by_side);
  EXPECT_TRUE(by_side);
  ASSERT_EQ(volumes.size(), 2u);
  EXPECT_EQ(volumes.begin()->first, 1.0);
  EXPECT_EQ(volumes.rbegin()->first, 2.0);
}

TEST(PlcDelaunay, ANonConformingFacetIsReported) {
  // Schonhardt's twisted prism: no tetrahedralization of its six vertices has its faces, so the Delaunay one
  // crosses some facets.
  PLC3 plc;
  const double pi = 3.14159265358979323846;
  for (int level = 0; level < 2; ++level)
    for (int k = 0; k < 3; ++k) {
      double a = pi / 2 + 2 * pi * k / 3 + level * pi / 6;
      plc.points.push_back({std::cos(a), std::sin(a), 1.5 * level});
    }
  plc.triangles = {{0, 2, 1}, {3, 4, 5}};
  for (int i = 0; i < 3; ++i) {
    int j = (i + 1) % 3;
    plc.triangles.push_back({i, j, 3 + j});
    plc.triangles.push_back({i, 3 + j, 3 + i});
  }
  for (int f = 0; f < 8; ++f) plc.facet_ids.push_back(f);
  PlcDelaunay d = delaunay_restricted_to_plc(plc);
  EXPECT_FALSE(d.uncovered_facets.empty());
  // Every facet is one triangle: the answer comes from the Delaunay tetrahedralization alone, and the uncovered
  // facets are exactly the triangles that are not its faces.
  EXPECT_EQ(d.delaunay_cells, delaunay_tetrahedra(plc.points));
  EXPECT_TRUE(d.tets.empty());
  DelaunayFaces faces = delaunay_faces(plc.points, plc.triangles);
  std::vector<int> not_faces;
  for (int f = 0; f < 8; ++f)
    if (!faces.is_face[f]) not_faces.push_back(f);
  EXPECT_EQ(d.uncovered_facets, not_faces);
}

TEST(PlcPredicates, DelaunayFacesOfABipyramid) {
  // The triangle 0, 1, 2 in z = 0 (circumcentre near the origin, radius about 1) and the apexes 3, 4 at z = +-2,
  // outside its diametral sphere: the Delaunay tetrahedralization is the two tets on that triangle, so the
  // triangle is a face and a triangle through both apexes is not (the edge 3-4 would cross the triangle).
  std::vector<PlcPoint> p = {{1, 0, 0}, {-0.5, 0.8, 0}, {-0.5, -0.8, 0}, {0, 0, 2}, {0, 0, -2}};
  DelaunayFaces d = delaunay_faces(p, {{0, 1, 2}, {0, 1, 3}, {2, 1, 4}, {3, 4, 0}});
  EXPECT_EQ(d.cells.size(), 2u);
  EXPECT_EQ(d.is_face, (std::vector<char>{1, 1, 1, 0}));
}

}  // namespace
}  // namespace nonobtuse
