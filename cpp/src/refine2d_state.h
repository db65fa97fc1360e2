// Internal: the state every boundary-refinement strategy works on (a CDT, a work queue of subsegment sides, the
// Steiner budget, per-edge bookkeeping) and the operations they share: finding encroachers, rounding a point
// onto a subsegment, splitting a constrained edge while keeping the domain marks.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "cdt.h"
#include "refine2d_diagnosis.h"
#include "nonobtuse/refine2d.h"

namespace nonobtuse::refine2d {

using cdt::CDT;
using cdt::K;
using cdt::Edge;
using cdt::Face_handle;
using cdt::Point;
using cdt::Vertex_handle;

// One side of a constrained subsegment: the side on the left of s -> e. The work queue holds sides, not edges,
// so that an interface (issue 4: a constraint with domain triangles on both sides) is two independent items.
struct Side {
  Vertex_handle s, e;
};

using Segment2 = std::pair<Point, Point>;

// What the walk over the diametral disk of a side found.
struct DiskWalk {
  std::vector<Vertex_handle> encroachers;  // vertices strictly inside the open half-disk, reachable from the side
  std::vector<Segment2> obstacles;         // the constrained edges of the faces reached, other than the side's own
};

// How a vertex strictly inside the open diametral disk of a subsegment [a, b] of an edge counts as its encroacher.
// Reach (obstacles == nullptr): reachable from the edge's domain faces inside the closed disk without crossing a
// constraint (float pruning with slack, so it errs toward yes): implied by being seen, but a walk can wrap around a
// constraint's free end (or an end on the circle) to vertices that no point of (a, b) sees; the refinement uses
// it (its result is certified exactly anyway). Exact: seen from some point y of the open subsegment, the closed
// segment [y, v] meeting none of *obstacles (covered_from); the lower bound uses it with the obstacles of the walk
// over the whole edge's disk: the first constraint on every sight line from the edge inside that disk is an edge of
// a face the walk reached. Closed obstacles are stricter than "no constraint properly crosses [y, v]" only on
// sight lines grazing a constraint's end, so Exact never counts a vertex that is not seen.
struct Sight {
  const std::vector<Segment2>* obstacles = nullptr;
};

// Exact: the closed segments `obstacles` block every sight line from v to the open segment (a, b) (v off its line;
// obstacles ending at v are ignored).
bool covered_from(const Point& v, const Point& a, const Point& b, const std::vector<Segment2>& obstacles);

class State {
 public:
  // Triangulates the domain (cdt::build).
  State(const Domain2& domain, long long budget);

  CDT cdt;
  const Domain2& domain;
  const int n_input;
  const long long budget;
  long long placed = 0;
  bool fallback_used = false;     // a greedy step had to break another subsegment's empty disk
  bool convex_polygon = false;    // the input domain is a convex polygon without holes, inner points or constraints
  std::deque<Side> queue;         // sides to (re)examine
  std::vector<BoundaryEdgeStats> edges;

  // The face on the left of s -> e, or nullptr when (s, e) is not a constrained edge of the CDT (anymore).
  Face_handle left_face(const Side& side) const;
  // A constrained subsegment with a domain triangle on its left (issue 4: both sides of an interface or of a
  // dangling segment are boundary sides, each refined on its own; an outer boundary edge has one).
  bool is_boundary_side(const Side& side) const;
  // The domain triangles next to the subsegment of `side`: its left face first when that is in the domain, then
  // the right one when that is (two for an interface or dangling segment). Visibility walks start from these.
  std::vector<Face_handle> domain_faces(const Side& side) const;
  // A boundary side whose triangle is obtuse at the apex (exact: CGAL::angle(s, apex, e) == OBTUSE).
  bool is_violated(const Side& side) const;
  // The apex of the side's triangle (call only on a boundary side).
  Vertex_handle apex(const Side& side) const;
  // Every boundary side of the current CDT, sorted by vertex indices. A scan of every face, repeated only after a
  // split.
  std::vector<Side> boundary_sides() const;

  // Vertices strictly inside the open diametral disk of the subsegment on a domain side of it (exact: strictly
  // left of s -> e when the left is a domain side, strictly right when the right is, and angle(s, q, e) ==
  // OBTUSE), found by walking from its domain_faces across unconstrained edges into every triangle meeting the
  // closed disk. Constraints stop the walk, which gives visibility; the float distance
  // test only prunes the walk (conservatively, with slack): every decision on a vertex is exact.
  // Cost: the number of triangles meeting the disk.
  // Walks on different lanes (0 or 1) may run concurrently, each on one thread; lane 0 is the refinement's.
  DiskWalk walk_diametral_disk(const Side& side, int lane = 0) const;

