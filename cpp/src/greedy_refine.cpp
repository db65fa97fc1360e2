// Sensitive Greedy-Refine (paper sections 4.1-4.4) on the constrained Delaunay triangulation.
//
// A boundary side (s, e) is violated when its triangle's apex is strictly inside the diametral disk; in a CDT
// that happens iff some vertex visible from the open subsegment lies in the open half-disk on the domain side.
// A sweep walks from s toward e: each step places the Steiner point x at the end of the longest subsegment
// [s, x] whose half-disk holds no vertex it sees (closed form t* = min |q - s|^2 / ((q - s) . d) over the
// vertices q reachable inside the disk, Theorem 2 and section 4.4), unless x lies in a forbidden interval: inside
// the open half-disk of another boundary subsegment f whose triangle would get x as apex (found exactly in x's
// conflict zone), where x would break f (Figure 5). Then x moves back to the interval's start (Theorem 3's
// rule); where the start is s itself, see choose_point.
//
// PSLGs: an interface or dangling subsegment is swept once for both of its sides (encroachers of both,
// t* = min over both); a sweep starting at an acute junction puts its first point on a power-of-two shell
// (concentric_shells.cpp, with the termination argument of that rule).
//
// Termination: every step inserts one Steiner point strictly inside the subsegment being refined, and the
// budget caps the points; a side is deferred at most once (the deferred set), so the queue drains: a side leaves
// the queue when it is not violated, and re-enters only when a split changes its triangle. Within the budget,
// for convex polygons Theorem 3 bounds the points by the optimum; in general (holes, reflex vertices,
// interfaces) no polynomial bound is known (paper, Figure 6), hence the budget and the status.
#include <algorithm>
#include <optional>
#include <set>

#include "concentric_shells.h"
#include "forbidden_intervals.h"
#include "greedy_edge.h"
#include "refine2d_strategies.h"
#include "split_point.h"

