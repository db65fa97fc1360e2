#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "nonobtuse/plc_predicates.h"

namespace nonobtuse {
namespace {

struct Surface {
  std::vector<PlcPoint> points;
  std::vector<PlcTriangle> triangles;
  // Adds the quad (a, b, c, d) (counter-clockwise seen from outside) as the triangles (a, b, c), (a, c, d).
  void quad(int a, int b, int c, int d) {
    triangles.push_back({a, b, c});
    triangles.push_back({a, c, d});
  }
};

// The box [lo, hi]^3, outward; its top and bottom squares are split along the diagonal x = y.
void add_box(Surface& s, double lo, double hi) {
  int o = static_cast<int>(s.points.size());
  for (int k = 0; k < 8; ++k) s.points.push_back({k & 1 ? hi : lo, k & 2 ? hi : lo, k & 4 ? hi : lo});
  s.quad(o + 0, o + 2, o + 3, o + 1);  // z = lo, normal -z
  s.quad(o + 4, o + 5, o + 7, o + 6);  // z = hi, normal +z
  s.quad(o + 0, o + 1, o + 5, o + 4);  // y = lo
  s.quad(o + 2, o + 6, o + 7, o + 3);  // y = hi
  s.quad(o + 0, o + 4, o + 6, o + 2);  // x = lo
  s.quad(o + 1, o + 3, o + 7, o + 5);  // x = hi
}

// A square torus: the annulus between the squares [0, 3]^2 and [1, 2]^2, extruded over z in [0, 1], outward.
Surface square_torus() {
  Surface s;
  const double outer[4][2] = {{0, 0}, {3, 0}, {3, 3}, {0, 3}}, inner[4][2] = {{1, 1}, {2, 1}, {2, 2}, {1, 2}};
  for (double z : {0.0, 1.0})
    for (int k = 0; k < 4; ++k) {
      s.points.push_back({outer[k][0], outer[k][1], z});  // o(k, z)
      s.points.push_back({inner[k][0], inner[k][1], z});  // i(k, z)
    }
  auto o = [](int k, int z) { return 8 * z + 2 * (k % 4); };
  auto i = [](int k, int z) { return 8 * z + 2 * (k % 4) + 1; };
  for (int k = 0; k < 4; ++k) {
    s.quad(o(k, 1), o(k + 1, 1), i(k + 1, 1), i(k, 1));  // top
    s.quad(o(k, 0), i(k, 0), i(k + 1, 0), o(k + 1, 0));  // bottom
    s.quad(o(k, 0), o(k + 1, 0), o(k + 1, 1), o(k, 1));  // outer wall
    s.quad(i(k + 1, 0), i(k, 0), i(k, 1), i(k + 1, 1));  // inner wall, facing the hole
  }
  return s;
}

std::vector<int> winding(const Surface& s, const std::vector<PlcPoint>& q) {
  return surface_winding_numbers(s.points, s.triangles, q);
}

TEST(WindingNumber, UnitCubeInsideOutsideAndOnItsFaces) {
  Surface cube;
  add_box(cube, 0, 1);
  EXPECT_EQ(unbalanced_edge(cube.triangles), (std::array<int, 2>{-1, -1}));
  // (0.5, 0.5, z) projects onto the diagonals of the top and bottom squares: decided by the perturbation.
  EXPECT_EQ(winding(cube, {{0.5, 0.5, 0.5}, {0.25, 0.75, 0.5}, {2, 0.5, 0.5}, {0.5, 0.5, 2}, {0.5, 0.5, -1}}),
            (std::vector<int>{1, 1, 0, 0, 0}));
  // On the surface, q + (e, e^2, e^3) is inside above the bottom face and beyond the face x = 0, outside above
  // the top face and beyond x = 1: the ray from q + (e, e^2, e^3) meets the same triangles as from that point.
  EXPECT_EQ(winding(cube, {{0.5, 0.25, 0}, {0.5, 0.25, 1}, {0, 0.5, 0.5}, {1, 0.5, 0.5}, {0, 0, 0}}),
            (std::vector<int>{1, 0, 1, 0, 1}));
  Surface inward = cube;
  for (auto& t : inward.triangles) std::swap(t[1], t[2]);
  EXPECT_EQ(winding(inward, {{0.5, 0.5, 0.5}, {2, 2, 2}}), (std::vector<int>{-1, 0}));
}

TEST(WindingNumber, NestedShellsCountTwiceACavityCancels) {
  Surface nested;
  add_box(nested, 0, 3);
  add_box(nested, 1, 2);  // both outward, as validation orients nested shells
  EXPECT_EQ(unbalanced_edge(nested.triangles), (std::array<int, 2>{-1, -1}));
  const std::vector<PlcPoint> q = {{0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}, {4, 4, 4}};
  EXPECT_EQ(winding(nested, q), (std::vector<int>{1, 2, 0}));
  Surface cavity = nested;
  for (std::size_t t = 12; t < cavity.triangles.size(); ++t) std::swap(cavity.triangles[t][1], cavity.triangles[t][2]);
  EXPECT_EQ(winding(cavity, q), (std::vector<int>{1, 0, 0}));
}

TEST(WindingNumber, SquareTorusHasAHole) {
  Surface torus = square_torus();
  EXPECT_EQ(unbalanced_edge(torus.triangles), (std::array<int, 2>{-1, -1}));
  EXPECT_EQ(winding(torus, {{0.5, 0.5, 0.5}, {2.5, 1.5, 0.5}, {1.5, 1.5, 0.5}, {1.5, 1.5, 2}, {4, 1, 0.5}}),
            (std::vector<int>{1, 1, 0, 0, 0}));
}

TEST(WindingNumber, AnOpenSurfaceHasAnUnbalancedEdge) {
  Surface open;
  add_box(open, 0, 1);
  open.triangles.erase(open.triangles.begin() + 2, open.triangles.begin() + 4);  // no top: points 4, 5, 6, 7
  auto e = unbalanced_edge(open.triangles);
  EXPECT_EQ(e, (std::array<int, 2>{4, 5}));  // the smallest edge of the missing top square
}

TEST(WindingNumber, EveryDelaunayCellOfAConvexSurfaceIsInside) {
  Surface cube;
  add_box(cube, 0, 1);
  EXPECT_EQ(delaunay_cells_inside_surface(cube.points, cube.triangles), delaunay_tetrahedra(cube.points));
  // In the square torus no cell lies in the hole: the cells whose centroid is in [1, 2]^2 are left out.
  Surface torus = square_torus();
  auto inside = delaunay_cells_inside_surface(torus.points, torus.triangles);
  auto all = delaunay_tetrahedra(torus.points);
  EXPECT_LT(inside.size(), all.size());
  for (const auto& c : all) {
    double x = 0, y = 0;
    for (int v : c) {
      x += torus.points[v].x / 4;
      y += torus.points[v].y / 4;
    }
    // A centroid on a wall of the hole is decided by q + (e, e^2, e^3): in the hole on x = 1 or y = 1.
    bool in_hole = x >= 1 && x < 2 && y >= 1 && y < 2;
    bool kept = std::find(inside.begin(), inside.end(), c) != inside.end();
    EXPECT_EQ(kept, !in_hole);
  }
}

}  // namespace
}  // namespace nonobtuse
