// Interior quality refinement (quality2d.cpp): the angle and area bounds reached, the boundary certificate kept,
// small input angles left alone with a status, budgets respected. Angles and areas are recomputed here from the
// returned mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "nonobtuse/check2d.h"
#include "nonobtuse/refine2d.h"
#include "quality2d.h"
#include "quality2d_boundary.h"

namespace nonobtuse {
namespace {

double smallest_angle(const Mesh2& m, const Triangle& t) {
  double best = 180.0;
  for (int i = 0; i < 3; ++i) {
    const Point2 &v = m.points[t[i]], &a = m.points[t[(i + 1) % 3]], &b = m.points[t[(i + 2) % 3]];
    const double ux = a.x - v.x, uy = a.y - v.y, wx = b.x - v.x, wy = b.y - v.y;
    best = std::min(best, std::atan2(std::abs(ux * wy - uy * wx), ux * wx + uy * wy) * 180.0 / M_PI);
  }
  return best;
}

double area(const Mesh2& m, const Triangle& t) {
  const Point2 &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]];
  return 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

Refine2DResult run(const Domain2& d, const Quality2DOptions& q, long long budget = -1) {
  Refine2DOptions o;
  o.quality = q;
  o.max_steiner = budget;
  o.check_every_split = true;
  Refine2DResult r = refine(d, o);
  EXPECT_EQ(r.obtuse_boundary_sides, count_obtuse_boundary_sides(r.mesh));
  return r;
}

// An L-shaped hexagon (angles 90 and 270 only) with an interior interface from the reflex corner.
Domain2 l_shape() {
  Domain2 d;
  d.points = {{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 10}, {0, 10}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 0}, {3, 0}};
  return d;
}

// The L's first pass by hand. The interface (0, 0)-(4, 4) makes 45 degrees with the edges at both its ends, so
// the sides split there get shells (an interface meets the junction: no greedy rule). The input CDT has the
// triangles (0, 0), (10, 0), (4, 4) and (0, 0), (4, 4), (0, 10), obtuse at (4, 4) opposite the edges from (0, 0)
// (dot products -8 and -8); both are split at the smallest power of two >= 10 / 3 from (0, 0), 4: at (4, 0) and
// (0, 4), exactly (the plain construction; rounded ulps off, the right angles there at (4, 0) and (0, 4) opposite
// the interface turned obtuse). Then every triangle has its smallest angle >= atan(2 / 3) = 33.7 degrees (the
// halves of the 6 x 4 and 4 x 6 rectangles, the isosceles right ones 4 x 4): nothing more goes in.
TEST(Quality2d, MinAngleReachedAndBoundaryCertified) {
  Quality2DOptions q;
  q.min_angle_degrees = 30.0;
  Refine2DResult r = run(l_shape(), q);
  ASSERT_EQ(r.status, RefineStatus::Converged);
  EXPECT_EQ(r.obtuse_boundary_sides, 0);
  // Without the bound the L has triangles of 26.57 degrees (atan(1/2)): points were needed.
  EXPECT_GT(r.quality.boundary_splits + r.quality.interior_points, 0);
  EXPECT_EQ(r.quality.small_angle_triangles, 0);  // the interface makes 45 degrees with the edges at (4, 4)
  double worst = 180.0;
  for (const Triangle& t : r.mesh.triangles) worst = std::min(worst, smallest_angle(r.mesh, t));
  EXPECT_GE(worst, 30.0 - 1e-9);
  EXPECT_NEAR(worst, r.quality.min_angle_degrees, 1e-9);
  EXPECT_EQ(r.quality.triangles, static_cast<long long>(r.mesh.triangles.size()));
  EXPECT_EQ(r.mesh.points.size(), l_shape().points.size() + r.steiner_points + r.quality.interior_points);
  // The hand count above: exactly the two shells, nothing inside.
  EXPECT_EQ(r.steiner_points, 2);
  EXPECT_EQ(r.quality.interior_points, 0);
  std::vector<std::pair<double, double>> added;
  for (std::size_t i = 6; i < r.mesh.points.size(); ++i) added.emplace_back(r.mesh.points[i].x, r.mesh.points[i].y);
  std::sort(added.begin(), added.end());
  EXPECT_EQ(added, (std::vector<std::pair<double, double>>{{0.0, 4.0}, {4.0, 0.0}}));
  EXPECT_NEAR(worst, std::atan(2.0 / 3.0) * 180.0 / M_PI, 1e-9);
}

