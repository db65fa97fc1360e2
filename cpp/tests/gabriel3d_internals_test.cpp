// Internals of the 3D Gabriel refinement: rounded_circumcenter (subfacet split points, needles too), the edges the
// kept tetrahedralization lacks, PointIndex and the repair order.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <random>

#include "gabriel3d_index.h"
#include "gabriel3d_refiner.h"

namespace nonobtuse::gabriel3d {
namespace {

TEST(Gabriel3DCircumcenter, NeedleTriangleGetsTheExactCenterRounded) {
  // Apex 1e-200 above the midpoint of a unit base: the floating-point construction divides by
  // 2 |(b - a) x (c - a)|^2 = 2e-400, which underflows to 0 (before the fix: NaN coordinates, and GMP raised SIGFPE
  // when the facet's exact 2D triangulation read them). The exact center: x = 0.5 and, from
  // 0.25 + y^2 = (y - h)^2, y = (h^2 - 0.25) / (2 h) = -1.25e199 for h = 1e-200 (to rounding).
  const double h = 1e-200;
  const P3 a(0, 0, 0), b(1, 0, 0), c(0.5, h, 0);
  double num_x, num_y, num_z, den;  // the floating-point construction's denominator (CGAL::circumcenter's)
  CGAL::determinants_for_circumcenterC3(a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), c.x(), c.y(), c.z(), num_x, num_y,
                                        num_z, den);
  ASSERT_EQ(den, 0.0);
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

TEST(Gabriel3DDelaunayRounds, MissingEdgesAreTheDiagonalTheCosphericalChoiceLeftOut) {
  // A square pyramid: the base's four corners are cocircular, so the tetrahedralization has one of its two
  // diagonals (CGAL's symbolic perturbation chooses); the base's sides and the pyramid's edges are all edges.
  PLC3 plc;
  plc.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}};
  plc.triangles = {{0, 2, 1}, {0, 3, 2}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  plc.facet_ids = {0, 0, 1, 2, 3, 4};
  const PlcState s = build_plc_state(plc);
  DelaunayRounds delaunay;
  delaunay.restrict(s, plc);
  const std::vector<Key> diagonals{key(0, 2), key(1, 3)};
  const std::vector<Key> missing = delaunay.missing_edges(diagonals);
  ASSERT_EQ(missing.size(), 1u);
  EXPECT_TRUE(missing[0] == diagonals[0] || missing[0] == diagonals[1]);
  EXPECT_TRUE(delaunay.missing_edges({key(0, 1), key(1, 2), key(2, 3), key(0, 3), key(0, 4), key(2, 4)}).empty());
}

}  // namespace
}  // namespace nonobtuse::gabriel3d

namespace nonobtuse::gabriel3d {
namespace {

TEST(Gabriel3DPointIndex, GrowingIndexFindsWhatBruteForceFinds) {
  // Points added one at a time across several rebuilds (pending list > max(256, 4 sqrt(n))); every query must
  // visit each point strictly within the ball (it may visit a few more just outside: the caller decides exactly),
  // and nearest() must return a point as close as the closest one.
  std::vector<P3> points;
  auto next = [state = 12345u]() mutable {
    state = state * 1103515245u + 12345u;
    return (state >> 8) / double(1 << 24);
  };
  for (int i = 0; i < 64; ++i) points.emplace_back(next(), next(), next());
  points.reserve(6000);
  PointIndex index(points);
  for (int i = 64; i < 6000; ++i) {
    points.emplace_back(next(), next(), next());
    index.add(i);
    if (i % 500 != 0) continue;
    SearchBall ball{{next(), next(), next()}, 0.2, false};
    std::vector<bool> seen(points.size(), false);
    index.for_each_in(ball, [&](int t) { seen[t] = true; });
    const P3 c(ball.center[0], ball.center[1], ball.center[2]);
    for (std::size_t t = 0; t < points.size(); ++t)
      if (CGAL::compare_squared_distance(points[t], c, 0.04) == CGAL::SMALLER) EXPECT_TRUE(seen[t]) << t;
    double closest = HUGE_VAL;
    for (const P3& p : points) closest = std::min(closest, CGAL::squared_distance(p, c));
    const int nearest = index.nearest(c);
    ASSERT_GE(nearest, 0);
    EXPECT_EQ(CGAL::squared_distance(points[nearest], c), closest) << i;
  }
}

}  // namespace
}  // namespace nonobtuse::gabriel3d

