// The memoized subfacet scan answer against brute force, as points are appended.
#include <gtest/gtest.h>

#include "gabriel3d_scan_memo.h"

namespace nonobtuse::gabriel3d {
namespace {

TEST(Gabriel3DScanMemo, AnswersAsBruteForceWhilePointsAreAppended) {
  auto next = [state = 7u]() mutable {
    state = state * 1103515245u + 12345u;
    return (state >> 8) / double(1 << 24);
  };
  std::vector<P3> points;
  for (int i = 0; i < 60; ++i) points.emplace_back(next(), next(), next());
  struct Case {
    int a, b, c;
    ScanMemo memo;
  };
  std::vector<Case> cases;
  for (int k = 0; k < 40; ++k) {  // triangles of sizes 0.01 to 0.2: the small ones stay clean for a while
    const double e = 0.01 + 0.005 * k, x = next(), y = next(), z = next();
    const int a = static_cast<int>(points.size());
    points.insert(points.end(), {P3(x, y, z), P3(x + e, y, z), P3(x, y + e, z + e / 2)});
    cases.push_back({a, a + 1, a + 2, {}});
  }
  PointIndex index(points);
  auto ignore = [](int t) { return t % 7 == 0; };  // as the facets' artifact test, some points do not count
  auto brute = [&](const Case& k) {
    for (std::size_t t = 0; t < points.size(); ++t) {
      const int i = static_cast<int>(t);
      if (i != k.a && i != k.b && i != k.c && !ignore(i) &&
          CGAL::side_of_bounded_sphere(points[k.a], points[k.b], points[k.c], points[t]) == CGAL::ON_BOUNDED_SIDE)
        return true;
    }
    return false;
  };
  long hits = 0, clean = 0;
  for (int step = 0; step < 40; ++step) {
    // Mostly a few points between two scans; once more than kMemoReach (the kd-tree query again).
    const int added = step == 20 ? kMemoReach + 5 : 1 + step % 4;
    for (int i = 0; i < added; ++i) {
      points.emplace_back(next(), next(), next());
      index.add(static_cast<int>(points.size()) - 1);
    }
    for (Case& k : cases) {
      const bool expected = brute(k);
      ASSERT_EQ(encroached_since_memo(points, index, k.a, k.b, k.c, k.memo, ignore), expected) << "step " << step;
      (expected ? hits : clean) += 1;
    }
    if (step == 30)  // a memo of another triangle (a face reused for other corners) is not trusted
      std::swap(cases[0].memo, cases[1].memo);
  }
  EXPECT_GT(hits, 100);  // both answers were compared, many times
  EXPECT_GT(clean, 100);
}

}  // namespace
}  // namespace nonobtuse::gabriel3d
