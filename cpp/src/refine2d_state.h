// Internal: the state every boundary-refinement strategy works on (a CDT, a work queue of subsegment sides, the
// Steiner budget, per-edge bookkeeping) and the operations they share: finding encroachers, rounding a point
// onto a subsegment, splitting a constrained edge while keeping the domain marks.
#pragma once
#include <cmath>
#include <deque>
#include <map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "cdt.h"
#include "nonobtuse/refine2d.h"

namespace nonobtuse::refine2d {

using cdt::CDT;
using cdt::Edge;
using cdt::Face_handle;
using cdt::Point;
using cdt::Vertex_handle;

// One side of a constrained subsegment: the side on the left of s -> e. The work queue holds sides, not edges,
// so that an interface (issue 4: a constraint with domain triangles on both sides) is two independent items.
struct Side {
  Vertex_handle s, e;
};

// What the walk over the diametral disk of a side found.
struct DiskWalk {
  std::vector<Vertex_handle> encroachers;  // vertices strictly inside the open half-disk, reachable from the side
  std::vector<Side> nearby;                // other boundary sides met by the walk (candidate forbidders)
};

class State {
 public:
  State(const Domain2& domain, long long budget);

  CDT cdt;
  const Domain2& domain;
  const int n_input;
  const long long budget;
  long long placed = 0;
  bool fallback_used = false;     // a greedy step had to break another subsegment's empty disk
  std::deque<Side> queue;         // sides to (re)examine
  std::vector<BoundaryEdgeStats> edges;

  // The face on the left of s -> e, or nullptr when (s, e) is not a constrained edge of the CDT (anymore).
  Face_handle left_face(const Side& side) const;
  // A constrained subsegment with a domain triangle on its left and none on its right. (Issue 4 relaxes this to
  // "a domain triangle on its left" so that both sides of an interface are refined.)
  bool is_boundary_side(const Side& side) const;
  // A boundary side whose triangle is obtuse at the apex (exact: CGAL::angle(s, apex, e) == OBTUSE).
  bool is_violated(const Side& side) const;
  // The apex of the side's triangle (call only on a boundary side).
  Vertex_handle apex(const Side& side) const;
  // Every boundary side of the current CDT.
  std::vector<Side> boundary_sides() const;

  // Vertices strictly inside the open diametral half-disk of `side` (exact: left of s -> e and
  // angle(s, q, e) == OBTUSE), found by walking from the side's triangle across unconstrained edges into every
  // triangle meeting the closed disk. Constraints stop the walk, which gives visibility; the float distance
  // test only prunes the walk (conservatively, with slack): every decision on a vertex is exact.
  // Cost: the number of triangles meeting the disk.
  DiskWalk walk_diametral_disk(const Side& side) const;

  // Inserts p (from candidates_near) into the constrained edge (s, e), which CGAL splits into (s, p), (p, e) before
  // restoring the constrained Delaunay property by flips. Every face that changed is incident to p; their domain
  // marks are copied from the side they lie on. Sides of the changed faces are pushed on the queue. Refuses
  // (returns nullptr) when p would invert a triangle next to the edge (p off the line by more than its
  // neighbours allow). Cost: O(degree of p) plus the flips.
  Vertex_handle split(const Side& side, const Point& p);
  // p would keep the two triangles next to the side counter-clockwise after the split (exact; p may be ulps
  // off the line, and a neighbouring apex nearly on it).
  bool keeps_triangles_valid(const Side& side, const Point& p) const;

  bool budget_left() const { return placed < budget; }
  // Every boundary side pushed on the queue.
  void enqueue_all();
  // The index in `edges` of the input boundary edge a subsegment lies on.
  int edge_of(const Side& side) const;
  // Single-edge Greedy-Refine (Theorem 2) of `side` against the vertices `q` only, without inserting anything:
  // the number of Steiner points it places, each rounded as the refinement rounds them.
  int greedy_count(const Side& side, std::vector<Vertex_handle> q) const;

 private:
  std::map<std::pair<int, int>, int> edge_index_;  // input boundary edge (min, max) -> index in edges
  std::vector<int> steiner_edge_;                   // Steiner point (index - n_input) -> index in edges
};

// Exact encroachment of q on side (s, e): q strictly left of s -> e and strictly inside the diametral disk.
inline bool encroaches(const Point& s, const Point& e, const Point& q) {
  return CGAL::orientation(s, e, q) == CGAL::LEFT_TURN && CGAL::angle(s, q, e) == CGAL::OBTUSE;
}

// Double points near s + t (e - s), t in (0, 1), that may stand for it on the subsegment, most preferred first:
// points exactly on the line (the dyadic parameters k / 2^m just below and above t that give exactly
// representable coordinates: with b-bit coordinates this succeeds once m + b <= 53, always for integer
// coordinates below 2^20; and the doubles within 2 ulps of the rounded point), then points a few ulps off the
// line to the right of s -> e (outside the domain), so the refined boundary s-p-e bends away from the domain and p
// never encroaches on the subsegments of its own edge; each group by decreasing progress along s -> e. Every
// candidate is strictly between s and e (exact: angle(s, p, e) obtuse). Rounding is a construction: the caller
// picks the first candidate its exact predicates accept (see pick_point).
std::vector<Point> candidates_near(const Point& s, const Point& e, double t);

// The first of candidates_near(s, e, t) accepted by `valid`; false when none is.
template <class Valid>
bool pick_point(const Point& s, const Point& e, double t, Valid&& valid, Point& p) {
  if (!(t > 0.0 && t < 1.0)) return false;
  for (const Point& c : candidates_near(s, e, t))
    if (valid(c)) {
      p = c;
      return true;
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

// The greedy end from s toward e: min over encroachers q of |q - s|^2 / ((q - s) . d), d = e - s, the parameter
// where q reaches the diametral circle of [s, s + t d] (paper-notes: (s - q).(x - q) >= 0 iff t (q - s).d <=
// |q - s|^2). 1 when no q blocks. `blocker` receives the minimizing vertex.
double greedy_parameter(const Point& s, const Point& e, const std::vector<Vertex_handle>& q,
                        Vertex_handle* blocker = nullptr);

// Keeps the vertices of q still encroaching [s, e] (disks of subsegments that share e shrink as s advances).
void keep_encroaching(const Point& s, const Point& e, std::vector<Vertex_handle>& q);

// True when no vertex of q encroaches [s, p] (exact).
bool subsegment_is_empty(const Point& s, const Point& p, const std::vector<Vertex_handle>& q);

// Splits `side` at the foot of q on it (rounded by pick_point): the new vertex, or nullptr when no double point
// strictly inside the side exists there or State::split refuses it. Defined in projection_refine.cpp.
Vertex_handle split_at_foot(State& st, const Side& side, const Point& q);

// The strategies; each runs until its queue is empty or the budget is spent.
void greedy_refine(State& state);
void projection_refine(State& state);
void project_flip(State& state);

}  // namespace nonobtuse::refine2d
