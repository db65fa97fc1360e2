// Exact signs of the control-volume coupling coefficients.
#include "nonobtuse/control_volumes2d.h"

#include <gtest/gtest.h>

#include <vector>

namespace nonobtuse {
namespace {

// Two triangles on the edge a = (0,0), b = (2,0): above, c1 = (1, 0.5), obtuse at c1 (dot (a - c1).(b - c1) =
// -1 + 0.25 = -0.75, cross 1: cot -0.75); below, c2 = (1, -2) (dot (b - c2).(a - c2) = -1 + 4 = 3, cross 4: cot
// 0.75). With k = (k_above, k_below) the sign of T_ab is that of k_above (-0.75)(4) + k_below (3)(1): k = (1, 1)
// gives -3 + 3 = 0 exactly, (1, 2) gives 3 > 0, (2, 1) gives -3 < 0. The four outer edges see their apex at an
// acute angle (e.g. (0, 2) at b: (a - b).(c1 - b) = 2 > 0): +1.
TEST(ControlVolumes2d, SignsOfTwoTrianglesOnOneEdge) {
  Mesh2 m;
  m.points = {{0, 0}, {2, 0}, {1, 0.5}, {1, -2}};
  m.triangles = {{0, 1, 2}, {1, 0, 3}};
  const std::vector<EdgeReport> edges = classify_edges(m);
  ASSERT_EQ(edges.size(), 5u);
  ASSERT_EQ(edges[0].edge, (Segment{0, 1}));
  ASSERT_EQ(edges[0].left.triangle, 0);  // (0, 1, 2) is counter-clockwise: the triangle above is on the left
  const auto signs = [&](std::vector<double> k) { return coupling_signs(m, edges, k); };
  EXPECT_EQ(signs({}), (std::vector<int>{0, 1, 1, 1, 1}));
  EXPECT_EQ(signs({1, 1}), (std::vector<int>{0, 1, 1, 1, 1}));
  EXPECT_EQ(signs({1, 2}), (std::vector<int>{1, 1, 1, 1, 1}));
  EXPECT_EQ(signs({2, 1}), (std::vector<int>{-1, 1, 1, 1, 1}));
}

TEST(ControlVolumes2d, RefusesBadConductivity) {
  Mesh2 m;
  m.points = {{0, 0}, {2, 0}, {1, 0.5}};
  m.triangles = {{0, 1, 2}};
  const std::vector<EdgeReport> edges = classify_edges(m);
  EXPECT_EQ(coupling_signs(m, edges, {}), (std::vector<int>{-1, 1, 1}));  // (0, 1) sees c1 obtuse
  EXPECT_THROW(coupling_signs(m, edges, {1, 1}), InvalidInput);           // two values, one triangle
  EXPECT_THROW(coupling_signs(m, edges, {0}), InvalidInput);              // not > 0
}

}  // namespace
}  // namespace nonobtuse