// nearest_shell: the smallest power of two >= |e - s| / 3, as a parameter of [s, e].
TEST(Quality2d, NearestShellIsTheSmallestPowerOfTwoOfAThird) {
  using refine2d::Point;
  EXPECT_EQ(refine2d::nearest_shell(Point(0, 0), Point(10, 0)), 0.4);            // 10 / 3 = 3.3 -> 4
  EXPECT_EQ(refine2d::nearest_shell(Point(0, 0), Point(768, 0)), 256.0 / 768);    // a third that is 2^8 stays
  EXPECT_EQ(refine2d::nearest_shell(Point(1, 1), Point(4, 5)), 2.0 / 5);          // |e - s| = 5: 1.67 -> 2
  // A subsegment a power of two long up to rounding (a shell point an ulp short of 256 from its junction) is
  // halved: 85.3 -> 128, where the largest power of two at or before its midpoint (127.99...) was 64.
  const double x = std::nextafter(256.0, 0.0);
  EXPECT_EQ(refine2d::nearest_shell(Point(0, 0), Point(x, 0)), 128.0 / x);
  for (double length : {1e-9, 0.3, 1.0, 2.9999, 3.0, 3.0001, 1e7}) {  // both pieces at least a third
    const double t = refine2d::nearest_shell(Point(0, 0), Point(length, 0));
    EXPECT_GE(t * 3.0, 1.0 - 1e-15) << length;
    EXPECT_LE(t * 3.0, 2.0 + 1e-15) << length;
  }
}

TEST(Quality2d, MaxAreaAndRegionAreas) {
  Domain2 d = l_shape();
  d.regions = {{{1, 6}, 1.0}, {{6, 1}, 2.0}};  // the interface (4,4)-(0,0) splits the L into two regions
  Quality2DOptions q;
  q.max_area = 2.0;
  q.region_max_area = {{2.0, 0.25}};
  Refine2DResult r = run(d, q);
  ASSERT_EQ(r.status, RefineStatus::Converged);
  int small_region = 0;
  for (std::size_t i = 0; i < r.mesh.triangles.size(); ++i) {
    const double a = area(r.mesh, r.mesh.triangles[i]);
    EXPECT_LE(a, r.mesh.triangle_region[i] == 2.0 ? 0.25 : 2.0);
    small_region += r.mesh.triangle_region[i] == 2.0;
  }
  EXPECT_GE(small_region, 2 * 32 / 0.25 / 2);  // region 2 has area 32: at least 128 triangles of area <= 0.25
}

TEST(Quality2d, SizeFunctionIsObeyedAtCentroids) {
  Quality2DOptions q;
  q.max_area_at = [](double x, double) { return 0.05 + 0.1 * x; };
  Refine2DResult r = run(l_shape(), q);
  ASSERT_EQ(r.status, RefineStatus::Converged);
  for (const Triangle& t : r.mesh.triangles) {
    const Point2 &a = r.mesh.points[t[0]], &b = r.mesh.points[t[1]], &c = r.mesh.points[t[2]];
    EXPECT_LE(area(r.mesh, t), 0.05 + 0.1 * (a.x + b.x + c.x) / 3 + 1e-12);
  }
}

