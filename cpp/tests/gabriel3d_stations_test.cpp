// Stations: the rounding search for an image at equal distance from an apex, at step.off's vertex 6 (coordinates
// near 1e3) with two segments 3.05e-7 rad apart, where the window of valid radii is a relative theta^2 (9.3e-14):
// found down to radius 0.004 (step.off needs about that at its vertex 5).
#include <gtest/gtest.h>

#include <cmath>

#include "gabriel3d_stations.h"

namespace nonobtuse::gabriel3d {
namespace {

bool inside(const P3& a, const P3& b, const P3& p) {
  return CGAL::side_of_bounded_sphere(a, b, p) == CGAL::ON_BOUNDED_SIDE;
}

TEST(Gabriel3DStations, RoundingFindsAnEqualRadiusImageAtATinyApexAngle) {
  const P3 apex(601.21307373046875, -2771.328857421875, -528.541259765625);  // step.off's vertex 6
  double u[3] = {-312.95, 1652.62, 1367.70};  // toward vertex 1
  const double norm_u = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  for (double& x : u) x /= norm_u;
  // v: u turned by theta toward w, a unit vector orthogonal to u.
  const double theta = 3.05e-7;
  double w[3] = {0.0, -u[2], u[1]};
  const double norm_w = std::sqrt(w[1] * w[1] + w[2] * w[2]);
  for (double& x : w) x /= norm_w;
  double v[3];
  for (int d = 0; d < 3; ++d) v[d] = std::cos(theta) * u[d] + std::sin(theta) * w[d];
  for (double r : {1.0, 0.1, 0.01, 0.004}) {
    const P3 a(apex.x() + r * u[0], apex.y() + r * u[1], apex.z() + r * u[2]);
    const double radius = std::sqrt(CGAL::to_double(CGAL::squared_distance(a, apex)));
    const P3 ideal(apex.x() + radius * v[0], apex.y() + radius * v[1], apex.z() + radius * v[2]);
    const auto accept = [&](const P3& q) { return !inside(apex, a, q) && !inside(apex, q, a); };
    const std::optional<P3> q = station_rounding(ideal, &apex, radius, accept);
    ASSERT_TRUE(q) << "no rounding found at radius " << r;
    EXPECT_FALSE(inside(apex, a, *q));
    EXPECT_FALSE(inside(apex, *q, a));
    EXPECT_LT(std::sqrt(CGAL::to_double(CGAL::squared_distance(*q, ideal))), 1e-10);  // a few ulps from the line
  }
}

}  // namespace
}  // namespace nonobtuse::gabriel3d
