// Exact shading of a side by obstacles seen from a vertex: covered_from and the per-vertex ShadowIntervals.
#include "shadows.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <iterator>
#include <tuple>
#include <utility>

namespace nonobtuse::refine2d {

namespace {

// Counter-clockwise order of directions from v; valid for directions less than 180 degrees apart, which holds for
// every pair compared in this file. Equal points first: their orientation is exactly zero, which the filter cannot
// certify (exact arithmetic).
struct Before {
  const Point& v;
  bool operator()(const Point& p, const Point& q) const { return p != q && CGAL::orientation(v, p, q) == CGAL::LEFT_TURN; }
};

// The wedge of directions from v to the open segment (a, b), counter-clockwise from lo to hi (< 180 degrees).
struct Wedge {
  const Point &lo, &hi;
  Wedge(const Point& v, const Point& a, const Point& b)
      : lo(CGAL::orientation(v, a, b) == CGAL::LEFT_TURN ? a : b), hi(&lo == &a ? b : a) {}
};

// The shadows in `wedge` of the obstacles in front of (a, b) seen from v (covered_from's rule), appended to `out`.
// An obstacle shades the directions of its part in front of (a, b), inside the triangle (v, a, b): a constraint
// meets the line ab inside [a, b] at most at a or b (constraints do not cross the edge; a or b may be its
// vertices), so one ending at a or b is in front iff its other end is strictly on v's side, and any other iff it
// meets the triangle; then its own angular span clipped to the wedge is in front. Obstacles ending at v or
// pointing at it shade nothing.
void add_shadows(const Point& v, const Point& a, const Point& b, const Wedge& wedge, const std::vector<Segment2>& obstacles,
                 std::vector<Segment2>& out) {
  const Before before{v};
  const auto v_side = CGAL::orientation(a, b, v);
  auto in_front = [&](const Point& c1, const Point& c2) {
    if (c1 == a || c1 == b) return CGAL::orientation(a, b, c2) == v_side;
    if (c2 == a || c2 == b) return CGAL::orientation(a, b, c1) == v_side;
    return segment_meets_triangle(c1, c2, v, a, b);
  };
  for (const auto& [c1, c2] : obstacles) {
    auto o = CGAL::orientation(v, c1, c2);
    if (c1 == v || c2 == v || o == CGAL::COLLINEAR || !in_front(c1, c2)) continue;
    const Point &from = o == CGAL::LEFT_TURN ? c1 : c2, &to = o == CGAL::LEFT_TURN ? c2 : c1;
    const Point &first = before(from, wedge.lo) ? wedge.lo : from, &last = before(wedge.hi, to) ? wedge.hi : to;
    if (before(first, last)) out.emplace_back(first, last);
  }
}

// Whether the closed intervals of directions `merged` (disjoint, counter-clockwise) and `shadows` (sorted by their
// first direction) together cover the directions from lo to hi. A sweep: *reach is the end of the covered prefix;
// each round extends it by the merged interval holding it (binary search) and by every shadow starting at or
// before it, and a round without progress leaves an open gap just after *reach.
bool covers(const Before& before, const Point& lo, const Point& hi, const std::vector<Segment2>& merged,
            const std::vector<Segment2>& shadows) {
  const Point* reach = &lo;
  std::size_t next = 0;
  while (before(*reach, hi)) {
    const Point* was = reach;
    auto it = std::upper_bound(merged.begin(), merged.end(), *reach,
                               [&](const Point& r, const Segment2& m) { return before(r, m.first); });
    if (it != merged.begin() && before(*reach, std::prev(it)->second)) reach = &std::prev(it)->second;
    for (; next < shadows.size() && !before(*reach, shadows[next].first); ++next)
      if (before(*reach, shadows[next].second)) reach = &shadows[next].second;
    if (reach == was) return false;
  }
  return true;
}

void sort_by_first(const Before& before, std::vector<Segment2>& shadows) {
  std::sort(shadows.begin(), shadows.end(), [&](const auto& x, const auto& y) { return before(x.first, y.first); });
}

}  // namespace

bool segments_meet(const Point& p, const Point& q, const Point& c1, const Point& c2) {
  if (p == c1 || p == c2 || q == c1 || q == c2) return true;
  if (std::max(p.x(), q.x()) < std::min(c1.x(), c2.x()) || std::max(c1.x(), c2.x()) < std::min(p.x(), q.x()) ||
      std::max(p.y(), q.y()) < std::min(c1.y(), c2.y()) || std::max(c1.y(), c2.y()) < std::min(p.y(), q.y()))
    return false;
  const auto o1 = CGAL::orientation(p, q, c1), o2 = CGAL::orientation(p, q, c2);
  if (o1 == o2 && o1 != CGAL::COLLINEAR) return false;
  const auto o3 = CGAL::orientation(c1, c2, p), o4 = CGAL::orientation(c1, c2, q);
  // Otherwise they meet; all four on one line with overlapping bounding boxes overlap too.
  return !(o3 == o4 && o3 != CGAL::COLLINEAR);
}

// Two disjoint compact convex sets are strictly separated by a line parallel to an edge of one of them (separating
// axes), so they are disjoint iff both ends lie strictly beyond one edge's line, or the three corners strictly on
// one side of the segment's line. Orientations only: filtered predicates, no constructions (CGAL's do_intersect
// constructs line intersections, exactly in rationals whenever an end lies on a side's line).
bool segment_meets_triangle(const Point& c1, const Point& c2, const Point& p, const Point& q, const Point& r) {
  for (const auto& [u, w, x] : {std::tie(p, q, r), std::tie(q, r, p), std::tie(r, p, q)}) {
    const auto outside = -CGAL::orientation(u, w, x);
    if (CGAL::orientation(u, w, c1) == outside && CGAL::orientation(u, w, c2) == outside) return false;
  }
  const auto o = CGAL::orientation(c1, c2, p);
  return o == CGAL::COLLINEAR || CGAL::orientation(c1, c2, q) != o || CGAL::orientation(c1, c2, r) != o;
}

// The closed angular intervals the obstacles shade, seen from v, cover the open wedge from a to b (add_shadows
// says which obstacles shade what; each kept meets the wedge and spans less than 180 degrees).
bool covered_from(const Point& v, const Point& a, const Point& b, const std::vector<Segment2>& obstacles) {
  const Before before{v};
  const Wedge wedge(v, a, b);
  std::vector<Segment2> shadows;
  add_shadows(v, a, b, wedge, obstacles, shadows);
  sort_by_first(before, shadows);
  return covers(before, wedge.lo, wedge.hi, {}, shadows);
}

std::array<Point, 4> fat_side(const Point& s, const Point& e) {
  const double m = 0x1p-30 * std::max({std::abs(s.x()), std::abs(s.y()), std::abs(e.x()), std::abs(e.y())});
  const double dx = e.x() - s.x(), dy = e.y() - s.y(), len = std::sqrt(dx * dx + dy * dy);
  const double tx = m * dx / len, ty = m * dy / len;  // m t; m n = (-ty, tx)
  return {Point(s.x() - tx - ty, s.y() - ty + tx), Point(s.x() - tx + ty, s.y() - ty - tx),
          Point(e.x() + tx + ty, e.y() + ty - tx), Point(e.x() + tx - ty, e.y() + ty + tx)};
}
std::vector<Segment2> obstacles_near_triangle(const Point& v, const Point& s, const Point& e,
                                              const std::vector<Segment2>& obstacles) {
  const std::array<Point, 3> corner = {v, s, e};
  auto largest = [](const Point& p) { return std::max(std::abs(p.x()), std::abs(p.y())); };
  const double corners_largest = std::max({largest(v), largest(s), largest(e)});
  // (p - o) x (q - o) in doubles.
  auto cross = [](const Point& o, const Point& p, const Point& q) {
    return (p.x() - o.x()) * (q.y() - o.y()) - (p.y() - o.y()) * (q.x() - o.x());
  };
  auto length = [](const Point& o, const Point& p) { return std::sqrt(CGAL::to_double(CGAL::squared_distance(o, p))); };
  // All of `points` strictly beyond the line o -> p (of length `len`) on the side `sign` (+1 left, -1 right) by
  // more than margin; false whenever a value is not finite (the obstacle is kept).
  auto beyond = [&](const Point& o, const Point& p, double len, double sign, double margin,
                    std::initializer_list<Point> points) {
    for (const Point& q : points)
      if (!(sign * cross(o, p, q) > margin * len)) return false;
    return true;
  };
  std::array<double, 3> side_length, outside;  // edge k of (v, s, e): corner k -> corner k + 1
  for (int k = 0; k < 3; ++k) {
    side_length[k] = length(corner[k], corner[(k + 1) % 3]);
    outside[k] = cross(corner[k], corner[(k + 1) % 3], corner[(k + 2) % 3]) > 0 ? -1.0 : 1.0;  // away from the third
  }
  std::vector<Segment2> out;
  for (const Segment2& c : obstacles) {
    const double margin = 0x1p-30 * std::max({corners_largest, largest(c.first), largest(c.second)});
    bool apart = false;
    for (int k = 0; k < 3 && !apart; ++k)
      apart = beyond(corner[k], corner[(k + 1) % 3], side_length[k], outside[k], margin, {c.first, c.second});
    const double len = apart ? 0.0 : length(c.first, c.second);
    apart = apart || beyond(c.first, c.second, len, 1.0, margin, {v, s, e}) ||
            beyond(c.first, c.second, len, -1.0, margin, {v, s, e});
    if (!apart) out.push_back(c);
  }
  return out;
}

bool in_umbra(const std::array<Point, 4>& source, const Point& x, const Segment2& c) {
  return std::all_of(source.begin(), source.end(), [&](const Point& y) { return segments_meet(y, x, c.first, c.second); });
}

std::vector<Segment2> unshaded_obstacles(const std::array<Point, 4>& fat, const Point& s, const Point& e,
                                         const std::vector<Segment2>& obstacles) {
  // Squared distance from [s, e] to the nearer end (doubles: the order only guides the search).
  auto distance2 = [&](const Segment2& c) {
    return std::min(distance2_to_segment(c.first.x(), c.first.y(), s, e),
                    distance2_to_segment(c.second.x(), c.second.y(), s, e));
  };
  std::vector<std::pair<double, std::size_t>> order;
  order.reserve(obstacles.size());
  for (std::size_t k = 0; k < obstacles.size(); ++k) order.emplace_back(distance2(obstacles[k]), k);
  std::sort(order.begin(), order.end());
  std::vector<std::size_t> kept;
  for (const auto& [d2, k] : order) {
    const Segment2& c = obstacles[k];
    const std::size_t tries = std::min(kept.size(), kUmbraTries);
    auto behind = [&](std::size_t j) { return in_umbra(fat, c.first, obstacles[j]) && in_umbra(fat, c.second, obstacles[j]); };
    if (std::none_of(kept.end() - static_cast<std::ptrdiff_t>(tries), kept.end(), behind)) kept.push_back(k);
  }
  std::sort(kept.begin(), kept.end());
  std::vector<Segment2> out;
  out.reserve(kept.size());
  for (std::size_t k : kept) out.push_back(obstacles[k]);
  return out;
}

const ShadowIntervals& ObstaclesInFront::shadows(Vertex_handle v, const std::vector<Segment2>& obstacles,
                                                 ByVertex& built) const {
  auto it = built.find(v->info());
  if (it == built.end())
    it = built.emplace(v->info(), ShadowIntervals(v->point(), fat_, obstacles_near_triangle(v->point(), s_, e_, obstacles)))
             .first;
  return it->second;
}

ShadowIntervals::ShadowIntervals(const Point& v, const std::array<Point, 4>& fat, std::vector<Segment2> obstacles)
    : v_(v), obstacles_(std::move(obstacles)) {
  // fat is counter-clockwise, so H, strictly right of one of its sides, lies outside it; only the long sides
  // (fat[1] -> fat[2] along the side's right, fat[3] -> fat[0] along its left) can face an encroacher.
  if (CGAL::orientation(fat[3], fat[0], v) == CGAL::RIGHT_TURN)
    facing_ = {fat[3], fat[0]};
  else if (CGAL::orientation(fat[1], fat[2], v) == CGAL::RIGHT_TURN)
    facing_ = {fat[1], fat[2]};
  else
    return;
  const Before before{v_};
  lo_ = hi_ = fat[0];  // fat lies outside H: its corners within half a turn seen from v
  for (const Point& corner : fat) {
    if (before(corner, lo_)) lo_ = corner;
    if (before(hi_, corner)) hi_ = corner;
  }
  auto inner = [&](const Point& p, const Point& q) {
    return (CGAL::orientation(v_, lo_, p) == CGAL::LEFT_TURN && CGAL::orientation(v_, lo_, q) == CGAL::LEFT_TURN) ||
           (CGAL::orientation(v_, hi_, p) == CGAL::RIGHT_TURN && CGAL::orientation(v_, hi_, q) == CGAL::RIGHT_TURN);
  };
  std::vector<Segment2> shadows;
  for (const Segment2& c : obstacles_) {
    const auto& [c1, c2] = c;
    const auto o = CGAL::orientation(v_, c1, c2);
    if (c1 == v_ || c2 == v_ || o == CGAL::COLLINEAR) continue;  // shades nothing (add_shadows)
    if (!(in_h(c1) && in_h(c2) && inner(c1, c2))) {
      maybe_.push_back(c);
      continue;
    }
    const Point &from = o == CGAL::LEFT_TURN ? c1 : c2, &to = o == CGAL::LEFT_TURN ? c2 : c1;
    const Point &first = before(from, lo_) ? lo_ : from, &last = before(hi_, to) ? hi_ : to;
    if (before(first, last)) shadows.emplace_back(first, last);
  }
  sort_by_first(before, shadows);
  for (const Segment2& shadow : shadows) {
    if (merged_.empty() || before(merged_.back().second, shadow.first))
      merged_.push_back(shadow);
    else if (before(merged_.back().second, shadow.second))
      merged_.back().second = shadow.second;
  }
  prepared_ = true;
}

bool ShadowIntervals::in_h(const Point& p) const {
  return CGAL::orientation(facing_.first, facing_.second, p) == CGAL::RIGHT_TURN;
}

bool ShadowIntervals::covered(const Point& a, const Point& b) const {
  if (!prepared_ || in_h(a) || in_h(b) || CGAL::orientation(v_, a, b) == CGAL::COLLINEAR)
    return covered_from(v_, a, b, obstacles_);
  const Before before{v_};
  const Wedge wedge(v_, a, b);
  // a and b lie outside H, like fat: all these directions lie within half a turn.
  if (before(wedge.lo, lo_) || before(hi_, wedge.hi)) return covered_from(v_, a, b, obstacles_);
  std::vector<Segment2> shadows;
  add_shadows(v_, a, b, wedge, maybe_, shadows);
  sort_by_first(before, shadows);
  return covers(before, wedge.lo, wedge.hi, merged_, shadows);
}

}  // namespace nonobtuse::refine2d
