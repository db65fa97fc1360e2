#include "nonobtuse/gabriel3d.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>

namespace nonobtuse {
namespace {

const std::vector<Point3> kRegularTet = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
const std::vector<Triangle> kTetFaces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

std::vector<Segment> edges_of(const std::vector<Triangle>& faces) {
  std::map<std::pair<int, int>, int> seen;
  std::vector<Segment> out;
  for (const auto& f : faces)
    for (int k = 0; k < 3; ++k) {
      int a = std::min(f[k], f[(k + 1) % 3]), b = std::max(f[k], f[(k + 1) % 3]);
      if (seen.emplace(std::make_pair(a, b), 0).second) out.push_back({a, b});
    }
  return out;
}

TEST(Gabriel3DCheck, RegularTetrahedronPasses) {
  // Each face's circumcenter is its centroid; the opposite vertex is at distance sqrt(R^2 + h^2) > R.
  auto r = check_gabriel(kRegularTet, kTetFaces, edges_of(kTetFaces));
  EXPECT_TRUE(r.faces.empty());
  EXPECT_TRUE(r.segments.empty());
}

TEST(Gabriel3DCheck, FlatSliverFaceIsEncroached) {
  // Apex (0, 0, 0.1) above the centroid of the big face's circumcircle (center (0,0,0), radius 1): depth 0.9.
  std::vector<Point3> p = {{1, 0, 0}, {-0.5, 0.8660254037844386, 0}, {-0.5, -0.8660254037844386, 0}, {0, 0, 0.1}};
  auto r = check_gabriel(p, {{0, 1, 2}}, {});
  ASSERT_EQ(r.faces.size(), 1u);
  EXPECT_EQ(r.faces[0].index, 0);
  EXPECT_EQ(r.faces[0].vertex, 3);
  EXPECT_NEAR(r.faces[0].depth, 0.9, 1e-9);
}

TEST(Gabriel3DCheck, RightAngleIsNotEncroached) {
  // (0,0,0) sees the diameter (1,0,0)-(0,1,0)... no: it sees segment (1,0,0)-(-1,0,0) through... use the classic:
  // Thales: (0,1,0) is on the sphere with diameter (-1,0,0)-(1,0,0): exactly a right angle, not strictly inside.
  std::vector<Point3> p = {{-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0.5, 0.5}};
  auto r = check_gabriel(p, {}, {{0, 1}});
  // (0, 0.5, 0.5) is at distance sqrt(0.5) < 1 from the center: inside.
  ASSERT_EQ(r.segments.size(), 1u);
  EXPECT_EQ(r.segments[0].vertex, 3);
  auto on_sphere = check_gabriel({p[0], p[1], p[2]}, {}, {{0, 1}});
  EXPECT_TRUE(on_sphere.segments.empty());
  // A right triangle's diametral sphere has its hypotenuse as a diameter; a point on that sphere does not encroach.
  std::vector<Point3> q = {{-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  EXPECT_TRUE(check_gabriel(q, {{0, 1, 2}}, {}).faces.empty());
}

TEST(Gabriel3DCheck, CubeWithVertexPushedNearFace) {
  // Unit cube; an extra vertex at (0.5, 0.5, 0.05) is 0.05 above the bottom face z = 0. Every cube triangle is
  // right-angled, so its diametral sphere is centered at its square's center with radius sqrt(0.5) = 0.7071.
  // Distances from the extra vertex: bottom center 0.05, side centers sqrt(0.25 + 0.45^2) = 0.6727 (inside),
  // top center 0.95 (outside). So the 2 bottom and 8 side triangles are encroached, the 2 top ones are not.
  std::vector<Point3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1},
                           {1, 1, 1}, {0, 1, 1}, {0.5, 0.5, 0.05}};
  std::vector<Triangle> faces = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                                 {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  auto r = check_gabriel(p, faces, {});
  ASSERT_EQ(r.faces.size(), 10u);
  for (const auto& e : r.faces) {
    EXPECT_TRUE(e.index != 2 && e.index != 3) << e.index;
    EXPECT_EQ(e.vertex, 8);
  }
  EXPECT_NEAR(r.faces[0].depth, 1.0 - 0.05 / std::sqrt(0.5), 1e-12);
  // Without the extra vertex: cube corners are on the spheres (cospherical), never strictly inside.
  p.pop_back();
  EXPECT_TRUE(check_gabriel(p, faces, edges_of(faces)).faces.empty());
}

TEST(Gabriel3DCheck, DegenerateFaceIsInvalidInput) {
  std::vector<Point3> p = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  EXPECT_THROW(check_gabriel(p, {{0, 1, 2}}, {}), InvalidInput);
  EXPECT_THROW(check_gabriel(p, {{0, 1, 5}}, {}), InvalidInput);
}

// A subdivided icosahedron (Loop-style midpoint subdivision projected onto the unit sphere): every face is nearly
// equilateral and Gabriel. Prints the throughput figure the check is held to (>= 1e6 faces per 10 s).
TEST(Gabriel3DCheck, ThroughputOnSubdividedSphere) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Point3> p = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                           {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<Triangle> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},   {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                             {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  auto normalize = [](Point3 q) {
    double n = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
    return Point3{q.x / n, q.y / n, q.z / n};
  };
  for (auto& q : p) q = normalize(q);
  for (int level = 0; level < 7; ++level) {  // 20 * 4^7 = 327680 faces
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      auto k = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(k);
      if (it != mid.end()) return it->second;
      p.push_back(normalize({(p[a].x + p[b].x) / 2, (p[a].y + p[b].y) / 2, (p[a].z + p[b].z) / 2}));
      return mid[k] = static_cast<int>(p.size()) - 1;
    };
    std::vector<Triangle> g;
    for (auto [a, b, c] : f) {
      int ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      g.insert(g.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
    }
    f = std::move(g);
  }
  auto start = std::chrono::steady_clock::now();
  auto r = check_gabriel(p, f, {});
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("check_gabriel: %zu faces, %zu points in %.3f s = %.3g faces per 10 s\n", f.size(), p.size(), seconds,
              10.0 * f.size() / seconds);
  // A fine triangulation of a sphere: every face's diametral sphere cuts a tiny cap and holds no other vertex.
  EXPECT_TRUE(r.faces.empty());
}

double volume(const Refine3DResult& r);

PLC3 cube_plc() {
  PLC3 plc;
  plc.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  plc.triangles = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                   {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  plc.facet_ids = {0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5};
  return plc;
}

TEST(Gabriel3DRefine, CubeConvergesWithoutSteinerPoints) {
  // A cube's square faces are Gabriel (the fourth corner is on each triangle's sphere) and its edges too (the
  // nearest other corners see an edge at 45 or 90 degrees... at angle 45/54.7 degrees: outside the sphere).
  auto r = refine_gabriel(cube_plc(), {});
  EXPECT_EQ(r.status, RefineStatus::Converged) << r.diagnosis.stop_reason;
  EXPECT_EQ(r.steiner_on_segments + r.steiner_on_facets, 0);
  EXPECT_EQ(r.points.size(), 8u);
  EXPECT_EQ(r.boundary_faces.size(), 12u);
  EXPECT_EQ(r.segments.size(), 12u);  // the cube's edges: the facets' boundary edges
  EXPECT_NEAR(volume(r), 1.0, 1e-12);  // positively oriented tets filling the unit cube
}

// A flat tetrahedron: the apex 0.1 above the center of an equilateral base with circumradius 1 encroaches the
// base (depth 0.9, see FlatSliverFaceIsEncroached). Each triangle is its own facet.
PLC3 flat_tetrahedron_plc() {
  PLC3 plc;
  plc.points = {{1, 0, 0}, {-0.5, 0.8660254037844386, 0}, {-0.5, -0.8660254037844386, 0}, {0, 0, 0.1}};
  plc.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  plc.facet_ids = {0, 1, 2, 3};
  return plc;
}

double volume(const Refine3DResult& r) {
  double sum = 0;
  for (auto [a, b, c, d] : r.tets) {
    auto u = r.points[b], v = r.points[c], w = r.points[d], o = r.points[a];
    double ux = u.x - o.x, uy = u.y - o.y, uz = u.z - o.z, vx = v.x - o.x, vy = v.y - o.y, vz = v.z - o.z;
    double wx = w.x - o.x, wy = w.y - o.y, wz = w.z - o.z;
    sum += (ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx)) / 6.0;
  }
  return sum;
}

TEST(Gabriel3DRefine, ObtusePrismConvergesWithTwoSteinerPoints) {
  // Right prism of height 1 over the triangle (0,0), (2,0), (1, tan 30deg) (angles 30, 30, 120 degrees). The side
  // rectangle opposite the 120-degree corner has its triangles' spheres centered at its center (1, 0, 0.5) with
  // radius sqrt(4 + 1)/2 = 1.118; the obtuse corners (1, 0.577, 0 or 1) are at sqrt(0.333 + 0.25) = 0.764: inside.
  // Splitting the two long edges at their midpoints (1, 0, 0) and (1, 0, 1) cuts the rectangle into two 1 x 1
  // squares (spheres of radius 0.707 around (0.5 or 1.5, 0, 0.5); the obtuse corners are at distance
  // sqrt(0.25 + 0.333 + 0.25) = 0.913: outside), and the new edge halves of length 1 have spheres of radius 0.5
  // that hold no vertex. Everything else is Gabriel from the start.
  PLC3 plc;
  const double h = std::tan(30.0 * 3.14159265358979323846 / 180.0);
  plc.points = {{0, 0, 0}, {2, 0, 0}, {1, h, 0}, {0, 0, 1}, {2, 0, 1}, {1, h, 1}};
  plc.triangles = {{0, 2, 1}, {3, 4, 5}, {0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}, {2, 0, 3}, {2, 3, 5}};
  plc.facet_ids = {0, 1, 2, 2, 3, 3, 4, 4};
  auto r = refine_gabriel(plc, {});
  EXPECT_EQ(r.status, RefineStatus::Converged) << r.diagnosis.stop_reason;
  EXPECT_EQ(r.steiner_on_segments, 2);
  EXPECT_EQ(r.steiner_on_facets, 0);
  EXPECT_TRUE(r.certificate.faces.empty());
  EXPECT_TRUE(r.certificate.segments.empty());
  EXPECT_NEAR(volume(r), h, 1e-12);  // base area 2 * h / 2, height 1
}

TEST(Gabriel3DRefine, ShellSplitsAtPowerOfTwoFromInputVertex) {
  // A single dangling segment from input vertex 0 at the origin to (10, 0, 0), encroached by (3, 0.5, 0); the
  // first split is the midpoint 5 (both ends are input vertices); the next split of [0, 5] has one input end and
  // length 5: the power of two in [5/3, 10/3] is 2, so the split point is (2, 0, 0).
  PLC3 plc;
  plc.points = {{0, 0, 0}, {10, 0, 0}, {3, 0.5, 0}, {5, 5, 5}};
  plc.segments = {{0, 1}};
  Refine3DOptions o;
  auto r = refine_gabriel(plc, o);
  ASSERT_GE(r.points.size(), 6u);
  EXPECT_EQ(r.points[4].x, 5.0);
  EXPECT_EQ(r.points[5].x, 2.0);
  o.split = SplitRule::Midpoint;
  auto m = refine_gabriel(plc, o);
  ASSERT_GE(m.points.size(), 6u);
  EXPECT_EQ(m.points[5].x, 2.5);
}

TEST(Gabriel3DRefine, BudgetIsAStatus) {
  PLC3 plc = flat_tetrahedron_plc();
  Refine3DOptions o;
  o.max_steiner = 1;
  auto r = refine_gabriel(plc, o);
  EXPECT_EQ(r.status, RefineStatus::BudgetExhausted);
  EXPECT_EQ(r.steiner_on_segments + r.steiner_on_facets, 1);
  o.max_steiner = 1000;
  o.min_length = 0.9;  // edges are sqrt(3) = 1.73 or 1.005 long: any split makes a piece < 0.87 < 0.9
  EXPECT_EQ(refine_gabriel(plc, o).status, RefineStatus::MinLengthReached);
}

}  // namespace
}  // namespace nonobtuse

namespace nonobtuse {
namespace {

// The flat tetrahedron (edges at 5.7 degrees to the base facet) keeps the refinement busy until its budget. In
// Debug builds (NONOBTUSE_CHECK_INVARIANTS) every insertion re-validates the facets' triangulations and the
// subsegments; here the outcome must be consistent with its certificate.
TEST(Gabriel3DRefine, FlatTetrahedronRunsToItsBudgetConsistently) {
  Refine3DOptions o;
  o.max_steiner = 200;
  auto r = refine_gabriel(flat_tetrahedron_plc(), o);
  bool clean = r.certificate.faces.empty() && r.certificate.segments.empty();
  EXPECT_EQ(r.status == RefineStatus::Converged, clean) << r.diagnosis.stop_reason;
  EXPECT_LE(r.steiner_on_segments + r.steiner_on_facets, 200);
  ASSERT_FALSE(r.diagnosis.smallest_angles.empty());
  EXPECT_EQ(r.diagnosis.smallest_angles[0].kind, "segment-facet");
  EXPECT_NEAR(r.diagnosis.smallest_angles[0].degrees, std::atan(0.1) * 180.0 / 3.14159265358979323846, 1e-9);
}

}  // namespace
}  // namespace nonobtuse

namespace nonobtuse {
namespace {

// A dangling segment from (0, 0, 0) to (10, 0, 0) with one vertex v off it; (5, 5, 5) is far outside every sphere
// (distance sqrt(50) = 7.07 > 5 from the center of [0, 10]).
PLC3 segment_with_one_encroacher(const Point3& v) {
  PLC3 plc;
  plc.points = {{0, 0, 0}, {10, 0, 0}, v, {5, 5, 5}};
  plc.segments = {{0, 1}};
  return plc;
}

TEST(Gabriel3DGreedy, OnePointWhereMidpointNeedsFour) {
  // v = (3, 0.5, 0) encroaches [0, 10] (distance 2.05 from the center 5 < radius 5).
  // Greedy: from 0 the free prefix ends at t = |v|^2 / (v·(10, 0, 0)) = 9.25 / 30 = 0.308; from 10 with
  // w = v - (10, 0, 0) = (-7, 0.5, 0): t = |w|^2 / (w·(-10, 0, 0)) = 49.25 / 70 = 0.7036, the longer one, and the
  // rest 0.296 is above the 1/4 guard. So x = 10 - 7.0357 = 2.9643, with v on the sphere of [x, 10] (right angle
  // at v); [0, x] (center 1.482, radius 1.482) has v at distance sqrt(1.518^2 + 0.25) = 1.598: outside. One point.
  // Midpoint: 5; [0, 5] (center 2.5, radius 2.5, v at 0.707): 2.5; [2.5, 5] (center 3.75, radius 1.25, v at
  // 0.901): 3.75; [2.5, 3.75] (center 3.125, radius 0.625, v at 0.515): 3.125; then [2.5, 3.125] (v at 0.534 from
  // 2.8125 > 0.3125) and [3.125, 3.75] (v at 0.664 from 3.4375) are free. Four points.
  PLC3 plc = segment_with_one_encroacher({3, 0.5, 0});
  Refine3DOptions o;
  o.split = SplitRule::Greedy;
  auto g = refine_gabriel(plc, o);
  EXPECT_EQ(g.status, RefineStatus::Converged) << g.diagnosis.stop_reason;
  ASSERT_EQ(g.steiner_on_segments, 1);
  EXPECT_EQ(g.greedy_splits, 1);
  EXPECT_NEAR(g.points[4].x, 10.0 - 49.25 / 7.0, 1e-12);
  EXPECT_EQ(g.points[4].y, 0.0);
  o.split = SplitRule::Midpoint;
  auto m = refine_gabriel(plc, o);
  EXPECT_EQ(m.status, RefineStatus::Converged) << m.diagnosis.stop_reason;
  EXPECT_EQ(m.steiner_on_segments, 4);
  EXPECT_EQ(m.greedy_splits, 0);
}

TEST(Gabriel3DGreedy, ShortRestFallsBackToTheShellsRule) {
  // v = (9, 0.5, 0): from 0 the free prefix is 81.25 / 90 = 0.903 of the segment, leaving a rest of 0.097 < 1/4;
  // from 10 it is 1.25 / 10 = 0.125 < 1/4. The guard refuses both: the shells rule splits at the midpoint (both
  // ends are input vertices), (5, 0, 0).
  auto r = refine_gabriel(segment_with_one_encroacher({9, 0.5, 0}), {.split = SplitRule::Greedy});
  ASSERT_GE(r.points.size(), 5u);
  EXPECT_EQ(r.points[4].x, 5.0);
}

TEST(Gabriel3DGreedy, AcuteInputVertexKeepsShells) {
  // Segments from the origin to (10, 0, 0) and to (10, 2, 0) meet at atan(0.2) = 11.3 degrees (acute), with the
  // free vertex (3, 0.5, 0) between them encroaching both. A subsegment ending at the origin only arises from
  // splitting one that ends there, which the shells rule splits (the midpoint when both ends are input vertices):
  // so the other end of every final subsegment at the origin is an input vertex, the midpoint of an input segment
  // (distance 5 or sqrt(26)), or at a power-of-two distance (up to the rounding of the point). Away from the
  // origin the greedy rule is used: [2, 5] on the first segment (after the midpoint 5 and the shell at 2) still
  // has (3, 0.5, 0) inside (center 3.5, radius 1.5, distance 0.707).
  PLC3 plc;
  plc.points = {{0, 0, 0}, {10, 0, 0}, {10, 2, 0}, {3, 0.5, 0}};
  plc.segments = {{0, 1}, {0, 2}};
  auto g = refine_gabriel(plc, {.split = SplitRule::Greedy});
  EXPECT_EQ(g.status, RefineStatus::Converged) << g.diagnosis.stop_reason;
  EXPECT_GT(g.greedy_splits, 0);
  int at_origin = 0;
  for (auto [a, b] : g.segments) {
    if (a != 0 && b != 0) continue;
    ++at_origin;
    int e = a == 0 ? b : a;
    if (e < 4) continue;
    const Point3& p = g.points[e];
    double d = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    bool midpoint = std::abs(d - 5.0) < 1e-12 || std::abs(d - std::sqrt(26.0)) < 1e-12;
    double k = std::round(std::log2(d));
    EXPECT_TRUE(midpoint || std::abs(d - std::exp2(k)) < 1e-12 * d) << "distance " << d;
  }
  EXPECT_EQ(at_origin, 2);
}

}  // namespace
}  // namespace nonobtuse