namespace nonobtuse::refine2d {
namespace {

using Key = std::pair<int, int>;
Key key(const Side& side) { return {side.s->info(), side.e->info()}; }

// Paper 4.3: when the greedy step is blocked by a vertex on the boundary whose own subsegment is violated,
// refine that subsegment first (its refinement may unblock this one).
bool blocked_by_violated_boundary(const State& st, Vertex_handle blocker) {
  auto ec = st.cdt().incident_edges(blocker), done = ec;
  if (ec == nullptr) return false;
  do {
    if (!ec->first->is_constrained(ec->second)) continue;
    Vertex_handle a = ec->first->vertex(CDT::ccw(ec->second)), b = ec->first->vertex(CDT::cw(ec->second));
    if (st.is_violated({a, b}) || st.is_violated({b, a})) return true;
  } while (++ec != done);
  return false;
}

enum class Step { Place, Defer, Stuck };

// Chooses the next Steiner point on `cur` (violated) given the walk's encroachers.
Step choose_point(State& st, const Side& cur, const Encroachers& q, std::set<Key>& deferred, Point& p) {
  const Point &s = cur.s->point(), &e = cur.e->point();
  auto empty = [&](const Point& c) {
    return splittable(st, cur, c) && subsegment_is_empty(st, cur, s, c, q, Sight{});
  };
  auto allowed = [&](const Point& c) { return empty(c) && !forbidder(st, cur, c); };
  Vertex_handle blocker;
  const double t_greedy = greedy_parameter(st, cur, s, e, q, Sight{}, &blocker);
  const bool may_defer = !deferred.count(key(cur));
  auto defer = [&] {
    deferred.insert(key(cur));
    return Step::Defer;
  };
  // Paper 4.3: blocked by a boundary vertex whose subsegment is violated: refine that one first.
  if (may_defer && blocker != nullptr && blocked_by_violated_boundary(st, blocker)) return defer();
  // Concentric shells: from an acute junction the first point goes on a power-of-two shell (concentric_shells.cpp).
  if (is_acute_junction(st, cur.s, cur.e) && pick_point(s, e, shell_at_or_before(s, e, t_greedy), allowed, p))
    return Step::Place;
  double t = t_greedy;
  // Each iteration places a point or moves t strictly back toward s (to a forbidden interval's start, or by a
  // relative 2^-40 when rounding put the start inside the interval again); every candidate is checked exactly.
  for (int iter = 0; iter < 64; ++iter) {
    if (!pick_point_at_or_before(s, e, t, empty, p)) break;
    std::optional<Side> f = forbidder(st, cur, p);
    if (!f) return Step::Place;
    auto [t_start, t_end] = forbidden_interval(s, e, *f);
    // An interval starting within 2^-20 |e - s| of s counts as starting at s: s was itself placed at the start of
    // f's interval (on f's circle up to rounding), and moving back to it would only creep forward by ulps.
    if (!in_closed_disk(s, *f) && t_start > 0x1p-20) {
      // Theorem 3: move back to the start of the forbidden interval. Where two intervals touch (the single-point
      // gap of Lemma 2, e.g. the foot of an obtuse apex), the exact gap point is among the candidates.
      if (pick_point(s, e, t_start, allowed, p)) {
        // The move back pays only when the next step can then clear f's interval: [p, end of the interval]
        // empty. Otherwise a later point lands in f's disk anyway (f is then refined in turn), and the greedy
        // point, farther along, covers more (the layers of experiments/figure6_propagation.py: 2n - 1 -> n).
        const double te = std::min(t_end, 1.0);
        const Point end = te < 1 ? Point(s.x() + te * (e.x() - s.x()), s.y() + te * (e.y() - s.y())) : e;
        if (subsegment_is_empty(st, cur, p, end, q, Sight{})) return Step::Place;
        break;
      }
      t = std::min(t_start, t * (1 - 0x1p-40));
      continue;
    }
    // The interval starts at s: no point before it. If f is violated itself, refine it first (paper 4.3).
    if (may_defer && st.is_violated(*f)) return defer();
    // Otherwise the end of the interval: s is on f's circle, so [s, end] is a chord of f's disk whose half on
    // f's side lies in f's empty disk: usually empty; checked exactly.
    if (t_end < 1 && pick_point(s, e, t_end, allowed, p)) return Step::Place;
    break;
  }
  // Fallback: the plain greedy point, which breaks f's disk (f is re-queued by the split and refined in turn).
  st.note_fallback();
  return pick_point_at_or_before(s, e, t_greedy, empty, p) ? Step::Place : Step::Stuck;
}

// Refines the violated side from s toward e until the remaining subsegment is fine, a step is deferred, or the
// budget is spent. The walk runs once: points placed on this edge lie on its line or within ulps of it, where
// they do not encroach its other subsegments, so the first walk's encroachers stay a superset; should that ever
// fail (the apex is not among them), the walk is redone.
void sweep(State& st, Side cur, std::set<Key>& deferred) {
  // Interfaces: both sides at once (the walk collected both sides' encroachers).
  Encroachers q = with_points(walk_diametral_disk(st, cur).encroachers, cur.s->point(), cur.e->point());
  while (st.budget_left() && (st.is_violated(cur) || st.is_violated({cur.e, cur.s}))) {
    keep_encroaching(cur.s->point(), cur.e->point(), q);
    const Vertex_handle apex = st.apex(cur);
    if (std::none_of(q.items.begin(), q.items.end(), [&](const Encroacher& c) { return c.v == apex; }))
      q = with_points(walk_diametral_disk(st, cur).encroachers, cur.s->point(), cur.e->point());
    Point p;
    Step step = choose_point(st, cur, q, deferred, p);
    if (step == Step::Defer) st.enqueue(cur);
    if (step != Step::Place) return;
    Vertex_handle v = split(st, cur, p);
    if (v == nullptr) return;
    cur = {v, cur.e};
  }
}

}  // namespace

void greedy_refine(State& st) {
  st.enqueue_all();
  greedy_refine_queued(st);
}

void greedy_refine_queued(State& st) {
  std::set<Key> deferred;
  while (st.has_work() && st.budget_left()) {
    Side side = st.next_side();
    if (!st.is_violated(side)) continue;
    const std::size_t before = st.queued();
    st.propagation().begin(side.s->info(), side.e->info(), st.added().size());
    sweep(st, shell_anchor(st, side), deferred);
    for (std::size_t i = before; i < st.queued(); ++i)
      st.propagation().queued(st.queued_at(i).s->info(), st.queued_at(i).e->info());
    st.propagation().end(st.added().size());
  }
}

}  // namespace nonobtuse::refine2d
