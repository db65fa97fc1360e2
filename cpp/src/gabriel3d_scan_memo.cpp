// A subfacet's scan answer from the points added since its last scan (gabriel3d_scan_memo.h).
#include "gabriel3d_scan_memo.h"

namespace nonobtuse::gabriel3d {

bool encroached_since_memo(const std::vector<P3>& points, const PointIndex& index, int a, int b, int c,
                           ScanMemo& memo, const std::function<bool(int)>& ignore) {
  const int n = static_cast<int>(points.size());
  const P3 &pa = points[a], &pb = points[b], &pc = points[c];
  if (memo.a == a && memo.b == b && memo.c == c && memo.clean_below >= 0 && n - memo.clean_below <= kMemoReach) {
    // The float filter of PointIndex::for_each_in: the ball contains the exact sphere, and the relative 1e-12
    // covers the rounding of the squared distances, so no point strictly inside is filtered out.
    const auto& o = memo.ball.center;
    const double r2 = memo.ball.radius * memo.ball.radius * (1.0 + 1e-12);
    for (int t = memo.clean_below; t < n; ++t) {
      if (t == a || t == b || t == c) continue;
      const P3& p = points[t];
      const double dx = p.x() - o[0], dy = p.y() - o[1], dz = p.z() - o[2];
      if (!memo.ball.everything && dx * dx + dy * dy + dz * dz > r2) continue;
      if (CGAL::side_of_bounded_sphere(pa, pb, pc, p) == CGAL::ON_BOUNDED_SIDE && !(ignore && ignore(t))) {
        memo.clean_below = -1;
        return true;
      }
    }
    memo.clean_below = n;
    return false;
  }
  const bool hit = deepest_encroacher(points, index, a, b, c, nullptr, ignore).vertex >= 0;
  memo = {a, b, c, hit ? -1 : n, hit ? SearchBall{} : search_ball(pa, pb, pc)};
  return hit;
}

}  // namespace nonobtuse::gabriel3d
