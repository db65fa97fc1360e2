// Concentric shells around acute junctions.
//
// Where two constraints meet at an input vertex v at an angle theta < 90 degrees, a point on one of them can sit
// inside the diametral disk of a subsegment at v on the other: a point b at distance |vb| from v encroaches the
// subsegment [v, a] of the other constraint iff |vb| < |va| cos(theta). Splitting at arbitrary points can then
// ping-pong between the two constraints, each split creating a new encroacher on the other one.
//
// The split rule (shell_at_or_before, used by greedy_refine's choose_point when the sweep starts at an acute
// junction): the first Steiner point from v goes at the largest power-of-two distance 2^k from v that does not
// exceed the greedy (or forbidden-interval) choice x. [v, 2^k] lies inside [v, x], and the diametral disk of
// [v, y] for y between v and x lies inside the disk of [v, x] (both circles pass through v, centred on the same
// ray), so the shell point keeps every emptiness the greedy point had; it is still checked exactly.
//
// Termination argument: after such splits, every split subsegment at v has a power-of-two length, i.e. its far
// end lies on one of the concentric circles |x - v| = 2^k. Two such ends a, b on constraints at angle theta < 90:
//   - equal shells (|va| = |vb|) never encroach each other: |vb| < |va| cos(theta) fails;
//   - if b encroaches [v, a] (|vb| < |va| cos(theta)), the greedy end for [v, a] is at distance |vb| / cos(theta)
//     > |vb| (b on its circle), so the shell split puts a' at a power of two >= |vb| (|vb| is itself a power of
//     two <= that distance), and a' cannot encroach [v, b] (that needs |va'| < |vb| cos(theta) < |vb|).
// So a split at a junction never creates an encroacher of another junction subsegment that is shorter; lengths at
// v only decrease, in powers of two, down to the shortest shell present, which only something other than v's
// constraints can shorten: the ping-pong around v is finite (at most log2(longest / shortest) splits per
// constraint at v). Rounding the shell point to doubles moves it by ulps of |v|, far below the margin
// 1 - cos(theta) of the strict inequalities unless theta is within ulps of 0; every decision stays exact. Outside
// junctions there is no such argument for general PSLGs (paper, Figure 6), hence the Steiner budget.
#include "concentric_shells.h"

#include <cmath>

namespace nonobtuse::refine2d {

namespace {

// Domain triangles on both sides of the constrained edge (a, b): an interface or a dangling segment.
bool is_interior_constraint(const State& st, Vertex_handle a, Vertex_handle b) {
  return st.is_boundary_side({a, b}) && st.is_boundary_side({b, a});
}

}  // namespace

bool is_acute_junction(const State& st, Vertex_handle v, Vertex_handle w) {
  if (v->info() < 0 || v->info() >= st.n_input()) return false;
  const bool interior = is_interior_constraint(st, v, w);
  auto ec = st.cdt().incident_edges(v), done = ec;
  if (ec == nullptr) return false;
  do {
    if (!ec->first->is_constrained(ec->second)) continue;
    Vertex_handle a = ec->first->vertex(CDT::ccw(ec->second)), b = ec->first->vertex(CDT::cw(ec->second));
    Vertex_handle u = a == v ? b : a;
    if (u != w && !st.cdt().is_infinite(u) && (interior || is_interior_constraint(st, v, u)) &&
        CGAL::angle(w->point(), v->point(), u->point()) == CGAL::ACUTE)
      return true;
  } while (++ec != done);
  return false;
}

Side shell_anchor(const State& st, const Side& side) {
  Side reverse{side.e, side.s};
  if (!is_acute_junction(st, side.s, side.e) && is_acute_junction(st, side.e, side.s) && st.is_boundary_side(reverse))
    return reverse;
  return side;
}

double shell_at_or_before(const Point& s, const Point& e, double t) {
  double length = std::sqrt(CGAL::to_double(CGAL::squared_distance(s, e)));
  double x = t * length;
  if (!(x > 0)) return t;
  return std::ldexp(1.0, std::ilogb(x)) / length;  // 2^floor(log2 x) / |e - s|
}

}  // namespace nonobtuse::refine2d