  // Inserts p (from candidates_near) into the constrained edge (s, e): CGAL splits it into (s, p), (p, e) and
  // restores the constrained Delaunay property by flips. When p is off the line and a neighbouring apex lies nearly
  // on it, or p bends a convex hull edge inward (so that splitting in place would invert a triangle or the hull),
  // the constraint is replaced by the polyline s-p-e and CGAL retriangulates. Domain marks of the changed faces are copied from the side they lie on; the sides of
  // changed faces are queued. Returns nullptr only when p coincides with an existing vertex.
  // Cost: O(degree of p) plus the flips.
  Vertex_handle split(const Side& side, const Point& p);
  // split(side, p) is safe: p splits the edge in place (splits_in_place), or the polyline s-p-e that replaces it
  // stays inside the triangle next to the edge on p's side (p strictly inside it, exact) or outside the hull, so
  // that it crosses no constraint and passes over no vertex. Every point given to split must pass this.
  bool splittable(const Side& side, const Point& p) const;

  bool budget_left() const { return placed < budget; }
#ifdef NONOBTUSE_CHECK_INVARIANTS
  bool check_every_split = true;   // debug builds: check_invariants after every split
#else
  bool check_every_split = false;  // tests may ask for check_invariants after every split in any build
#endif
  // CGAL's is_valid (constrained Delaunay everywhere, the exterior included), and the maintained domain marks
  // equal a recomputation (which then replaces them). O(n): after every split in debug builds or when
  // check_every_split is set.
  void check_invariants();
  // Every boundary side pushed on the queue.
  void enqueue_all();
  // The index in `edges` of the input boundary edge a subsegment lies on (either orientation).
  int edge_of(const Side& side) const;
  // The index in `edges` of the input edge Steiner point `index` (>= n_input) was placed on.
  int steiner_edge(int index) const { return steiner_edge_.at(index - n_input); }
  // Provenance of the work queue (issue 4 diagnosis, refine2d_diagnosis.cpp).
  Propagation propagation;
  // The boundary sides (other than `side`) that a vertex at p, on `side`, would make violated: exactly those
  // among the edges of p's conflict zone (the triangles whose circumcircle strictly contains p, reachable from
  // `side`'s domain_faces across unconstrained edges; their triangles get p as apex) whose open half-disk contains p.
  // These are the forbidden intervals of `side` that contain p, visibility included. Cost: the conflict zone.
  std::vector<Side> sides_broken_by(const Side& side, const Point& p) const;

  // Whether v, strictly inside the open diametral disk of [a, b] on `start`'s edge, counts against it (Sight).
  bool sees(const Side& start, const Point& a, const Point& b, Vertex_handle v, Sight sight) const;

  // The greedy end from s toward e (s on the side `start`, whose left face touches [s, e]): the smallest
  // t = |q - s|^2 / ((q - s) . d), d = e - s, over the vertices q of `q` that [s, s + t d] would see (`sight`;
  // paper 4.4: only visible vertices encroach). At that t, q reaches the circle of [s, s + t d] (paper-notes:
  // (s - q).(x - q) >= 0 iff t (q - s).d <= |q - s|^2). 1 when nothing blocks; `blocker` receives the vertex.
  // Cost: one walk per candidate tried, in increasing t (usually one).
  double greedy_parameter(const Side& start, const Point& s, const Point& e, const std::vector<Vertex_handle>& q,
                          Sight sight, Vertex_handle* blocker = nullptr) const;
  // True when no vertex of q that [s, p] would see (`sight`) encroaches it (exact encroachment, on either side: q
  // only holds vertices of domain sides).
  bool subsegment_is_empty(const Side& start, const Point& s, const Point& p, const std::vector<Vertex_handle>& q,
                           Sight sight) const;

  // Single-edge Greedy-Refine (Theorem 2) of `side` against the encroachers of its disk walk only, without
  // inserting anything: the number of Steiner points it places, each rounded as the refinement rounds them; a
  // vertex counts against a subsegment only when the subsegment sees it (Sight with the walk's obstacles).
  int greedy_count(const Side& side, const DiskWalk& walk) const;

