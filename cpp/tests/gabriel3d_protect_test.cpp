// Protecting balls of the protected Gabriel strategy: their radii (hand-checked), and the protected subsegments
// and sphere points they produce.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <tuple>
#include <vector>

#include "gabriel3d_protect.h"

namespace nonobtuse::gabriel3d {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The box [-1, 1]^3 (bottom facet a fan around the foot (-0.25, 0.0625, -1), point 8) with dangling segments of
// length 0.5 from the foot at angle theta to the bottom facet, in the directions `azimuths` (radians).
PLC3 box_with_segments(double theta_degrees, const std::vector<double>& azimuths) {
  PLC3 plc;
  for (double z : {-1.0, 1.0})
    for (auto [x, y] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) plc.points.push_back({x, y, z});
  const Point3 foot{-0.25, 0.0625, -1.0};
  plc.points.push_back(foot);
  const double t = theta_degrees * kPi / 180.0;
  for (double a : azimuths) {
    plc.points.push_back(
        {foot.x + 0.5 * std::cos(t) * std::cos(a), foot.y + 0.5 * std::cos(t) * std::sin(a), foot.z + 0.5 * std::sin(t)});
    plc.segments.push_back({8, static_cast<int>(plc.points.size()) - 1});
  }
  auto facet = [&](int id, std::vector<Triangle> tris) {
    for (const auto& tri : tris) plc.triangles.push_back(tri), plc.facet_ids.push_back(id);
  };
  facet(0, {{8, 1, 0}, {8, 2, 1}, {8, 3, 2}, {8, 0, 3}});  // bottom, facing -z
  facet(1, {{4, 5, 6}, {4, 6, 7}});
  for (int i = 0; i < 4; ++i) {
    int j = (i + 1) % 4;
    facet(2 + i, {{i, j, 4 + j}, {i, 4 + j, 4 + i}});
  }
  for (int i = 0; i < 4; ++i) {
    plc.segments.push_back({i, (i + 1) % 4});
    plc.segments.push_back({4 + i, 4 + (i + 1) % 4});
    plc.segments.push_back({i, 4 + i});
  }
  return plc;
}

TEST(Gabriel3DProtect, RadiusIsAPowerOfTwoAtMostAQuarterOfTheFeatureSize) {
  EXPECT_EQ(protecting_radius(1.0), 0.25);
  EXPECT_EQ(protecting_radius(0.9), 0.125);  // 0.225 -> 0.125
  EXPECT_EQ(protecting_radius(0.5), 0.125);
  EXPECT_EQ(protecting_radius(3.0), 0.5);  // 0.75 -> 0.5
}

TEST(Gabriel3DProtect, PowerOfTwoPieceCutsWithinOneToTwo) {
  EXPECT_EQ(power_of_two_piece(1.0), 0.5);   // 1 < 1.5: 0.5 and 0.5
  EXPECT_EQ(power_of_two_piece(2.0), 1.0);   // 1 and 1
  EXPECT_EQ(power_of_two_piece(3.5), 2.0);   // 2 and 1.5
  EXPECT_EQ(power_of_two_piece(0.7), 0.25);  // 0.25 and 0.45 (0.5 would leave 0.2)
}

TEST(Gabriel3DProtect, SegmentsThroughAnApexAreSplitWhereTheyLeaveItsBall) {
  // Two segments of length 0.5 from the foot (ball radius 0.125, as below): each is split once, at t = 0.125 / 0.5
  // from the foot (exactly 1/4 when the foot is the segment's first end, 3/4 when its second); the box edges, whose
  // ends are no apices, never.
  PLC3 plc = box_with_segments(5.0, {0.0, kPi / 2});
  PlcState s = build_plc_state(plc);
  const auto balls = protecting_balls(s, plc);
  ASSERT_EQ(balls.size(), 1u);
  std::vector<std::tuple<int, int, double>> calls;
  split_segments_on_spheres(s, balls, [&](int from, int to, double t) { calls.emplace_back(from, to, t); return -1; },
                            [] { return true; });
  ASSERT_EQ(calls.size(), 2u);
  for (const auto& [from, to, t] : calls) {
    ASSERT_TRUE(from == 8 || to == 8);
    EXPECT_NEAR(from == 8 ? t : 1.0 - t, 0.25, 1e-15);
  }
  calls.clear();
  split_segments_on_spheres(s, balls, [&](int from, int to, double t) { calls.emplace_back(from, to, t); return -1; },
                            [] { return false; });
  EXPECT_TRUE(calls.empty());
}

TEST(Gabriel3DProtect, OneBallAtTheFootSizedByTheNearestFeature) {
  // The foot's local feature size: the segment's far end at 0.5 (the box wall x = -1 is 0.75 away, the nearest box
  // edge 0.75, the corners farther), so its ball has radius 0.125; no other vertex has a segment leaning over a
  // facet (the box edges lie in their facets, and the far end is on no facet).
  PLC3 plc = box_with_segments(5.0, {0.0});
  PlcState s = build_plc_state(plc);
  EXPECT_NEAR(local_feature_size(s, plc, 8), 0.5, 1e-15);
  auto balls = protecting_balls(s, plc);
  ASSERT_EQ(balls.size(), 1u);
  EXPECT_EQ(balls[0].apex, 8);
  EXPECT_EQ(balls[0].radius, 0.125);
  Protection protection(s, balls);
  EXPECT_EQ(protection.strictly_containing(P3(-0.25 + 0.12, 0.0625, -1.0)), &protection.balls()[0]);
  EXPECT_EQ(protection.strictly_containing(P3(-0.25 + 0.13, 0.0625, -1.0)), nullptr);
  EXPECT_EQ(protection.strictly_containing(P3(-0.25 + 0.125, 0.0625, -1.0)), nullptr);  // on the sphere
}

TEST(Gabriel3DProtect, OntoSphereMovesAlongTheRay) {
  auto p = onto_sphere(P3(1, 2, 3), 0.5, P3(1, 2, 3.1));
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(*p, P3(1, 2, 3.5));
  EXPECT_FALSE(onto_sphere(P3(1, 2, 3), 0.5, P3(1, 2, 3)).has_value());
}

TEST(Gabriel3DProtect, ArcSplitPointRefusesAPointWhoseDirectionFromTheApexIsRounding) {
  // The foot (-0.25, 0.0625, -1) on the bottom facet z = -1, ball radius 0.125. A split point one ulp above the foot
  // has the direction +z from it: moved along that ray it would land at z = -0.875, r off the facet's plane. It is
  // refused, as the foot itself is; a point 0.01 from the foot in the plane goes on the sphere, in the plane.
  PLC3 plc = box_with_segments(5.0, {0.0});
  PlcState s = build_plc_state(plc);
  const auto balls = protecting_balls(s, plc);
  ASSERT_EQ(balls.size(), 1u);
  const Facet& bottom = *s.facets[s.point_facets[8].at(0)];
  const std::set<int> none;
  EXPECT_FALSE(arc_split_point(s, bottom, balls[0], P3(-0.25, 0.0625, std::nextafter(-1.0, 0.0)), none, none));
  EXPECT_FALSE(arc_split_point(s, bottom, balls[0], P3(-0.25, 0.0625, -1.0), none, none));
  const auto y = arc_split_point(s, bottom, balls[0], P3(-0.24, 0.0625, -1.0), none, none);
  ASSERT_TRUE(y);
  EXPECT_EQ(*y, P3(-0.125, 0.0625, -1.0));
}

// Three segments at 3 degrees to the bottom facet, 10 degrees apart in azimuth: the protected strategy converges,
// the exact certificate is clean, nothing but the foot lies strictly inside the ball, and no point of the sphere
// encroaches a protected subsegment [foot, x] (every x: the point of a segment at distance r from the foot).
TEST(Gabriel3DProtect, ProtectedSubsegmentsAreNeverEncroached) {
  PLC3 plc = box_with_segments(3.0, {0.0, 10.0 * kPi / 180.0, 20.0 * kPi / 180.0});
  PlcState state = build_plc_state(plc);
  auto balls = protecting_balls(state, plc);
  ASSERT_EQ(balls.size(), 1u);
  // The far ends are 0.5 from the foot up to rounding (0.49999999999999994 here): r is 0.125 or 0.0625.
  const double radius = balls[0].radius;
  EXPECT_EQ(radius, protecting_radius(local_feature_size(state, plc, 8)));
  EXPECT_TRUE(radius == 0.125 || radius == 0.0625);
  Refine3DOptions o;
  o.split = SplitRule::Protected;
  o.min_length = 1e-6;
  auto r = refine_gabriel(plc, o);
  ASSERT_EQ(r.status, RefineStatus::Converged) << r.diagnosis.stop_reason;
  EXPECT_EQ(r.strategy, "protected");
  EXPECT_EQ(r.protecting_balls, 1);
  EXPECT_TRUE(r.certificate.faces.empty() && r.certificate.segments.empty());
  const P3 foot = to_cgal(plc.points[8]);
  std::vector<P3> ends, on_sphere;
  for (const auto& seg : r.segments) {
    if (seg[0] != 8 && seg[1] != 8) continue;
    const P3 x = to_cgal(r.points[seg[0] == 8 ? seg[1] : seg[0]]);
    EXPECT_NEAR(std::sqrt(CGAL::to_double(CGAL::squared_distance(foot, x))), radius, 1e-15);
    ends.push_back(x);
  }
  EXPECT_EQ(ends.size(), 3u);  // only the dangling segments end at the foot
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const P3 p = to_cgal(r.points[i]);
    if (i == 8) continue;
    const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(foot, p)));
    EXPECT_GT(d, radius * (1 - 1e-14)) << "point " << i << " inside the ball";
    if (d < radius * (1 + 1e-14)) on_sphere.push_back(p);
  }
  EXPECT_GT(on_sphere.size(), ends.size());  // moved circumcenters on the bottom facet's arc
  for (const P3& x : ends)
    for (const P3& y : on_sphere)
      EXPECT_NE(CGAL::side_of_bounded_sphere(foot, x, y), CGAL::ON_BOUNDED_SIDE);
}

TEST(Gabriel3DProtect, FallbackRunsWhereShellsCascade) {
  // At 1 degree concentric shells alone run the subsegment at the foot down to min_length; the default then runs
  // the protected strategy from the input.
  PLC3 plc = box_with_segments(1.0, {0.0});
  Refine3DOptions o;
  o.min_length = 1e-6;
  o.protected_fallback = false;
  auto shells = refine_gabriel(plc, o);
  EXPECT_NE(shells.status, RefineStatus::Converged);
  EXPECT_EQ(shells.strategy, "shells");
  o.protected_fallback = true;
  auto r = refine_gabriel(plc, o);
  EXPECT_EQ(r.status, RefineStatus::Converged) << r.diagnosis.stop_reason;
  EXPECT_EQ(r.strategy, "shells+protected");
  EXPECT_EQ(r.other_attempt.rfind(std::string("shells: ") + to_string(shells.status), 0), 0u) << r.other_attempt;
}

}  // namespace
}  // namespace nonobtuse::gabriel3d
