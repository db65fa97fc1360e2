// Internal: the split point. Where a Steiner point goes in doubles (the rounding of a constructed point onto a
// subsegment, candidates_near and pick_point), whether the triangulation can take it there (splittable), and the
// split itself, the one operation that inserts a Steiner point into the refinement state.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <tuple>
#include <vector>

#include "refine2d_state.h"

namespace nonobtuse::refine2d {

// Double points near s + t (e - s), t in (0, 1), that may stand for it on the subsegment, most preferred first:
// points exactly on the line (the dyadic parameters k / 2^m just below and above t that give exactly
// representable coordinates: with b-bit coordinates this succeeds once m + b <= 53, always for integer
// coordinates below 2^20), then points off the line to its right (outside the domain: the refined boundary
// s-p-e bends away from the domain), then to its left, each group nearest to the target first. Off-line
// candidates are the doubles nearest the line near the rounded point (within 2 ulps of the finer coordinate)
// and a grid up to 8 ulps outward. Where the subsegment spans at most 64 doubles in a coordinate (far from the
// origin), the doubles nearest the line at every double between s and e are candidates too, and off-line points
// farther than 2^-8 of its length from the line come last, nearest the line first. Every candidate is strictly
// between s and e (exact: angle(s, p, e) obtuse).
// Rounding is a construction: the caller picks the first candidate its exact predicates accept (pick_point).
std::vector<Point> candidates_near(const Point& s, const Point& e, double t);

// The candidates of candidates_near before ordering, each with its rank (group, distance to the target along the
// line, position along it, index): candidates_near lists them by increasing rank, consecutive equal points once.
struct RankedCandidates {
  std::vector<Point> points;
  std::vector<std::tuple<int, double, double, std::size_t>> rank;  // rank[k] is that of points[std::get<3>(rank[k])]
};
RankedCandidates ranked_candidates(const Point& s, const Point& e, double t);

// The first of candidates_near(s, e, t) accepted by `valid`; false when none is. The same order, popped from a
// heap: the first candidate is usually accepted, and sorting all of them took a fifth of a thin layer's refinement.
template <class Valid>
bool pick_point(const Point& s, const Point& e, double t, Valid&& valid, Point& p) {
  if (!(t > 0.0 && t < 1.0)) return false;
  RankedCandidates c = ranked_candidates(s, e, t);
  auto later = [](const auto& a, const auto& b) { return a > b; };  // a min-heap of ranks
  std::make_heap(c.rank.begin(), c.rank.end(), later);
  const Point* previous = nullptr;
  for (auto end = c.rank.end(); end != c.rank.begin(); --end) {
    std::pop_heap(c.rank.begin(), end, later);
    const Point& q = c.points[std::get<3>(*(end - 1))];
    if (previous && q == *previous) continue;  // candidates_near lists it once
    previous = &q;
    if (valid(q)) {
      p = q;
      return true;
    }
  }
  return false;
}

// pick_point at t, else at t moved back toward s by relative steps 2^-40, 2^-36, ..., 2^-4 (float t may overshoot
// an exact bound by a few ulps; each retry is re-checked exactly). False when all fail.
template <class Valid>
bool pick_point_at_or_before(const Point& s, const Point& e, double t, Valid&& valid, Point& p) {
  if (pick_point(s, e, t, valid, p)) return true;
  for (int k = 40; k >= 4; k -= 4)
    if (pick_point(s, e, t * (1 - std::ldexp(1.0, -k)), valid, p)) return true;
  return false;
}

// Inserts p (from candidates_near) into the constrained edge (s, e): CGAL splits it into (s, p), (p, e) and
// restores the constrained Delaunay property by flips. When p is off the line and a neighbouring apex lies nearly
// on it, or p bends a convex hull edge inward (so that splitting in place would invert a triangle or the hull),
// the constraint is replaced by the polyline s-p-e and CGAL retriangulates. Domain marks of the changed faces are
// copied from the side they lie on; the sides of changed faces are queued; the point is counted against the budget
// and on its input edge. Returns nullptr only when p coincides with an existing vertex.
// Cost: O(degree of p) plus the flips.
Vertex_handle split(State& st, const Side& side, const Point& p);
// split(st, side, p) is safe: p splits the edge in place (splits_in_place), or the polyline s-p-e that replaces it
// stays inside the triangle next to the edge on p's side (p strictly inside it, exact) or outside the hull, so
// that it crosses no constraint and passes over no vertex. Every point given to split must pass this.
bool splittable(const State& st, const Side& side, const Point& p);

// Parameter of the foot of q on the line s + t (e - s) (float: a construction, rounded by pick_point).
inline double foot_parameter(const Point& s, const Point& e, const Point& q) {
  double dx = e.x() - s.x(), dy = e.y() - s.y();
  return ((q.x() - s.x()) * dx + (q.y() - s.y()) * dy) / (dx * dx + dy * dy);
}

// Splits `side` at the foot of q on it (rounded by pick_point): the new vertex, or nullptr when no double point
// strictly inside the side exists there or split refuses it.
Vertex_handle split_at_foot(State& st, const Side& side, const Point& q);

}  // namespace nonobtuse::refine2d
