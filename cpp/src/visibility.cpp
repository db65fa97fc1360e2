// Visibility from a subsegment: the walk over its diametral disk and exact shading by obstacles.
#include "visibility.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <tuple>

namespace nonobtuse::refine2d {

namespace {

// A convex quadrilateral around the side [s, e] whose every point within `margin` of it lies inside: the corners
// s - m t + m n, s - m t - m n, e + m t - m n, e + m t + m n (t along the side, n its left normal, m = 2^-30 of
// the largest coordinate), rounded; rounding moves them by ulps, far less than m. Every subsegment end that
// greedy_count asks about lies within ulps of the side, hence inside.
std::array<Point, 4> fat_side(const Point& s, const Point& e) {
  const double m = 0x1p-30 * std::max({std::abs(s.x()), std::abs(s.y()), std::abs(e.x()), std::abs(e.y())});
  const double dx = e.x() - s.x(), dy = e.y() - s.y(), len = std::sqrt(dx * dx + dy * dy);
  const double tx = m * dx / len, ty = m * dy / len;  // m t; m n = (-ty, tx)
  return {Point(s.x() - tx - ty, s.y() - ty + tx), Point(s.x() - tx + ty, s.y() - ty - tx),
          Point(e.x() + tx + ty, e.y() + ty - tx), Point(e.x() + tx - ty, e.y() + ty + tx)};
}

// Exact: every closed segment from a point of the convex hull of `source` to x meets the closed segment c (x lies
// in c's umbra). The points y for which [y, x] meets c form a convex set (those on c or beyond it seen from x: a
// truncated cone, a ray or the plane), so holding the four corners suffices.
bool in_umbra(const std::array<Point, 4>& source, const Point& x, const Segment2& c) {
  return std::all_of(source.begin(), source.end(), [&](const Point& y) { return segments_meet(y, x, c.first, c.second); });
}

// A face waiting in walk_seen, with the last constraints met on the way to it (indices into the constraints met).
constexpr int kRecent = 4;
// Skipping a face is never needed for correctness, only for speed: the first kFreeFaces faces of a walk are
// crossed out of without the umbra tests, which would cost more than they save on the small disks of most sides
// (a convex polygon's, where nearly collinear neighbours also make the orientations slow).
constexpr std::size_t kFreeFaces = 16;
struct SeenEntry {
  Face_handle face;
  std::array<int, kRecent> recent;
};

// The Walked::Seen walk from the side's domain faces over its disk (right_in_domain: the side's other side is a
// domain side too); visit(face) for every face entered. After the first kFreeFaces faces, an unconstrained edge
// [u, w] near the disk is crossed unless
// - u and w both lie in the umbra (in_umbra, from fat_side) of one blocker: a constraint other than the side, among
//   those of the face being left, the last kRecent met on the way to it, and the first four met that touch the
//   side's ends (the walls that bound what the side sees); or
// - !right_in_domain, and u and w both lie strictly right of fat_side's right edge.
// Why the walk still enters every face that a sight line passes through before its first constraint (so that
// the first constraint on it is an obstacle and its end vertex an encroacher): such a sight line from a point y
// of fat_side enters the domain through the side and then crosses unconstrained edges at points p with [y, p]
// meeting no constraint but the side. Such a p is in no blocker's umbra (y sees it), and it is not strictly right
// of the fat side when the domain lies left only (the sight line runs from y to a vertex strictly left of the
// side). Either rule is a set inclusion tested exactly on corners of convex sets (the umbra and the half-plane are
// convex), so the walk never skips such an edge.
template <class Visit>
void walk_seen(const State& st, const Side& side, bool right_in_domain, Visit&& visit, int lane) {
  const Point &s = side.s->point(), &e = side.e->point();
  const DiskReach disk(s, e);
  const std::array<Point, 4> source = fat_side(s, e);
  auto beyond_right = [&](const Point& p) { return CGAL::orientation(source[1], source[2], p) == CGAL::RIGHT_TURN; };
  std::vector<Segment2> met;
  std::vector<int> walls;  // the constraints met touching s or e (at most four)
  const unsigned walk = ++st.lane(lane).face_walks;
  std::vector<SeenEntry> stack;
  for (Face_handle f : st.domain_faces(side)) {
    f->info().visit[lane] = walk;
    stack.push_back({f, {-1, -1, -1, -1}});
  }
  std::size_t entered = 0;
  while (!stack.empty()) {
    const SeenEntry entry = stack.back();
    stack.pop_back();
    Face_handle f = entry.face;
    visit(f);
    ++entered;
    std::array<int, kRecent> recent;  // the face's own constraints first, then its path's
    int k = 0;
    for (int i = 0; i < 3; ++i) {
      if (!f->is_constrained(i)) continue;
      Vertex_handle u = f->vertex(CDT::ccw(i)), w = f->vertex(CDT::cw(i));
      if ((u == side.s && w == side.e) || (u == side.e && w == side.s)) continue;
      recent[k++] = static_cast<int>(met.size());
      if (walls.size() < 4 && (u == side.s || u == side.e || w == side.s || w == side.e))
        walls.push_back(static_cast<int>(met.size()));
      met.emplace_back(u->point(), w->point());
    }
    for (int j = 0; k < kRecent; ++j) recent[k++] = entry.recent[j];
    auto hidden = [&](const Point& u, const Point& w) {
      if (!right_in_domain && beyond_right(u) && beyond_right(w)) return true;
      auto shades = [&](int c) { return c >= 0 && in_umbra(source, u, met[c]) && in_umbra(source, w, met[c]); };
      return std::any_of(recent.begin(), recent.end(), shades) || std::any_of(walls.begin(), walls.end(), shades);
    };
    for (int i = 0; i < 3; ++i) {
      if (f->is_constrained(i)) continue;
      Face_handle g = f->neighbor(i);
      if (g->info().visit[lane] == walk || st.cdt().is_infinite(g)) continue;
      const Point &u = f->vertex(CDT::ccw(i))->point(), &w = f->vertex(CDT::cw(i))->point();
      if (!disk.near(u, w) || (entered > kFreeFaces && hidden(u, w))) continue;
      g->info().visit[lane] = walk;
      stack.push_back({g, recent});
    }
  }
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

DiskWalk walk_diametral_disk(const State& st, const Side& side, int lane, Walked walked) {
  DiskWalk out;
  const Point &s = side.s->point(), &e = side.e->point();
  const bool left = st.is_boundary_side(side), right = st.is_boundary_side({side.e, side.s});
  auto on_domain_side = [&](const Point& q) { return (left && encroaches(s, e, q)) || (right && encroaches(e, s, q)); };
  std::vector<Vertex_handle> reached;  // the vertices of the faces reached (walks skip infinite faces), once each
  WalkLane& scratch = st.lane(lane);
  const unsigned stamp = ++scratch.vertex_lists;
  std::vector<unsigned>& listed = scratch.vertex_stamp;
  // Obstacles only where they come near the disk (the walk's own pruning test): a sight line from a point of the
  // edge to a vertex in the disk lies in the closed disk, and covered_from only uses obstacles that meet the
  // triangle (v, a, b) inside it or end at a or b; the faces reached reach far beyond the disk (a polygon's
  // fans), and their far constrained edges would make every covered_from linear in them.
  const DiskReach disk(s, e);
  auto visit = [&](Face_handle f) {
    for (int i = 0; i < 3; ++i) {
      const auto index = static_cast<std::size_t>(f->vertex(i)->info());
      if (index >= listed.size()) listed.resize(index + 1, 0);
      if (listed[index] != stamp) {
        listed[index] = stamp;
        reached.push_back(f->vertex(i));
      }
      Vertex_handle u = f->vertex(CDT::ccw(i)), w = f->vertex(CDT::cw(i));
      if (f->is_constrained(i) && !((u == side.s && w == side.e) || (u == side.e && w == side.s)) &&
          disk.near(u->point(), w->point()))
        out.obstacles.emplace_back(u->point(), w->point());
    }
    return false;
  };
  if (walked == Walked::Seen)
    walk_seen(st, side, right, visit, lane);
  else
    walk_disk(st, st.domain_faces(side), s, e, visit, lane);
  for (Vertex_handle v : reached)
    if (v != side.s && v != side.e && on_domain_side(v->point())) out.encroachers.push_back(v);
  // Deterministic order (the walk order depends on face handles): by vertex index.
  std::sort(out.encroachers.begin(), out.encroachers.end(),
            [](Vertex_handle a, Vertex_handle b) { return a->info() < b->info(); });
  return out;
}

bool sees(const State& st, const Side& start, const Point& a, const Point& b, Vertex_handle v, Sight sight) {
  if (sight.in_front != nullptr) return !covered_from(v->point(), a, b, sight.in_front->of(v));
  if (sight.obstacles != nullptr) return !covered_from(v->point(), a, b, *sight.obstacles);
  bool found = false;
  walk_disk(st, st.domain_faces(start), a, b, [&](Face_handle f) { return found = f->has_vertex(v); });
  return found;
}

// Exact: the closed segment [c1, c2] (c1 != c2) meets the closed triangle (p, q, r) (not degenerate). Two
// disjoint compact convex sets are strictly separated by a line parallel to an edge of one of them (separating
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

// The closed angular intervals the obstacles shade, seen from v, cover the open wedge from a to b. An obstacle
// shades the directions of its part in front of (a, b), inside the triangle (v, a, b): a constraint meets the line
// ab inside [a, b] at most at a or b (constraints do not cross the edge; a or b may be its vertices), so one ending
// at a or b is in front iff its other end is strictly on v's side, and any other iff it meets the triangle; then
// its own angular span clipped to the wedge is in front.
bool covered_from(const Point& v, const Point& a, const Point& b, const std::vector<Segment2>& obstacles) {
  const bool ccw = CGAL::orientation(v, a, b) == CGAL::LEFT_TURN;
  const Point &lo = ccw ? a : b, &hi = ccw ? b : a;  // the wedge, counter-clockwise from lo to hi (< 180 degrees)
  // Counter-clockwise order of directions from v; valid for directions less than 180 degrees apart, which holds
  // for every pair compared below (each obstacle kept meets the wedge and spans less than 180 degrees).
  // Equal points first: their orientation is exactly zero, which the filter cannot certify (exact arithmetic).
  auto before = [&v](const Point& p, const Point& q) { return p != q && CGAL::orientation(v, p, q) == CGAL::LEFT_TURN; };
  std::vector<Segment2> shades;
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
    const Point &first = before(from, lo) ? lo : from, &last = before(hi, to) ? hi : to;
    if (before(first, last)) shades.emplace_back(first, last);
  }
  std::sort(shades.begin(), shades.end(), [&](const auto& x, const auto& y) { return before(x.first, y.first); });
  const Point* reach = &lo;  // the directions from lo up to *reach are shaded (none strictly inside yet)
  for (const auto& [first, last] : shades) {
    if (before(*reach, first)) return false;  // an open gap of directions between *reach and first
    if (before(*reach, last)) reach = &last;
  }
  return !before(*reach, hi);
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

}  // namespace nonobtuse::refine2d