 private:
  // The two faces beside a constrained edge: left of s -> e (its apex at index i) and right (apex right_apex).
  struct Wings {
    Face_handle left, right;
    int i;
    Vertex_handle right_apex;
  };
  // One edge lookup; InternalError when the side is not a constrained edge.
  Wings wings(const Side& side) const;
  // Inserting p into the edge keeps both triangles beside it counter-clockwise (p may be ulps off the line, a
  // neighbouring apex nearly on it) and CGAL's convex hull convex (p must not bend a hull edge inward). Exact.
  bool splits_in_place(const Side& side, const Wings& w, const Point& p) const;
  // Every side of `sides` (the boundary sides) on the hull, no interface, every vertex on a constraint.
  bool is_convex_polygon(const std::vector<Side>& sides) const;
  // The neighbour of `from` along the constraint toward `end` (`end`, or a vertex the constraint passes through).
  Vertex_handle next_on_constraint(Vertex_handle from, Vertex_handle end) const;
  // Domain marks of the faces changed by inserting v between to_s and to_e (see split); queues their sides.
  void remark_around(Vertex_handle v, Vertex_handle to_e, Vertex_handle to_s, const cdt::FaceInfo& left,
                     const cdt::FaceInfo& right);
  // Depth-first walk on `lane` from the faces `start` across the unconstrained edges (u, w) for which
  // crosses(u, w) holds; visit(face) returns true to stop.
  template <class Crosses, class Visit>
  void walk(const std::vector<Face_handle>& start, Crosses&& crosses, Visit&& visit, int lane) const;
  // walk into the faces meeting the closed diametral disk of [a, b] (float pruning with slack: a little too far).
  template <class Visit>
  void walk_disk(const std::vector<Face_handle>& start, const Point& a, const Point& b, Visit&& visit,
                 int lane = 0) const;
  // A fresh stamp for a walk over faces on `lane`: the walk has reached a face iff its info().visit[lane] equals
  // the stamp (cheaper than a set of face handles). Walks on one lane must not nest; each lane has its own stamps,
  // so that walks on two lanes can run on two threads (the lower bound).
  unsigned new_walk(int lane) const { return ++walks_[lane]; }
  mutable unsigned walks_[2] = {0, 0};
  // walk_diametral_disk lists each vertex once: vertex_walk_[lane][index] is the stamp of the last walk on the
  // lane that listed it.
  mutable unsigned vertex_lists_[2] = {0, 0};
  mutable std::vector<unsigned> vertex_walk_[2];
  // Input boundary edge (min, max) -> index in edges; keyed min << 32 | max (a hash map: a polygon of a million
  // vertices has a million edges).
  std::unordered_map<std::uint64_t, int> edge_index_;
  static std::uint64_t edge_key(int a, int b) {
    return static_cast<std::uint64_t>(std::min(a, b)) << 32 | static_cast<std::uint32_t>(std::max(a, b));
  }
  std::vector<int> steiner_edge_;                   // Steiner point (index - n_input) -> index in edges
  long long splits_ = 0;                            // calls to split: the CDT changes only there
  mutable std::vector<Side> sides_;                 // boundary_sides() as of split number sides_of_
  mutable long long sides_of_ = -1;
};

// Exact CGAL::angle(a, apex, b) == OBTUSE, i.e. (a - apex) . (b - apex) < 0, with a static filter (Epick's Angle_2
// has none, and the disk walks evaluate it for every vertex they meet): the dot product in doubles decides when
// its magnitude exceeds 2^-50 times the sum of the absolute products, which bounds its rounding error (four
// roundings per product term, each relative 2^-53: under 4 * 2^-53 < 2^-50 of their sum); otherwise (near zero,
// or magnitudes where underflow or overflow void the bound) CGAL decides.
inline bool obtuse(const Point& a, const Point& apex, const Point& b) {
  const double ux = a.x() - apex.x(), uy = a.y() - apex.y(), vx = b.x() - apex.x(), vy = b.y() - apex.y();
  const double dot = ux * vx + uy * vy, bound = (std::abs(ux * vx) + std::abs(uy * vy)) * 0x1p-50;
  if (bound > 0x1p-900 && bound < 0x1p+900) {
    if (dot < -bound) return true;
    if (dot > bound) return false;
  }
  return CGAL::angle(a, apex, b) == CGAL::OBTUSE;
}

// Exact encroachment of q on side (s, e): q strictly left of s -> e and strictly inside the diametral disk.
inline bool encroaches(const Point& s, const Point& e, const Point& q) {
  return CGAL::orientation(s, e, q) == CGAL::LEFT_TURN && obtuse(s, q, e);
}

// Double points near s + t (e - s), t in (0, 1), that may stand for it on the subsegment, most preferred first:
// points exactly on the line (the dyadic parameters k / 2^m just below and above t that give exactly
// representable coordinates: with b-bit coordinates this succeeds once m + b <= 53, always for integer
// coordinates below 2^20), then points off the line to its right (outside the domain: the refined boundary
// s-p-e bends away from the domain), then to its left, each group nearest to the target first. Off-line
// candidates are the doubles nearest the line near the rounded point (within 2 ulps of the finer coordinate)
// and a grid up to 8 ulps outward. Every candidate is strictly between s and e (exact: angle(s, p, e) obtuse).
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

// Exact: q strictly inside the open diametral disk of [s, e], on either side (not on the line). The encroacher
// lists come from walk_diametral_disk, which only collects vertices on domain sides, so for a boundary edge this
// is `encroaches`, and for an interface it treats both sides at once (t* = min over both sides' encroachers).
inline bool inside_diametral_disk(const Point& s, const Point& e, const Point& q) {
  return CGAL::orientation(s, e, q) != CGAL::COLLINEAR && obtuse(s, q, e);
}

// Keeps the vertices of q still encroaching [s, e] (disks of subsegments that share e shrink as s advances).
void keep_encroaching(const Point& s, const Point& e, std::vector<Vertex_handle>& q);


// Splits `side` at the foot of q on it (rounded by pick_point): the new vertex, or nullptr when no double point
// strictly inside the side exists there or State::split refuses it. Defined in projection_refine.cpp.
Vertex_handle split_at_foot(State& st, const Side& side, const Point& q);

// The strategies; each runs until its queue is empty or the budget is spent.
void greedy_refine(State& state);
void projection_refine(State& state);
void project_flip(State& state);

}  // namespace nonobtuse::refine2d
