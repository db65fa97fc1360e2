// Internal: candidate search for diametral-sphere tests. A kd-tree proposes the points near a sphere with a
// floating-point query that provably misses none of the points strictly inside; the exact predicate decides.
#pragma once
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <functional>
#include <optional>
#include <unordered_map>
#include <vector>

#include "nonobtuse/gabriel3d.h"

namespace nonobtuse::gabriel3d {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P3 = K::Point_3;

inline P3 to_cgal(const Point3& p) { return P3(p.x, p.y, p.z); }
inline Point3 from_cgal(const P3& p) { return {p.x(), p.y(), p.z()}; }

// A ball that contains a diametral sphere: everything == true when no finite bound could be computed.
struct SearchBall {
  std::array<double, 3> center{};
  double radius = 0.0;
  bool everything = false;
};

// Balls containing the diametral sphere of segment ab / of triangle abc. The center and radius are evaluated in
// interval arithmetic, so the returned ball contains the exact sphere whatever the rounding: no relative margin is
// guessed from the triangle's shape (a sliver's circumcenter can be off by far more than a few ulps).
SearchBall search_ball(const P3& a, const P3& b);
SearchBall search_ball(const P3& a, const P3& b, const P3& c);

// The circumcenter of triangle abc rounded to doubles, or nullopt when abc is collinear or it does not fit in a
// double. The floating-point construction is tried first; for a needle triangle it can divide by an underflowed
// zero (infinite or NaN coordinates, which an exact 2D kernel cannot even read: GMP raises SIGFPE on NaN), and
// then the exact circumcenter is rounded instead.
std::optional<P3> rounded_circumcenter(const P3& a, const P3& b, const P3& c);

// A kd-tree over a growing point list. Points added after the last rebuild sit in a pending list that every query
// scans; the tree is rebuilt when that list exceeds max(256, 4 sqrt(n)): insertion amortized O(sqrt(n) log n),
// a query O(log n + sqrt(n)).
class PointIndex {
 public:
  explicit PointIndex(const std::vector<P3>& points);  // indexes points[0, size) now; keeps a reference
  void add(int i);                                      // points[i] was appended
  // Calls visit(i) for every indexed point within ball (and some just outside it): the squared-distance tests are
  // done in floating point, so the radius is enlarged by a relative 1e-12, far above their rounding error
  // (at most a few units of 2^-53 relative: differences, squares and sums of positive terms).
  template <class Visit>
  void for_each_in(const SearchBall& ball, Visit&& visit) const;
  int nearest(const P3& q) const;  // closest indexed point (floating-point distances), -1 when empty

 private:
  struct Node {
    std::array<double, 3> lo, hi;  // bounding box of the node's points
    int begin, end;                // range in order_
    int left = -1, right = -1;
  };
  // An indexed point with its coordinates: the tree's points in tree order, so that the leaves' scans and the
  // builds read memory in sequence (with point indices only, every coordinate was a random access).
  struct Item {
    std::array<double, 3> p;
    int i;
  };
  void rebuild();
  int build(int begin, int end);
  // Inline (it was a call through the PLT from every query's traversal: 2% of refine_gabriel on fandisk).
  static double box_distance2(const Node& node, const std::array<double, 3>& q) {
    double s = 0.0;
    for (int d = 0; d < 3; ++d) {
      double e = std::max({node.lo[d] - q[d], 0.0, q[d] - node.hi[d]});
      s += e * e;
    }
    return s;
  }
  const std::vector<P3>& points_;
  std::vector<Item> order_;
  std::vector<Node> nodes_;
  std::vector<int> pending_;
};

template <class Visit>
void PointIndex::for_each_in(const SearchBall& ball, Visit&& visit) const {
  if (ball.everything) {
    for (const Item& item : order_) visit(item.i);
    for (int i : pending_) visit(i);
    return;
  }
  const auto& c = ball.center;
  const double r2 = ball.radius * ball.radius * (1.0 + 1e-12);
  auto d2 = [&](int i) {
    const P3& p = points_[i];
    double dx = p.x() - c[0], dy = p.y() - c[1], dz = p.z() - c[2];
    return dx * dx + dy * dy + dz * dz;
  };
  for (int i : pending_)
    if (d2(i) <= r2) visit(i);
  if (nodes_.empty()) return;
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (box_distance2(node, c) > r2) continue;
    if (node.left < 0) {
      for (int k = node.begin; k < node.end; ++k) {
        const auto& p = order_[k].p;
        double dx = p[0] - c[0], dy = p[1] - c[1], dz = p[2] - c[2];
        if (dx * dx + dy * dy + dz * dz <= r2) visit(order_[k].i);
      }
    } else {
      stack[top++] = node.left;
      stack[top++] = node.right;
    }
  }
}

// The point strictly inside the diametral sphere of segment ab (c == -1) or triangle abc, other than the simplex's
// own vertices, that is deepest by floating-point depth among those the exact predicate confirms (exact ties in
// depth are vanishingly rare and only change which encroacher is named); vertex == -1 when the sphere is empty.
// Points for which ignore(i) is true are not considered.
// What the exact checks of one refinement found clean so far: per simplex (its corners sorted; -1 third for a
// segment), the number of points it was checked against. Points are only appended and never move, so a simplex
// clean against points[0, n) stays clean against them, and its deepest encroacher, if any, is a later point.
struct CheckMemo {
  struct Hash {
    std::size_t operator()(const std::array<int, 3>& k) const;
  };
  std::unordered_map<std::array<int, 3>, int, Hash> clean_below;
};

// check_gabriel on points already in the kernel's type, on two threads from a few thousand rows (faces and segments;
// the report does not depend on it). Stops when out_of_time() (asked before each row, from both threads) returns
// true: the rows not reached are counted as unchecked_faces / unchecked_segments. memo (kept
// across the checks of one refinement, whose points only grow): the simplices found clean before are tested against
// the points added since only; the report is the same but for `candidates`.
GabrielReport check_gabriel_until(const std::vector<P3>& points, const std::vector<Triangle>& faces,
                                  const std::vector<Segment>& segments, const std::function<bool()>& out_of_time,
                                  CheckMemo* memo = nullptr);

Encroachment deepest_encroacher(const std::vector<P3>& points, const PointIndex& index, int a, int b, int c,
                                std::size_t* candidates = nullptr, const std::function<bool(int)>& ignore = {});

}  // namespace nonobtuse::gabriel3d