TEST(Quality2d, SmallInputAngleTerminatesAndIsReported) {
  // A 5-degree wedge closed by an arc of chords: triangles at the apex cannot all reach 25 degrees.
  Domain2 d;
  d.points.push_back({0, 0});
  const double a = 5.0 * M_PI / 180.0;
  for (int i = 0; i <= 4; ++i) d.points.push_back({10 * std::cos(a * i / 4), 10 * std::sin(a * i / 4)});
  for (int i = 0; i < 6; ++i) d.segments.push_back({i, (i + 1) % 6});
  Quality2DOptions q;
  q.min_angle_degrees = 25.0;
  Refine2DResult r = run(d, q, 2000);
  EXPECT_EQ(r.obtuse_boundary_sides, 0);
  EXPECT_EQ(r.status, RefineStatus::Converged);
  EXPECT_GT(r.quality.small_angle_triangles, 0);
  EXPECT_GE(r.quality.min_angle_outside_small_angles_degrees, 25.0 - 1e-9);
  EXPECT_LT(r.quality.min_angle_degrees, 25.0);
}

TEST(Quality2d, InteriorBudgetIsAStatus) {
  Quality2DOptions q;
  q.min_angle_degrees = 30.0;
  q.max_area = 1e-3;
  q.max_interior = 10;
  Refine2DResult r = run(l_shape(), q);
  EXPECT_EQ(r.status, RefineStatus::BudgetExhausted);
  EXPECT_EQ(r.quality.interior_points, 10);
  EXPECT_GT(r.quality.bad_triangles, 0);
  EXPECT_EQ(r.obtuse_boundary_sides, 0);  // interior points never break the boundary
}

// cdt_ditch.poly (../shared/data/2d): a channel split by the interface (10, 11) at x = 1.27, which the input vertices
// of both walls encroach. Its lower bound is 2 points, all on the interface. Triangle's midpoints put 3 there (as
// Triangle -pq25D does); minimal_boundary_first gives the greedy boundary's 2, at the lower bound, and the quality
// refinement then keeps them: every triangle reaches 25 degrees with no boundary split and the certificate holds.
TEST(Quality2d, MinimalBoundaryFirstCanNeedFewerPoints) {
  Domain2 d;
  d.points = {{15.2817039560085, -35.8482583312558}, {16.9298083110526, -19.5320252163193},
              {15.2817039560085, 0.9044687862274401}, {17.5890500530702, 18.044754078686},
              {16.1057561335305, 40.7061889605422}, {-16.6915205318468, -35.6010426779992},
              {-14.3017692170329, -14.9173330221958}, {-14.9610109590506, 14.006898408828},
              {-15.0434161768028, 37.9044115569673}, {1.27281693813374, -36.0954739845124},
              {1.27281693813374, 40.62378374279}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {5, 6}, {6, 7}, {7, 8}, {9, 10}, {0, 9}, {5, 9}, {4, 10}, {8, 10}};
  Quality2DOptions q;
  q.min_angle_degrees = 25.0;
  const Refine2DResult midpoints = run(d, q);
  q.minimal_boundary_first = true;
  const Refine2DResult minimal = run(d, q);
  for (const Refine2DResult* r : {&midpoints, &minimal}) {
    EXPECT_EQ(r->status, RefineStatus::Converged) << r->diagnosis.stop_reason;
    EXPECT_EQ(r->obtuse_boundary_sides, 0);
    for (const Triangle& t : r->mesh.triangles) EXPECT_GE(smallest_angle(r->mesh, t), 25.0);
  }
  EXPECT_EQ(minimal.lower_bound, 2);
  EXPECT_EQ(minimal.steiner_points, minimal.lower_bound);
  EXPECT_EQ(minimal.quality.interior_points, 0);
  EXPECT_EQ(midpoints.steiner_points, 3);
}

TEST(Quality2d, OffByDefault) {
  Refine2DResult r = run(l_shape(), Quality2DOptions{});
  EXPECT_EQ(r.quality.interior_points, 0);
  EXPECT_EQ(r.quality.triangles, 0);
  EXPECT_EQ(default_interior_budget(10, 100.0, 0.5), 100 + 100000 + 800);
}

}  // namespace
}  // namespace nonobtuse
