// Rounding of Steiner points (candidates_near) and the shared refinement state.
#include "refine2d_state.h"

#include <gtest/gtest.h>

namespace nonobtuse::refine2d {
namespace {

// Integer endpoints below 2^20: the dyadic parameter k / 2^m with m + 20 <= 53 gives an exactly representable
// point on the line, so the first candidate is exactly collinear, and within 2^-32 of the target parameter.
TEST(Refine2dState, IntegerEdgeGetsAnExactlyCollinearPoint) {
  Point s(3, 7), e(1000003, 700001);
  auto c = candidates_near(s, e, 0.3);
  ASSERT_FALSE(c.empty());
  EXPECT_EQ(CGAL::orientation(s, e, c.front()), CGAL::COLLINEAR);
  EXPECT_NEAR((c.front().x() - 3) / 1000000, 0.3, 0x1p-32);
}

// Every candidate lies strictly between s and e (exact: the angle at it is obtuse), whatever the coordinates.
TEST(Refine2dState, CandidatesAreStrictlyInside) {
  Point s(909090.9090909091, -62.0), e(910544.3021892799, -59.553939415441825);
  for (double t : {1e-12, 0.25, 0.899, 1 - 1e-12})
    for (const Point& p : candidates_near(s, e, t)) {
      EXPECT_NE(p, s);
      EXPECT_NE(p, e);
      EXPECT_EQ(CGAL::angle(s, p, e), CGAL::OBTUSE);
    }
}

// The first candidate off a non-representable line is on the outside (right of s -> e) when one is offered there.
TEST(Refine2dState, OffLineCandidatesPreferTheOutside) {
  Point s(0.1, 0.2), e(0.7, 0.3);
  auto c = candidates_near(s, e, 0.37);
  ASSERT_FALSE(c.empty());
  auto o = CGAL::orientation(s, e, c.front());
  EXPECT_NE(o, CGAL::LEFT_TURN);
}

}  // namespace
}  // namespace nonobtuse::refine2d
