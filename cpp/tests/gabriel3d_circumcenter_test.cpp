// rounded_circumcenter: the Steiner point of a subfacet split, also for needle triangles.
#include <gtest/gtest.h>

#include <cmath>

#include "gabriel3d_index.h"

namespace nonobtuse::gabriel3d {
namespace {

TEST(Gabriel3DCircumcenter, NeedleTriangleGetsTheExactCenterRounded) {
  // Apex 1e-200 above the midpoint of a unit base: the floating-point construction divides by
  // 2 |(b - a) x (c - a)|^2 = 2e-400, which underflows to 0 (before the fix: NaN coordinates, and GMP raised SIGFPE
  // when the facet's exact 2D triangulation read them). The exact center: x = 0.5 and, from
  // 0.25 + y^2 = (y - h)^2, y = (h^2 - 0.25) / (2 h) = -1.25e199 for h = 1e-200 (to rounding).
  const double h = 1e-200;
  const P3 a(0, 0, 0), b(1, 0, 0), c(0.5, h, 0);
  const P3 naive = CGAL::circumcenter(a, b, c);
  ASSERT_FALSE(std::isfinite(naive.x()) && std::isfinite(naive.y()) && std::isfinite(naive.z()));
  auto center = rounded_circumcenter(a, b, c);
  ASSERT_TRUE(center.has_value());
  EXPECT_EQ(center->x(), 0.5);
  EXPECT_NEAR(center->y() / (-0.25 / (2 * h)), 1.0, 1e-12);
  EXPECT_EQ(center->z(), 0.0);
}

TEST(Gabriel3DCircumcenter, CollinearHasNone) {
  EXPECT_FALSE(rounded_circumcenter(P3(0, 0, 0), P3(1, 1, 1), P3(2, 2, 2)).has_value());
}

TEST(Gabriel3DCircumcenter, OrdinaryTriangleUsesTheFloatingPointCenter) {
  // Right triangle: the center is the hypotenuse's midpoint (0.5, 0.5, 0), exact in doubles.
  auto center = rounded_circumcenter(P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0));
  ASSERT_TRUE(center.has_value());
  EXPECT_EQ(*center, P3(0.5, 0.5, 0));
}

}  // namespace
}  // namespace nonobtuse::gabriel3d
