#include "nonobtuse/check2d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <map>

#include "nonobtuse/control_volumes2d.h"
#include "nonobtuse/triangulate.h"

namespace nonobtuse {
namespace {

const EdgeReport& find_edge(const std::vector<EdgeReport>& edges, int a, int b) {
  for (const auto& e : edges)
    if (e.edge == Segment{a, b}) return e;
  throw std::runtime_error("edge not found");
}

// The side of e that has a triangle (for boundary edges).
const EdgeSide& the_side(const EdgeReport& e) { return e.left.triangle >= 0 ? e.left : e.right; }

TEST(Check2d, ExactRightAngleIsRightNotObtuse) {
  // (0,0), (2,0), (1,1): at (1,1) the vectors to the ends are (-1,-1) and (1,-1), dot = 1 - 1 = 0.
  Mesh2 m{{{0, 0}, {2, 0}, {1, 1}}, {{0, 1, 2}}, {{0, 1}, {1, 2}, {0, 2}}, {}};
  auto edges = classify_edges(m);
  ASSERT_EQ(edges.size(), 3u);
  const auto& e = find_edge(edges, 0, 1);
  EXPECT_EQ(e.kind, EdgeKind::Boundary);
  EXPECT_EQ(e.left.triangle, 0);  // (0, 1, 2) is counter-clockwise
  EXPECT_EQ(e.right.triangle, -1);
  EXPECT_EQ(e.left.apex, 2);
  EXPECT_EQ(e.left.angle, AngleClass::Right);
  // edge (1, 2) faces (0,0): vectors (2,0), (1,1), 45 degrees; edge (0, 2) faces (2,0): 45 degrees.
  EXPECT_EQ(the_side(find_edge(edges, 1, 2)).angle, AngleClass::Acute);
  EXPECT_EQ(the_side(find_edge(edges, 0, 2)).angle, AngleClass::Acute);
  // cot(90) = 0, cot(45) = 1: signs 0, +1, +1 in edge order (0,1), (0,2), (1,2).
  EXPECT_EQ(coupling_signs(m, edges, {}), (std::vector<int>{0, 1, 1}));
}

TEST(Check2d, ObtuseBoundaryTriangleIsFound) {
  // (0,0), (4,0), (2,1): at (2,1) the vectors are (-2,-1), (2,-1), dot = -4 + 1 = -3 < 0.
  Mesh2 m{{{0, 0}, {4, 0}, {2, 1}}, {{0, 1, 2}}, {{0, 1}, {1, 2}, {0, 2}}, {}};
  auto edges = classify_edges(m);
  EXPECT_EQ(find_edge(edges, 0, 1).left.angle, AngleClass::Obtuse);
  EXPECT_EQ(coupling_signs(m, edges, {})[0], -1);
}

TEST(Check2d, SquareWithCenterPasses) {
  // Corners (0,0), (2,0), (2,2), (0,2), center (1,1): each boundary edge faces the center at exactly 90
  // degrees ((-1,-1).(1,-1) = 0); each interior edge faces two 45-degree corners.
  Mesh2 m{{{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}},
          {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}},
          {{0, 1}, {1, 2}, {2, 3}, {0, 3}},
          {}};
  auto edges = classify_edges(m);
  ASSERT_EQ(edges.size(), 8u);
  auto signs = coupling_signs(m, edges, {});
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const auto& e = edges[i];
    if (e.edge[1] == 4) {
      EXPECT_EQ(e.kind, EdgeKind::Interior);
      EXPECT_EQ(e.left.angle, AngleClass::Acute);
      EXPECT_EQ(e.right.angle, AngleClass::Acute);
      EXPECT_TRUE(e.locally_delaunay);
      EXPECT_EQ(signs[i], 1);  // cot 45 + cot 45 = 2
    } else {
      EXPECT_EQ(e.kind, EdgeKind::Boundary);
      EXPECT_EQ(the_side(e).angle, AngleClass::Right);
      EXPECT_EQ(signs[i], 0);
    }
  }
}

