// The split rules for encroached subsegments of the Gabriel refinement: concentric shells and Greedy-Refine.
#include "gabriel3d_split_rule.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "gabriel3d_protect.h"

namespace nonobtuse::gabriel3d {

P3 interpolate(const P3& a, const P3& b, double t) {
  return P3(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y()), a.z() + t * (b.z() - a.z()));
}

// The split parameter t (the split point is a + t (b - a)) of the shells rule: the midpoint, unless exactly one end
// e is an input vertex: then the point at distance 2^k from e, the power of two that cuts the subsegment most
// evenly (pieces within a 1:2 ratio), as in Ruppert's and Shewchuk's concentric shells. Termination argument:
// every vertex placed near e on any segment through e then lies on a sphere of radius 2^k around e, and two such
// vertices on segments meeting at e at the same radius r never encroach each other's subsegment that ends at e
// (r·d2 is strictly inside the sphere with diameter [e, e + r·d1] iff |r·d2 - r·d1/2| < r/2 iff
// cos(angle(d1, d2)) > 1: never). So the ping-pong of midpoint splitting down two segments meeting at a small
// angle stops once the subsegments at e reach a common shell. Small segment-facet and dihedral angles have no
// known terminating rule: the budgets end those runs.
double shell_cutting_evenly(const P3& pa, const P3& pb, bool a_input, bool b_input) {
  if (a_input == b_input) return 0.5;
  double length = std::sqrt(CGAL::to_double(CGAL::squared_distance(pa, pb)));
  const double shell = power_of_two_piece(length);
  return a_input ? shell / length : 1.0 - shell / length;
}

// The greedy rule (the 2D paper's Greedy-Refine on one edge). Against the subsegment's current encroachers E (the
// vertices strictly inside its diametral sphere, plus `pending`), the prefix [s, x] from end s is free of E iff
// (v - s)·(v - x) >= 0 for every v in E; with x = s + t (e - s) that is t ((v - s)·(e - s)) <= |v - s|^2, so the
// longest free prefix ends at t* = min over v of |v - s|^2 / ((v - s)·(e - s)) (< 1 for an encroacher). The end
// s with the longer free prefix is used (from either end, the greedy piece belongs to an optimal cover of the
// subsegment against E, because sub-pieces of a free piece are free: diametral balls of nested segments that share
// an end are nested). The rounded point is checked with the exact predicate and moved toward s by growing
// relative steps until [s, x] is free of E. Returns t, or nullopt (the caller uses the shells rule) when the free
// prefix or the rest [x, e] is shorter than kGreedyMinPiece of the subsegment (also when rounding shortens the
// prefix below that), or when the rounded point is an existing vertex. In exact arithmetic a vertex v of E never
// encroaches the rest [x, e] either: x lies at or beyond the foot of v on the segment (t* >= ((v - s)·(e - s)) /
// |e - s|^2 since |v - s|^2 >= that dot squared over |e - s|^2), so v sees [x, e] at an angle of at most 90°.
// The guard, measured on the 7 corpus inputs shells converges on (experiments/README.md): bounding only the prefix,
// a greedy point lands next to the far end (an encroacher near it) and the tiny rest starts a cascade (6 of the 7
// ended at min_length); bounding both pieces by 1/8, 1/4 or 3/8 converges on 7, 7 and 6 of them, with 40266 and
// 40345 points in total at 1/8 and 1/4 (shells: 45403); 1/4 keeps the larger smallest subsegment.
constexpr double kGreedyMinPiece = 0.25;

std::optional<double> greedy_split_parameter(const PlcState& s, const PointIndex& index, int a, int b,
                                             const P3* pending) {
  const P3 &pa = s.points[a], &pb = s.points[b];
  std::vector<P3> encroachers;
  index.for_each_in(search_ball(pa, pb), [&](int v) {
    if (v != a && v != b && CGAL::side_of_bounded_sphere(pa, pb, s.points[v]) == CGAL::ON_BOUNDED_SIDE)
      encroachers.push_back(s.points[v]);
  });
  if (pending && CGAL::side_of_bounded_sphere(pa, pb, *pending) == CGAL::ON_BOUNDED_SIDE)
    encroachers.push_back(*pending);
  if (encroachers.empty()) return std::nullopt;
  auto reach = [&](const P3& from, const P3& e) {  // t* from `from`, floating point (checked exactly below)
    double best = 1.0;
    const K::Vector_3 d = e - from;
    for (const P3& v : encroachers) {
      const K::Vector_3 w = v - from;
      double along = w * d;
      if (along > 0) best = std::min(best, (w * w) / along);
    }
    return best;
  };
  const double from_a = reach(pa, pb), from_b = reach(pb, pa);
  const bool at_a = from_a >= from_b;
  const P3& from = at_a ? pa : pb;
  double piece = std::max(from_a, from_b);
  for (int step = 0; step < 64 && piece >= kGreedyMinPiece && 1.0 - piece >= kGreedyMinPiece; ++step) {
    const double t = at_a ? piece : 1.0 - piece;
    const P3 x = interpolate(pa, pb, t);
    if (s.at.count({x.x(), x.y(), x.z()})) return std::nullopt;
    if (std::none_of(encroachers.begin(), encroachers.end(), [&](const P3& v) {
          return CGAL::side_of_bounded_sphere(from, x, v) == CGAL::ON_BOUNDED_SIDE;
        }))
      return t;
    piece *= 1.0 - std::ldexp(1.0, step - 52);  // relative steps of 2^-52, 2^-51, ...: at most 53 of them
  }
  return std::nullopt;
}

}  // namespace nonobtuse::gabriel3d
