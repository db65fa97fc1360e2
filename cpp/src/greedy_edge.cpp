// Single-edge Greedy-Refine (Theorem 2): the greedy end, subsegment emptiness and the greedy count.
#include "greedy_edge.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "split_point.h"

namespace nonobtuse::refine2d {

Encroachers with_points(const std::vector<Vertex_handle>& vertices, const Point& s, const Point& e) {
  Encroachers q;
  q.axis = std::abs(e.y() - s.y()) > std::abs(e.x() - s.x()) ? 1 : 0;
  q.items.reserve(vertices.size());
  for (Vertex_handle v : vertices) q.items.push_back({v->point(), v});
  std::stable_sort(q.items.begin(), q.items.end(),
                   [axis = q.axis](const Encroacher& a, const Encroacher& b) { return a.p[axis] < b.p[axis]; });
  return q;
}

namespace {

// The items whose coordinate along q.axis may lie strictly inside the diametral disk of [s, p]: that disk spans
// [min - |other|/2, max + |other|/2] along the axis (centre +- radius, radius <= (|dx| + |dy|) / 2), where min and
// max are s's and p's coordinates and |other| their difference along the other axis. The float bounds use
// |other| itself: its computed value is at least half the exact one, so the real-number bounds enclose the disk's,
// and rounding to nearest is monotone, so no double coordinate inside the exact span falls outside the rounded one.
std::pair<std::vector<Encroacher>::const_iterator, std::vector<Encroacher>::const_iterator> may_be_inside(
    const Encroachers& q, const Point& s, const Point& p) {
  const int a = q.axis;
  const double margin = std::abs(p[1 - a] - s[1 - a]);
  const double lo = std::min(s[a], p[a]) - margin, hi = std::max(s[a], p[a]) + margin;
  auto first = std::lower_bound(q.items.begin(), q.items.end(), lo,
                                [a](const Encroacher& c, double x) { return c.p[a] < x; });
  auto last = std::upper_bound(first, q.items.end(), hi, [a](double x, const Encroacher& c) { return x < c.p[a]; });
  return {first, last};
}

}  // namespace

double greedy_parameter(const State& st, const Side& start, const Point& s, const Point& e, const Encroachers& q,
                        Sight sight, Vertex_handle* blocker) {
  double dx = e.x() - s.x(), dy = e.y() - s.y();
  std::vector<std::pair<double, Vertex_handle>> order;
  for (const auto& [point, v] : q.items) {
    double wx = point.x() - s.x(), wy = point.y() - s.y();
    double den = wx * dx + wy * dy;  // > |w|^2 > 0 for an encroacher: (q - s).(e - s) = |q - s|^2 - (s - q).(e - q)
    if (den > 0) order.emplace_back((wx * wx + wy * wy) / den, v);
  }
  // Candidates in increasing (t, index), popped from a heap: usually the first one decides, and a point set's
  // hull edge has a large part of the input in its disk, which a full sort per step would order every time.
  auto later = [](const auto& a, const auto& b) {
    return std::make_pair(a.first, a.second->info()) > std::make_pair(b.first, b.second->info());
  };
  std::make_heap(order.begin(), order.end(), later);
  // q blocks at the first t >= t_q where [s, s + t d] sees it (paper 4.4: only visible vertices encroach).
  // Subsegments and their disks grow with t, so seeing (either sight) is monotone in t: bisect when q is hidden at
  // t_q (behind a reflex spike, it may come into view later).
  auto seen = [&](double t, Vertex_handle v) { return sees(st, start, s, Point(s.x() + t * dx, s.y() + t * dy), v, sight); };
  double best = 1.0;
  while (!order.empty()) {
    std::pop_heap(order.begin(), order.end(), later);
    const auto [tq, v] = order.back();
    order.pop_back();
    if (tq >= best) break;
    double t = tq;
    if (!seen(tq, v)) {
      if (!seen(best, v)) continue;
      double lo = tq, hi = best;  // hidden at lo, seen at hi
      for (int k = 0; k < 48 && lo < hi * (1 - 0x1p-40); ++k) (seen(0.5 * (lo + hi), v) ? hi : lo) = 0.5 * (lo + hi);
      t = hi;
    }
    if (t < best) {
      best = t;
      if (blocker) *blocker = v;
    }
  }
  return best;
}

void keep_encroaching(const Point& s, const Point& e, Encroachers& q) {
  auto [first, last] = may_be_inside(q, s, e);
  const auto kept_from = first - q.items.cbegin(), kept_to = last - q.items.cbegin();
  q.items.erase(q.items.begin() + kept_to, q.items.end());
  q.items.erase(q.items.begin(), q.items.begin() + kept_from);
  q.items.erase(std::remove_if(q.items.begin(), q.items.end(),
                               [&](const Encroacher& c) { return !inside_diametral_disk(s, e, c.p); }),
                q.items.end());
}

bool subsegment_is_empty(const State& st, const Side& start, const Point& s, const Point& p, const Encroachers& q,
                         Sight sight) {
  std::vector<Vertex_handle> inside;
  auto [first, last] = may_be_inside(q, s, p);
  for (auto c = first; c != last; ++c)
    if (inside_diametral_disk(s, p, c->p)) inside.push_back(c->v);
  if (inside.empty()) return true;
  if (sight.obstacles != nullptr)
    return std::none_of(inside.begin(), inside.end(), [&](Vertex_handle v) { return sees(st, start, s, p, v, sight); });
  // Reach: one walk for all of them (v is reachable iff some face of the whole walk has it).
  std::sort(inside.begin(), inside.end());
  bool seen = false;
  walk_disk(st, st.domain_faces(start), s, p, [&](Face_handle f) {
    for (int i = 0; i < 3; ++i) seen = seen || std::binary_search(inside.begin(), inside.end(), f->vertex(i));
    return seen;
  });
  return !seen;
}

int greedy_count(const State& st, const Side& side, const DiskWalk& walk) {
  if (walk.encroachers.empty()) return 0;  // most sides: no shadows to build (a polygon's million edges)
  Encroachers q = with_points(walk.encroachers, side.s->point(), side.e->point());
  // Every subsegment below lies on the side, up to rounding: each vertex's sight questions scan only the obstacles
  // near its triangle with the side.
  const ObstaclesInFront in_front(side.s->point(), side.e->point(), walk.obstacles);
  const Sight sight{&walk.obstacles, &in_front};
  Point x = side.s->point();
  const Point& e = side.e->point();
  int count = 0;
  // Each step places a point strictly between x and e; the count of the exact greedy is at most |q| (projecting
  // every vertex works), the bound below only guards against rounding making steps degenerate.
  for (std::size_t step = 0; step < 2 * q.items.size() + 8; ++step) {
    keep_encroaching(x, e, q);
    if (q.items.empty()) break;
    double t = greedy_parameter(st, side, x, e, q, sight);
    if (t >= 1) break;
    Point p;
    auto empty = [&](const Point& c) { return subsegment_is_empty(st, side, x, c, q, sight); };
    if (!pick_point_at_or_before(x, e, t, empty, p)) break;
    x = p;
    ++count;
  }
  return count;
}

}  // namespace nonobtuse::refine2d
