// Forbidden intervals: the boundary sides a Steiner point would break, and where the interval lies.
#include "forbidden_intervals.h"

#include <algorithm>
#include <cmath>

namespace nonobtuse::refine2d {

std::vector<Side> sides_broken_by(const State& st, const Side& side, const Point& p) {
  std::vector<Side> out;
  const Side reverse{side.e, side.s};
  std::vector<Face_handle> stack = st.domain_faces(side);
  const unsigned walk = ++st.lane(0).face_walks;
  for (Face_handle f : stack) f->info().visit[0] = walk;
  while (!stack.empty()) {
    Face_handle f = stack.back();
    stack.pop_back();
    for (int i = 0; i < 3; ++i) {
      Side edge{f->vertex(CDT::ccw(i)), f->vertex(CDT::cw(i))};  // f is on its left
      if (f->is_constrained(i)) {
        if (!same_side(edge, side) && !same_side(edge, reverse) && st.is_boundary_side(edge) &&
            encroaches(edge.s->point(), edge.e->point(), p))
          out.push_back(edge);
        continue;
      }
      Face_handle g = f->neighbor(i);
      if (g->info().visit[0] == walk || st.cdt().is_infinite(g)) continue;
      g->info().visit[0] = walk;
      if (CGAL::side_of_bounded_circle(g->vertex(0)->point(), g->vertex(1)->point(), g->vertex(2)->point(), p) ==
          CGAL::ON_BOUNDED_SIDE)
        stack.push_back(g);
    }
  }
  return out;
}

std::optional<Side> forbidder(const State& st, const Side& cur, const Point& p) {
  std::vector<Side> broken = sides_broken_by(st, cur, p);
  if (broken.empty()) return std::nullopt;
  return broken.front();
}

std::pair<double, double> forbidden_interval(const Point& s, const Point& e, const Side& f) {
  const Point &a = f.s->point(), &b = f.e->point();
  double mx = 0.5 * (a.x() + b.x()), my = 0.5 * (a.y() + b.y());
  double r2 = 0.25 * ((b.x() - a.x()) * (b.x() - a.x()) + (b.y() - a.y()) * (b.y() - a.y()));
  double dx = e.x() - s.x(), dy = e.y() - s.y(), wx = s.x() - mx, wy = s.y() - my;
  double A = dx * dx + dy * dy, B = 2 * (dx * wx + dy * wy), C = wx * wx + wy * wy - r2;
  double disc = std::max(0.0, B * B - 4 * A * C), root = std::sqrt(disc);
  return {(-B - root) / (2 * A), (-B + root) / (2 * A)};
}

bool in_closed_disk(const Point& s, const Side& f) {
  const Point &a = f.s->point(), &b = f.e->point();
  return s == a || s == b || CGAL::angle(a, s, b) != CGAL::ACUTE;
}

}  // namespace nonobtuse::refine2d
