#include "refine2d_state.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nonobtuse::refine2d {
namespace {

bool same_side(const Side& a, const Side& b) { return a.s == b.s && a.e == b.e; }

// Squared distance from (cx, cy) to the segment [u, w], in doubles (used only to prune walks).
double distance2_to_segment(double cx, double cy, const Point& u, const Point& w) {
  double dx = w.x() - u.x(), dy = w.y() - u.y();
  double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((cx - u.x()) * dx + (cy - u.y()) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  double px = u.x() + t * dx - cx, py = u.y() + t * dy - cy;
  return px * px + py * py;
}

}  // namespace

State::State(const Domain2& d, long long b) : domain(d), n_input(static_cast<int>(d.points.size())), budget(b) {
  cdt::build(cdt, domain);
  for (const Side& side : boundary_sides()) {
    int a = side.s->info(), c = side.e->info();
    edge_index_[{std::min(a, c), std::max(a, c)}] = static_cast<int>(edges.size());
    edges.push_back({{a, c}, 0, 0});
  }
}

Face_handle State::left_face(const Side& side) const {
  Face_handle f;
  int i;
  if (!cdt.is_edge(side.s, side.e, f, i) || !f->is_constrained(i)) return nullptr;
  // Face f lies on the left of f->vertex(ccw(i)) -> f->vertex(cw(i)) (faces are counter-clockwise).
  return f->vertex(CDT::ccw(i)) == side.s ? f : f->neighbor(i);
}

bool State::is_boundary_side(const Side& side) const {
  Face_handle f = left_face(side);
  if (f == nullptr || !f->info().in_domain) return false;
  return !f->neighbor(f->index(apex(side)))->info().in_domain;
}

Vertex_handle State::apex(const Side& side) const {
  Face_handle f = left_face(side);
  for (int i = 0; i < 3; ++i)
    if (f->vertex(i) != side.s && f->vertex(i) != side.e) return f->vertex(i);
  throw InternalError("refine2d: degenerate face");
}

bool State::is_violated(const Side& side) const {
  if (!is_boundary_side(side)) return false;
  Vertex_handle c = apex(side);
  return !cdt.is_infinite(c) && CGAL::angle(side.s->point(), c->point(), side.e->point()) == CGAL::OBTUSE;
}

std::vector<Side> State::boundary_sides() const {
  std::vector<Side> out;
  for (auto e = cdt.constrained_edges_begin(); e != cdt.constrained_edges_end(); ++e) {
    Face_handle f = e->first;
    int i = e->second;
    Side left{f->vertex(CDT::ccw(i)), f->vertex(CDT::cw(i))}, right{left.e, left.s};
    if (is_boundary_side(left)) out.push_back(left);
    if (is_boundary_side(right)) out.push_back(right);
  }
  std::sort(out.begin(), out.end(), [](const Side& a, const Side& b) {
    return std::make_pair(a.s->info(), a.e->info()) < std::make_pair(b.s->info(), b.e->info());
  });
  return out;
}

void State::enqueue_all() {
  for (const Side& side : boundary_sides()) queue.push_back(side);
}

DiskWalk State::walk_diametral_disk(const Side& side) const {
  DiskWalk out;
  const Point &s = side.s->point(), &e = side.e->point();
  double cx = 0.5 * (s.x() + e.x()), cy = 0.5 * (s.y() + e.y());
  double r2 = 0.25 * CGAL::to_double(CGAL::squared_distance(s, e));
  double reach = r2 * (1 + 1e-9) + 1e-300;  // pruning slack: walk a little too far rather than too little
  std::vector<Face_handle> stack{left_face(side)};
  std::unordered_set<Face_handle> seen{stack.back()};
  std::unordered_set<Vertex_handle> found;
  while (!stack.empty()) {
    Face_handle f = stack.back();
    stack.pop_back();
    for (int i = 0; i < 3; ++i) {
      Vertex_handle v = f->vertex(i);
      if (v != side.s && v != side.e && !cdt.is_infinite(v) && !found.count(v) && encroaches(s, e, v->point())) {
        found.insert(v);
        out.encroachers.push_back(v);
      }
      if (f->is_constrained(i)) {
        Side other{f->vertex(CDT::ccw(i)), f->vertex(CDT::cw(i))};
        if (!same_side(other, side) && is_boundary_side(other)) out.nearby.push_back(other);
        continue;
      }
      Face_handle g = f->neighbor(i);
      if (seen.count(g) || cdt.is_infinite(g)) continue;
      const Point &u = f->vertex(CDT::ccw(i))->point(), &w = f->vertex(CDT::cw(i))->point();
      if (distance2_to_segment(cx, cy, u, w) > reach) continue;
      seen.insert(g);
      stack.push_back(g);
    }
  }
  // Deterministic order (the walk order depends on face handles): by vertex index.
  std::sort(out.encroachers.begin(), out.encroachers.end(),
            [](Vertex_handle a, Vertex_handle b) { return a->info() < b->info(); });
  return out;
}

std::vector<Point> candidates_near(const Point& s, const Point& e, double t) {
  double dx = e.x() - s.x(), dy = e.y() - s.y();
  std::vector<Point> out;
  // Dyadic parameters from fine to coarse, below and above t: the first exactly collinear one of each.
  for (bool up : {false, true})
    for (int m = 52; m >= 12; --m) {
      double scale = std::ldexp(1.0, m), tm = (up ? std::ceil(t * scale) : std::floor(t * scale)) / scale;
      Point q(s.x() + tm * dx, s.y() + tm * dy);
      if (tm > 0.0 && tm < 1.0 && CGAL::orientation(s, e, q) == CGAL::COLLINEAR) {
        out.push_back(q);
        break;
      }
    }
  // The doubles within 2 ulps (per coordinate) of the rounded point, and a grid reaching 8 ulps outward from it
  // (steps along and across the line, in units of the larger coordinate ulp).
  double x0 = s.x() + t * dx, y0 = s.y() + t * dy, inf = std::numeric_limits<double>::infinity();
  auto step = [&](double v, int k) {
    for (; k > 0; --k) v = std::nextafter(v, inf);
    for (; k < 0; ++k) v = std::nextafter(v, -inf);
    return v;
  };
  for (int i = -2; i <= 2; ++i)
    for (int j = -2; j <= 2; ++j) out.emplace_back(step(x0, i), step(y0, j));
  double u = std::max(step(std::abs(x0), 1) - std::abs(x0), step(std::abs(y0), 1) - std::abs(y0));
  double len = std::hypot(dx, dy), tx = dx / len, ty = dy / len;  // right normal: (ty, -tx)
  for (int i = -2; i <= 2; ++i)
    for (int j = 1; j <= 8; ++j) out.emplace_back(x0 + u * (i * tx + j * ty), y0 + u * (i * ty - j * tx));
  out.erase(std::remove_if(out.begin(), out.end(),
                           [&](const Point& q) {
                             return q == s || q == e || CGAL::orientation(s, e, q) == CGAL::LEFT_TURN ||
                                    CGAL::angle(s, q, e) != CGAL::OBTUSE;
                           }),
            out.end());
  auto rank = [&](const Point& q) {
    bool off = CGAL::orientation(s, e, q) != CGAL::COLLINEAR;
    return std::make_pair(off, -((q.x() - s.x()) * dx + (q.y() - s.y()) * dy));
  };
  std::stable_sort(out.begin(), out.end(), [&](const Point& a, const Point& b) { return rank(a) < rank(b); });
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

bool State::keeps_triangles_valid(const Side& side, const Point& p) const {
  Face_handle fl = left_face(side);
  if (fl == nullptr) throw InternalError("refine2d: split of an edge that is not a constraint");
  int i = fl->index(apex(side));
  Face_handle fr = fl->neighbor(i);
  // p (possibly off the line by ulps) must keep both triangles next to the edge counter-clockwise once split.
  for (Face_handle f : {fl, fr}) {
    Vertex_handle c = f->vertex(f == fl ? i : fr->index(fl));
    if (cdt.is_infinite(c)) continue;
    auto o = CGAL::orientation(side.s->point(), side.e->point(), c->point());
    if (CGAL::orientation(side.s->point(), p, c->point()) != o || CGAL::orientation(p, side.e->point(), c->point()) != o)
      return false;
  }
  return true;
}

Vertex_handle State::split(const Side& side, const Point& p) {
  if (!keeps_triangles_valid(side, p)) return nullptr;
  Face_handle fl = left_face(side);
  int i = fl->index(apex(side));
  Face_handle fr = fl->neighbor(i);
  cdt::FaceInfo left = fl->info(), right = fr->info();
  Vertex_handle v = cdt.insert(p, CDT::EDGE, fl, i);
  v->info() = n_input + static_cast<int>(placed);
  steiner_edge_.push_back(edge_of(side));
  ++edges[steiner_edge_.back()].steiner_points;
  ++placed;
  // Counter-clockwise around v, from the face on the left of v -> e up to the constraint (v, s): the left side.
  auto fc = cdt.incident_faces(v), done = fc;
  while (fc->vertex(CDT::ccw(fc->index(v))) != side.e) ++fc;
  done = fc;
  bool on_left = true;
  do {
    fc->info() = on_left ? left : right;
    if (fc->vertex(CDT::cw(fc->index(v))) == side.s) on_left = false;
    int j = fc->index(v);
    Side opposite{fc->vertex(CDT::ccw(j)), fc->vertex(CDT::cw(j))};
    if (fc->is_constrained(j)) {
      queue.push_back(opposite);
      queue.push_back({opposite.e, opposite.s});
    }
  } while (++fc != done);
  queue.push_back({side.s, v});
  queue.push_back({v, side.e});
  return v;
}

int State::edge_of(const Side& side) const {
  for (Vertex_handle v : {side.s, side.e})
    if (v->info() >= n_input) return steiner_edge_.at(v->info() - n_input);
  int a = side.s->info(), b = side.e->info();
  auto it = edge_index_.find({std::min(a, b), std::max(a, b)});
  if (it == edge_index_.end()) throw InternalError("refine2d: a boundary subsegment outside the input boundary");
  return it->second;
}

double greedy_parameter(const Point& s, const Point& e, const std::vector<Vertex_handle>& q,
                        Vertex_handle* blocker) {
  double dx = e.x() - s.x(), dy = e.y() - s.y(), best = 1.0;
  for (Vertex_handle v : q) {
    double wx = v->point().x() - s.x(), wy = v->point().y() - s.y();
    double den = wx * dx + wy * dy;  // > |w|^2 > 0 for an encroacher: (q - s).(e - s) = |q - s|^2 - (s - q).(e - q)
    if (den <= 0) continue;
    double t = (wx * wx + wy * wy) / den;
    if (t < best) {
      best = t;
      if (blocker) *blocker = v;
    }
  }
  return best;
}

void keep_encroaching(const Point& s, const Point& e, std::vector<Vertex_handle>& q) {
  q.erase(std::remove_if(q.begin(), q.end(), [&](Vertex_handle v) { return !encroaches(s, e, v->point()); }),
          q.end());
}

bool subsegment_is_empty(const Point& s, const Point& p, const std::vector<Vertex_handle>& q) {
  return std::none_of(q.begin(), q.end(), [&](Vertex_handle v) { return encroaches(s, p, v->point()); });
}

int State::greedy_count(const Side& side, std::vector<Vertex_handle> q) const {
  Point x = side.s->point();
  const Point& e = side.e->point();
  int count = 0;
  // Each step places a point strictly between x and e; the count of the exact greedy is at most |q| (projecting
  // every vertex works), the bound below only guards against rounding making steps degenerate.
  for (std::size_t step = 0; step < 2 * q.size() + 8; ++step) {
    keep_encroaching(x, e, q);
    if (q.empty()) break;
    double t = greedy_parameter(x, e, q);
    Point p;
    auto empty = [&](const Point& c) { return subsegment_is_empty(x, c, q); };
    if (!pick_point_at_or_before(x, e, t, empty, p)) break;
    x = p;
    ++count;
  }
  return count;
}

}  // namespace nonobtuse::refine2d