// Edge (0,1) from (0,0) to (4,0) with apexes (2,1) above (left) and (2,-4) below (right).
// Left: u - c = (-2,-1), v - c = (2,-1): dot -3, cross 4, cot = -3/4 (126.87 degrees, obtuse).
// Right (triangle (1,0,3)): u - c = (2,4), v - c = (-2,4): dot 12, cross 16, cot = +3/4 (53.13 degrees).
// The two angles sum to exactly 180: the four points are cocircular, so the edge is (just) locally Delaunay.
Mesh2 kite(bool constrained) {
  Mesh2 m{{{0, 0}, {4, 0}, {2, 1}, {2, -4}}, {{0, 1, 2}, {1, 0, 3}}, {{1, 2}, {0, 2}, {0, 3}, {1, 3}}, {}};
  if (constrained) m.segments.push_back({0, 1});
  return m;
}

TEST(Check2d, InterfaceEdgeChecksBothSides) {
  Mesh2 m = kite(true);
  auto edges = classify_edges(m);
  const auto& e = find_edge(edges, 0, 1);
  EXPECT_EQ(e.kind, EdgeKind::Interface);
  EXPECT_EQ(e.left.apex, 2);
  EXPECT_EQ(e.left.angle, AngleClass::Obtuse);
  EXPECT_EQ(e.right.apex, 3);
  EXPECT_EQ(e.right.angle, AngleClass::Acute);
  EXPECT_TRUE(e.locally_delaunay);  // cocircular counts as Delaunay
}

TEST(Check2d, UnconstrainedEdgeBetweenRegionsIsAnInterface) {
  Mesh2 m = kite(false);
  EXPECT_EQ(find_edge(classify_edges(m), 0, 1).kind, EdgeKind::Interior);
  m.triangle_region = {1.0, 2.0};
  EXPECT_EQ(find_edge(classify_edges(m), 0, 1).kind, EdgeKind::Interface);
}

TEST(Check2d, CouplingSignIsExactAtZeroAndWeightedByConductivity) {
  Mesh2 m = kite(true);
  auto edges = classify_edges(m);
  std::size_t i = 0;
  while (edges[i].edge != Segment{0, 1}) ++i;
  EXPECT_EQ(coupling_signs(m, edges, {})[i], 0);           // -3/4 + 3/4
  EXPECT_EQ(coupling_signs(m, edges, {1.0, 2.0})[i], 1);   // -3/4 + 2 * 3/4
  EXPECT_EQ(coupling_signs(m, edges, {2.0, 1.0})[i], -1);  // -2 * 3/4 + 3/4
  EXPECT_THROW(coupling_signs(m, edges, {1.0, 0.0}), InvalidInput);
  EXPECT_THROW(coupling_signs(m, edges, {1.0}), InvalidInput);
}

TEST(Check2d, AnglesAreExactOneUlpFromRight) {
  // Apex (0.5, 0.5 + d) over the edge (0,0)-(1,0): dot = -1/4 + (1/2 + d)^2 = d + d^2, so acute iff d > 0.
  // 0.5 + 2^-53 and 0.5 - 2^-54 are the doubles next to 0.5.
  for (double d : {std::ldexp(1.0, -53), -std::ldexp(1.0, -54)}) {
    Mesh2 m{{{0, 0}, {1, 0}, {0.5, 0.5 + d}}, {{0, 1, 2}}, {}, {}};
    auto edges = classify_edges(m);
    EXPECT_EQ(edges[0].left.angle, d > 0 ? AngleClass::Acute : AngleClass::Obtuse);
    EXPECT_EQ(coupling_signs(m, edges, {})[0], d > 0 ? 1 : -1);
  }
}

TEST(Check2d, MalformedMeshesAreRefused) {
  Mesh2 clockwise{{{0, 0}, {1, 0}, {0, 1}}, {{0, 2, 1}}, {}, {}};
  EXPECT_THROW(classify_edges(clockwise), InvalidInput);
  Mesh2 degenerate{{{0, 0}, {1, 0}, {2, 0}}, {{0, 1, 2}}, {}, {}};
  EXPECT_THROW(classify_edges(degenerate), InvalidInput);
  // Three triangles on the edge (0, 1): two of them on the same side.
  Mesh2 fan{{{0, 0}, {1, 0}, {0, 1}, {0, -1}, {1, 1}}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}, {}, {}};
  EXPECT_THROW(classify_edges(fan), InvalidInput);
  Mesh2 stray_segment{{{0, 0}, {1, 0}, {0, 1}, {5, 5}}, {{0, 1, 2}}, {{2, 3}}, {}};
  EXPECT_THROW(classify_edges(stray_segment), InvalidInput);
}