namespace nonobtuse::gabriel3d {
namespace {

// The faces of scattered_order's result as sorted corner triples, in its order.
std::vector<Triangle> in_scattered_order(const std::vector<Triangle>& faces) {
  std::vector<Triangle> out;
  for (std::size_t i : scattered_order(faces)) {
    Triangle t = faces[i];
    std::sort(t.begin(), t.end());
    out.push_back(t);
  }
  return out;
}

TEST(Gabriel3DRepairOrder, DependsOnTheSetOfFacesAlone) {
  // The two triangles of every square of a 12 x 12 grid of points (index 13 i + j).
  std::vector<Triangle> faces;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) {
      const int p = 13 * i + j;
      faces.push_back({p, p + 1, p + 14});
      faces.push_back({p, p + 14, p + 13});
    }
  const std::vector<std::size_t> order = scattered_order(faces);
  std::vector<std::size_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);  // a permutation
  // The same faces in reverse row order, each row rotated (as another cell order would give them) or reversed.
  std::vector<Triangle> other(faces.rbegin(), faces.rend());
  for (std::size_t i = 0; i < other.size(); ++i) {
    Triangle& t = other[i];
    if (i % 3 == 1) t = {t[1], t[2], t[0]};
    if (i % 3 == 2) t = {t[2], t[1], t[0]};
  }
  EXPECT_EQ(in_scattered_order(other), in_scattered_order(faces));
  // Scattered: not the order of the smallest corner, which keeps the faces around a point together.
  const std::vector<Triangle> result = in_scattered_order(faces);
  EXPECT_FALSE(std::is_sorted(result.begin(), result.end()));
}

}  // namespace
}  // namespace nonobtuse::gabriel3d

