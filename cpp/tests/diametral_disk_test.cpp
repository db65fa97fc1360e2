// The exact diametral-disk predicates every piece of the refinement decides with.
#include "diametral_disk.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace nonobtuse::refine2d {
namespace {

// The filtered obtuse test agrees with CGAL's exact angle, also where the dot product is zero or within rounding
// of it: (a - apex) . (b - apex) for apex on the circle with diameter ab is exactly 0 (right angle), and the
// points nudged by one ulp off it decide by the exact fallback.
TEST(DiametralDisk, ObtuseAgreesWithTheExactAngle) {
  const Point a(0, 0), b(10, 0);
  std::vector<Point> apexes = {{5, 5}, {5, 4}, {5, 6}, {3, 4.58257569495584}, {0.1, 0.2}, {1e-300, 1e-300}};
  apexes.emplace_back(5, std::nextafter(5.0, 0.0));  // inside the circle by one ulp: obtuse
  apexes.emplace_back(5, std::nextafter(5.0, 9.0));  // outside by one ulp: acute
  for (const Point& p : apexes) EXPECT_EQ(obtuse(a, p, b), CGAL::angle(a, p, b) == CGAL::OBTUSE) << p;
  EXPECT_FALSE(obtuse(a, Point(5, 5), b));  // right angle: 25 - 25 = 0
  EXPECT_TRUE(obtuse(a, Point(5, std::nextafter(5.0, 0.0)), b));
}

// Encroachment is strict and one-sided: (5, 4) is inside the disk of (0,0)-(10,0) ((s - q).(e - q) = -25 + 16 < 0)
// and on its left; (5, -4) is inside but on the right; (5, 5) is on the circle (a right angle, no encroachment).
TEST(DiametralDisk, EncroachmentIsStrictAndOnTheLeft) {
  const Point s(0, 0), e(10, 0);
  EXPECT_TRUE(encroaches(s, e, Point(5, 4)));
  EXPECT_FALSE(encroaches(s, e, Point(5, -4)));
  EXPECT_TRUE(encroaches(e, s, Point(5, -4)));
  EXPECT_FALSE(encroaches(s, e, Point(5, 5)));
  EXPECT_TRUE(inside_diametral_disk(s, e, Point(5, -4)));
  EXPECT_FALSE(inside_diametral_disk(s, e, Point(5, 0)));  // on the segment itself: not in either open half-disk
}

}  // namespace
}  // namespace nonobtuse::refine2d