// Meshes of counter-clockwise triangles with consistently paired edges that still overlap themselves.
TEST(Check2d, OverlappingMeshesAreRefused) {
  // An open fan around (0,0) winding twice: ring points at 72 k degrees, radius 1 + 0.05 k, k = 0..9,
  // triangles (0, k, k + 1); the fan covers 9 * 72 = 648 degrees.
  Mesh2 spiral;
  spiral.points.push_back({0, 0});
  for (int k = 0; k < 10; ++k)
    spiral.points.push_back({(1 + 0.05 * k) * std::cos(k * 72 * M_PI / 180), (1 + 0.05 * k) * std::sin(k * 72 * M_PI / 180)});
  for (int k = 1; k < 10; ++k) {
    spiral.triangles.push_back({0, k, k + 1});
    spiral.segments.push_back({k, k + 1});
  }
  EXPECT_THROW(classify_edges(spiral), InvalidInput);
  EXPECT_THROW(count_obtuse_boundary_sides(spiral), InvalidInput);
  spiral.triangles.resize(4);  // 4 * 72 = 288 degrees: embedded
  spiral.segments.resize(4);
  EXPECT_EQ(classify_edges(spiral).size(), 9u);
  // A closed fan winding twice (a pentagram: rim points 144 degrees apart): every edge has one triangle on each
  // side, the hub is interior and its fan winds twice.
  Mesh2 pentagram;
  pentagram.points.push_back({0, 0});
  for (int k = 0; k < 5; ++k) pentagram.points.push_back({std::cos(k * 144 * M_PI / 180), std::sin(k * 144 * M_PI / 180)});
  for (int k = 0; k < 5; ++k) pentagram.triangles.push_back({0, 1 + k, 1 + (k + 1) % 5});
  EXPECT_THROW(classify_edges(pentagram), InvalidInput);
  // Two triangles at (0,0) sharing no edge, the second inside the first's angle: two fans covering the same
  // directions. Moved to the other side of (0,0), the second no longer overlaps (a valid bow tie).
  Mesh2 nested{{{0, 0}, {2, 0}, {0, 2}, {2, 1}, {1, 2}}, {{0, 1, 2}, {0, 3, 4}}, {}, {}};
  EXPECT_THROW(classify_edges(nested), InvalidInput);
  Mesh2 bow_tie{{{0, 0}, {2, 0}, {0, 2}, {-2, -1}, {-1, -2}}, {{0, 1, 2}, {0, 3, 4}}, {}, {}};
  EXPECT_EQ(classify_edges(bow_tie).size(), 6u);
  // Two boundary edges from (0,0) in the same direction: (0,0)-(1,0) and (0,0)-(2,0) in two triangles above and
  // below the x axis.
  Mesh2 slit{{{0, 0}, {1, 0}, {0, 1}, {2, 0}, {0, -1}}, {{0, 1, 2}, {0, 4, 3}}, {}, {}};
  EXPECT_THROW(classify_edges(slit), InvalidInput);
}

TEST(Check2d, EveryEdgeOfATriangulationOnceAndDelaunay) {
  // The square-with-hole ring of cdt_test: 8 triangles and 4 + 4 boundary edges; counting triangle sides,
  // 3 * 8 = 2 * interior + boundary = 2 * I + 8, so I = 8.
  Domain2 d;
  d.points = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {3, 1}, {3, 3}, {1, 3}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  d.holes = {{2, 2}};
  auto edges = classify_edges(triangulate(d));
  int boundary = 0, interior = 0;
  for (const auto& e : edges) {
    boundary += e.kind == EdgeKind::Boundary;
    interior += e.kind == EdgeKind::Interior;
    EXPECT_TRUE(e.locally_delaunay);  // a constrained Delaunay triangulation without interior constraints
  }
  EXPECT_EQ(boundary, 8);
  EXPECT_EQ(interior, 8);
}

