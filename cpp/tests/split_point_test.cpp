// The split point: rounding onto a subsegment (candidates_near, pick_point), splittable and the split itself.
#include "split_point.h"

#include <gtest/gtest.h>

#include <cmath>
#include <tuple>
#include <vector>

#include "refine2d_fixtures.h"
#include "refine2d_state_fixtures.h"

namespace nonobtuse::refine2d {
namespace {

// Integer endpoints below 2^20: the dyadic parameter k / 2^m with m + 20 <= 53 gives an exactly representable
// point on the line, so the first candidate is exactly collinear, and within 2^-32 of the target parameter.
TEST(SplitPoint, IntegerEdgeGetsAnExactlyCollinearPoint) {
  Point s(3, 7), e(1000003, 700001);
  auto c = candidates_near(s, e, 0.3);
  ASSERT_FALSE(c.empty());
  EXPECT_EQ(CGAL::orientation(s, e, c.front()), CGAL::COLLINEAR);
  EXPECT_NEAR((c.front().x() - 3) / 1000000, 0.3, 0x1p-32);
}

// Every candidate lies strictly between s and e (exact: the angle at it is obtuse), whatever the coordinates.
TEST(SplitPoint, CandidatesAreStrictlyInside) {
  Point s(909090.9090909091, -62.0), e(910544.3021892799, -59.553939415441825);
  for (double t : {1e-12, 0.25, 0.899, 1 - 1e-12})
    for (const Point& p : candidates_near(s, e, t)) {
      EXPECT_NE(p, s);
      EXPECT_NE(p, e);
      EXPECT_EQ(CGAL::angle(s, p, e), CGAL::OBTUSE);
    }
}

// pick_point offers the candidates in candidates_near's order (it pops them from a heap instead of sorting).
TEST(SplitPoint, PickPointTriesCandidatesInOrder) {
  for (const auto& [s, e, t] : {std::tuple{Point(3, 7), Point(1000003, 700001), 0.3},
                                std::tuple{Point(0.1, 0.2), Point(0.7, 0.3), 0.37},
                                std::tuple{Point(909090.9090909091, -62.0), Point(910544.3021892799, -59.55), 0.9}}) {
    std::vector<Point> tried;
    Point p;
    EXPECT_FALSE(pick_point(s, e, t, [&](const Point& q) { return tried.push_back(q), false; }, p));
    EXPECT_EQ(tried, candidates_near(s, e, t));
    EXPECT_GT(tried.size(), 10u);
  }
}

// The first candidate off a non-representable line is on the outside (right of s -> e) when one is offered there.
TEST(SplitPoint, OffLineCandidatesPreferTheOutside) {
  Point s(0.1, 0.2), e(0.7, 0.3);
  auto c = candidates_near(s, e, 0.37);
  ASSERT_FALSE(c.empty());
  auto o = CGAL::orientation(s, e, c.front());
  EXPECT_NE(o, CGAL::LEFT_TURN);
}

// Far from the origin: s = (1e9, 1e9) and e = s + (9, 2) ulps (an ulp is 2^-23 there), a segment of 9.2 ulps
// with no double strictly inside it on its line (gcd(9, 2) = 1). Every candidate's offset off the line, in ulps,
// is |9 y - 2 x| / sqrt(85) for its coordinates (x, y) in ulps from s (exact integers: the differences are exact);
// the first candidate is within one ulp of the line, and candidates farther than 2^-8 of the length come in
// increasing offset.
TEST(SplitPoint, FarFromTheOriginCandidatesHugTheLine) {
  const double u = 0x1p-23;
  const Point s(1e9, 1e9), e(1e9 + 9 * u, 1e9 + 2 * u);
  const std::vector<Point> c = candidates_near(s, e, 0.5);
  ASSERT_FALSE(c.empty());
  auto offset = [&](const Point& q) { return std::abs(9 * (q.y() - s.y()) / u - 2 * (q.x() - s.x()) / u); };
  EXPECT_LE(offset(c.front()), std::sqrt(85.0));
  for (std::size_t k = 1; k < c.size(); ++k) EXPECT_LE(offset(c[k - 1]), offset(c[k])) << k;
  for (const Point& q : c) EXPECT_EQ(CGAL::angle(s, q, e), CGAL::OBTUSE);  // strictly between s and e
}

// Figure 5's quadrilateral: the foot of c = (90, 20) on (a, d) is (90, 0), exactly representable, so split_at_foot
// puts the Steiner point there: point index 4, counted once on the input edge (a, d); (a, d) is no constraint any
// more, (a, p) and (p, d) are boundary sides, neither violated (c sees both at a right angle), and the
// triangulation is valid with domain marks equal to a recomputation.
TEST(SplitPoint, SplitAtTheFootOfTheApex) {
  testing::OwningState st(testing::figure5_quadrilateral());
  st.set_check_every_split(true);
  const Side ad{st.v(0), st.v(1)};
  EXPECT_TRUE(splittable(st, ad, Point(90, 0)));
  const int edge = st.edge_of(ad);
  Vertex_handle p = split_at_foot(st, ad, st.v(2)->point());
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p->point(), Point(90, 0));
  EXPECT_EQ(p->info(), 4);
  EXPECT_EQ(st.placed(), 1);
  EXPECT_EQ(st.steiner_edge(4), edge);
  EXPECT_EQ(st.edges()[edge].steiner_points, 1);
  EXPECT_EQ(st.left_face(ad), nullptr);
  for (const Side& side : {Side{st.v(0), p}, Side{p, st.v(1)}}) {
    EXPECT_TRUE(st.is_boundary_side(side));
    EXPECT_FALSE(st.is_violated(side));
    EXPECT_EQ(st.edge_of(side), edge);
  }
  EXPECT_GT(st.queued(), 0u);  // the sides of the changed triangles
  EXPECT_NO_THROW(st.check_invariants());
}

// A point off the line, inside the quadrilateral near (a, d) but beyond c's side: (50, 30) is not in the triangle
// (a, d, c) next to (a, d) (left of c -> a: orientation(c, a, p) is a right turn), so the polyline a-p-d would
// cross the diagonal's triangle and pass c's constraints: not splittable. (50, -1), outside the hull, is.
TEST(SplitPoint, SplittableOnlyInsideTheTriangleBesideTheEdge) {
  testing::OwningState st(testing::figure5_quadrilateral());
  const Side ad{st.v(0), st.v(1)};
  EXPECT_FALSE(splittable(st, ad, Point(50, 30)));
  EXPECT_TRUE(splittable(st, ad, Point(50, -1)));
  EXPECT_TRUE(splittable(st, ad, Point(50, 0)));
}

}  // namespace
}  // namespace nonobtuse::refine2d