namespace nonobtuse::gabriel3d {
namespace {

// Random faces and segments over random points, each between a point and two of its 8 nearest (so that some are
// encroached and most not): enough rows (5,500) that the check runs them in two halves.
struct RandomRows {
  std::vector<P3> points;
  std::vector<Triangle> faces;
  std::vector<Segment> segments;
};

RandomRows random_rows(int n, int faces, int segments, unsigned seed) {
  RandomRows r;
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> coordinate(0.0, 1.0);
  for (int i = 0; i < n; ++i) r.points.emplace_back(coordinate(random), coordinate(random), coordinate(random));
  std::vector<std::vector<int>> near(n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j)
      if (j != i) near[i].push_back(j);
    std::partial_sort(near[i].begin(), near[i].begin() + 8, near[i].end(), [&](int j, int k) {
      return CGAL::squared_distance(r.points[i], r.points[j]) < CGAL::squared_distance(r.points[i], r.points[k]);
    });
    near[i].resize(8);
  }
  std::uniform_int_distribution<int> vertex(0, n - 1), neighbour(0, 7);
  while (static_cast<int>(r.faces.size()) < faces) {
    const int a = vertex(random);
    const Triangle t{a, near[a][neighbour(random)], near[a][neighbour(random)]};
    if (t[1] != t[2] && !CGAL::collinear(r.points[t[0]], r.points[t[1]], r.points[t[2]])) r.faces.push_back(t);
  }
  while (static_cast<int>(r.segments.size()) < segments) {
    const int a = vertex(random);
    r.segments.push_back({a, near[a][neighbour(random)]});
  }
  return r;
}

// Is some point strictly inside the diametral sphere of face abc (c >= 0) or segment ab, by the exact predicate on
// every point?
bool encroached_by_any(const std::vector<P3>& points, int a, int b, int c) {
  for (int t = 0; t < static_cast<int>(points.size()); ++t) {
    if (t == a || t == b || t == c) continue;
    const auto side = c < 0 ? CGAL::side_of_bounded_sphere(points[a], points[b], points[t])
                            : CGAL::side_of_bounded_sphere(points[a], points[b], points[c], points[t]);
    if (side == CGAL::ON_BOUNDED_SIDE) return true;
  }
  return false;
}

// The report's rows ascending, each encroached by its named vertex, and every row a brute-force scan finds
// encroached among them.
void expect_brute_force(const RandomRows& r, const GabrielReport& report) {
  std::vector<bool> face(r.faces.size(), false), segment(r.segments.size(), false);
  for (std::size_t i = 0; i < report.faces.size(); ++i) {
    const Encroachment& e = report.faces[i];
    if (i > 0) EXPECT_LT(report.faces[i - 1].index, e.index);
    const Triangle& t = r.faces[e.index];
    EXPECT_EQ(CGAL::side_of_bounded_sphere(r.points[t[0]], r.points[t[1]], r.points[t[2]], r.points[e.vertex]),
              CGAL::ON_BOUNDED_SIDE);
    face[e.index] = true;
  }
  for (std::size_t i = 0; i < report.segments.size(); ++i) {
    const Encroachment& e = report.segments[i];
    if (i > 0) EXPECT_LT(report.segments[i - 1].index, e.index);
    const Segment& g = r.segments[e.index];
    EXPECT_EQ(CGAL::side_of_bounded_sphere(r.points[g[0]], r.points[g[1]], r.points[e.vertex]),
              CGAL::ON_BOUNDED_SIDE);
    segment[e.index] = true;
  }
  for (std::size_t f = 0; f < r.faces.size(); ++f)
    EXPECT_EQ(face[f], encroached_by_any(r.points, r.faces[f][0], r.faces[f][1], r.faces[f][2])) << "face " << f;
  for (std::size_t s = 0; s < r.segments.size(); ++s)
    EXPECT_EQ(segment[s], encroached_by_any(r.points, r.segments[s][0], r.segments[s][1], -1)) << "segment " << s;
}

TEST(Gabriel3DCheckHalves, TheTwoHalvesFindWhatABruteForceScanFinds) {
  const RandomRows r = random_rows(400, 5000, 500, 7);
  const GabrielReport report = check_gabriel_until(r.points, r.faces, r.segments, [] { return false; });
  ASSERT_FALSE(report.faces.empty());
  ASSERT_FALSE(report.segments.empty());
  EXPECT_LT(report.faces.size(), r.faces.size());
  expect_brute_force(r, report);
}

TEST(Gabriel3DCheckHalves, TheMemoOfAnEarlierCheckChangesNoFinding) {
  // The rows over the first 300 points checked first (the memo records what they found clean), then over all 400.
  RandomRows r = random_rows(400, 5000, 500, 11);
  RandomRows fewer = random_rows(300, 5000, 500, 11);
  r.faces = fewer.faces;
  r.segments = fewer.segments;
  fewer.points.assign(r.points.begin(), r.points.begin() + 300);
  CheckMemo memo;
  check_gabriel_until(fewer.points, fewer.faces, fewer.segments, [] { return false; }, &memo);
  EXPECT_FALSE(memo.clean_below.empty());
  const GabrielReport remembered = check_gabriel_until(r.points, r.faces, r.segments, [] { return false; }, &memo);
  const GabrielReport fresh = check_gabriel_until(r.points, r.faces, r.segments, [] { return false; });
  expect_brute_force(r, remembered);
  for (const auto& [found, expected] : {std::pair{&remembered.faces, &fresh.faces},
                                        std::pair{&remembered.segments, &fresh.segments}}) {
    ASSERT_EQ(found->size(), expected->size());
    for (std::size_t i = 0; i < found->size(); ++i) {
      EXPECT_EQ((*found)[i].index, (*expected)[i].index);
      EXPECT_EQ((*found)[i].vertex, (*expected)[i].vertex);
    }
  }
  // The memo now: every row the check found clean at 400 points, none it found encroached.
  std::size_t encroached = 0;
  for (std::size_t f = 0, next = 0; f < r.faces.size(); ++f) {
    Triangle k = r.faces[f];
    std::sort(k.begin(), k.end());
    const bool listed = next < fresh.faces.size() && fresh.faces[next].index == static_cast<int>(f);
    next += listed;
    encroached += listed;
    const auto it = memo.clean_below.find(k);
    if (listed) EXPECT_EQ(it, memo.clean_below.end()) << "face " << f;
    else EXPECT_TRUE(it != memo.clean_below.end() && it->second == 400) << "face " << f;
  }
  EXPECT_GT(encroached, 0u);
}

TEST(Gabriel3DCheckHalves, RowsNotReachedInTimeAreCountedInBothHalves) {
  const RandomRows r = random_rows(400, 5000, 500, 13);
  std::atomic<int> asked{0};  // out of time after 1,000 rows in all (the halves ask from two threads)
  const GabrielReport report =
      check_gabriel_until(r.points, r.faces, r.segments, [&] { return ++asked > 1000; });
  const std::size_t unchecked = report.unchecked_faces + report.unchecked_segments;
  EXPECT_EQ(unchecked, r.faces.size() + r.segments.size() - 1000);
  EXPECT_GT(report.unchecked_segments, 0u);  // the second half's segments
  EXPECT_GT(report.unchecked_faces, 0u);     // the first half's faces
}

}  // namespace
}  // namespace nonobtuse::gabriel3d