// A wheel: hub 0 and n rim vertices, the rim and one spoke listed as segments. The hub's half-edges are paired by a
// scan up to a bucket of 16 and sorted beyond, so both ways are covered: the constrained spoke an interface, every
// other spoke interior, every rim edge boundary, the edges sorted by (a, b), and a triangle repeated at the hub
// refused.
TEST(Check2d, WheelEdgesAtAHubOfAnyDegree) {
  for (int n : {6, 40}) {
    Mesh2 m;
    m.points.push_back({0, 0});
    for (int i = 0; i < n; ++i) m.points.push_back({std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n)});
    for (int i = 0; i < n; ++i) {
      int a = 1 + i, b = 1 + (i + 1) % n;
      m.triangles.push_back({0, a, b});
      m.segments.push_back({a, b});
    }
    const int spoke = 1 + n / 3;
    m.segments.push_back({0, spoke});
    auto edges = classify_edges(m);
    ASSERT_EQ(edges.size(), 2u * n) << n;
    for (std::size_t k = 0; k < edges.size(); ++k) {
      const auto& e = edges[k];
      EdgeKind expected = e.edge[0] != 0           ? EdgeKind::Boundary
                          : e.edge[1] == spoke ? EdgeKind::Interface
                                               : EdgeKind::Interior;
      EXPECT_EQ(e.kind, expected) << n << " " << e.edge[0] << " " << e.edge[1];
      if (k > 0) EXPECT_LT(edges[k - 1].edge, e.edge);
    }
    EXPECT_EQ(count_obtuse_boundary_sides(m), 0);  // every rim angle at the hub is 360 / n degrees
    m.triangles.push_back(m.triangles[n / 2]);
    EXPECT_THROW(classify_edges(m), InvalidInput) << n;
  }
}

// Above kForkThreshold triangles the half-edges are bucketed and paired on two threads: every edge's sides and kind
// equal a plain map's, the obtuse count is the sum of both parts, and errors planted in either half are found.
TEST(Check2d, LargeMeshMatchesAPlainEdgeMap) {
  Domain2 d;
  d.convex_hull_boundary = true;
  std::uint64_t state = 12345;  // a 64-bit LCG: the same points on every platform
  auto uniform = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  for (int i = 0; i < 60000; ++i) d.points.push_back({uniform(), uniform()});
  Mesh2 m = triangulate(d);
  ASSERT_GE(m.triangles.size(), 100000u);
  std::map<std::pair<int, int>, std::pair<int, int>> sides;  // (a, b), a < b -> (left, right) triangle
  for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t)
    for (int k = 0; k < 3; ++k) {
      int u = m.triangles[t][(k + 1) % 3], v = m.triangles[t][(k + 2) % 3];
      auto& s = sides.try_emplace({std::min(u, v), std::max(u, v)}, -1, -1).first->second;
      (u < v ? s.first : s.second) = t;
    }
  auto edges = classify_edges(m);
  ASSERT_EQ(edges.size(), sides.size());
  long long obtuse = 0;
  for (const auto& e : edges) {
    auto [left, right] = sides.at({e.edge[0], e.edge[1]});
    ASSERT_EQ(e.left.triangle, left);
    ASSERT_EQ(e.right.triangle, right);
    ASSERT_EQ(e.kind, left < 0 || right < 0 ? EdgeKind::Boundary : EdgeKind::Interior);
    for (const EdgeSide* s : {&e.left, &e.right})
      obtuse += e.kind == EdgeKind::Boundary && s->triangle >= 0 && s->angle == AngleClass::Obtuse;
  }
  EXPECT_GT(obtuse, 0);  // random points: some hull triangles are obtuse
  EXPECT_EQ(count_obtuse_boundary_sides(m), obtuse);
  for (std::size_t t : {std::size_t{7}, m.triangles.size() - 7}) {  // in the lower and the upper half
    Mesh2 bad = m;
    bad.triangles.push_back(bad.triangles[t]);
    EXPECT_THROW(classify_edges(bad), InvalidInput) << t;
    bad = m;
    std::swap(bad.triangles[t][0], bad.triangles[t][1]);
    EXPECT_THROW(count_obtuse_boundary_sides(bad), InvalidInput) << t;
  }
}

}  // namespace
}  // namespace nonobtuse
