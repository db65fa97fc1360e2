#include "refine2d_state.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <initializer_list>
#include <tuple>

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

// A face with the edge (a, b) and the index of the edge in it, circulating around a and b in lockstep: O(the
// smaller degree). CGAL's is_edge circulates around a only, which at a junction of k constraints (shells put
// many points around it) made every lookup there O(k).
bool find_edge(const CDT& cdt, Vertex_handle a, Vertex_handle b, Face_handle& f, int& i) {
  if (cdt.dimension() < 2) return cdt.is_edge(a, b, f, i);
  auto ca = cdt.incident_faces(a), cb = cdt.incident_faces(b);
  const auto end_a = ca, end_b = cb;
  bool more_a = true, more_b = true;
  int ia, ib;
  while (more_a || more_b) {
    if (more_a) {
      if (ca->has_vertex(b, ib)) {
        f = ca;
        i = 3 - ca->index(a) - ib;
        return true;
      }
      more_a = ++ca != end_a;
    }
    if (more_b) {
      if (cb->has_vertex(a, ia)) {
        f = cb;
        i = 3 - ia - cb->index(b);
        return true;
      }
      more_b = ++cb != end_b;
    }
  }
  return false;
}

}  // namespace

State::State(const Domain2& d, long long b) : domain(d), n_input(static_cast<int>(d.points.size())), budget(b) {
  cdt::build(cdt, domain);
  if (std::none_of(cdt.finite_faces_begin(), cdt.finite_faces_end(), [](const auto& f) { return f.info().in_domain(); }))
    throw InvalidInput("the domain contains no triangle (are all points collinear, or is everything a hole?)");
  const std::vector<Side> sides = boundary_sides();
  for (const Side& side : sides) {
    int a = side.s->info(), c = side.e->info();
    if (edge_index_.emplace(edge_key(a, c), static_cast<int>(edges.size())).second)
      edges.push_back({{a, c}, 0, 0});  // an interface appears once, as (min, max)
  }
  convex_polygon = is_convex_polygon(sides);
}

bool State::is_convex_polygon(const std::vector<Side>& sides) const {
  // A polygon has as many boundary sides as vertices; inner points or constraints break the count (a cheap test
  // first: the constrained-edge scan below visits every edge of the triangulation).
  if (sides.size() != cdt.number_of_vertices()) return false;
  for (const Side& side : sides) {
    Face_handle f = left_face(side);
    if (!cdt.is_infinite(f->neighbor(f->index(apex(side))))) return false;
  }
  for (auto e = cdt.constrained_edges_begin(); e != cdt.constrained_edges_end(); ++e)
    if (e->first->info().in_domain() && e->first->neighbor(e->second)->info().in_domain()) return false;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (!cdt.are_there_incident_constraints(v)) return false;
  return true;
}

Face_handle State::left_face(const Side& side) const {
  Face_handle f;
  int i;
  if (!find_edge(cdt, side.s, side.e, f, i) || !f->is_constrained(i)) return nullptr;
  // Face f lies on the left of f->vertex(ccw(i)) -> f->vertex(cw(i)) (faces are counter-clockwise).
  return f->vertex(CDT::ccw(i)) == side.s ? f : f->neighbor(i);
}

bool State::is_boundary_side(const Side& side) const {
  Face_handle f = left_face(side);
  return f != nullptr && f->info().in_domain();
}

std::vector<Face_handle> State::domain_faces(const Side& side) const {
  std::vector<Face_handle> out;
  for (const Side& sd : {side, Side{side.e, side.s}})
    if (is_boundary_side(sd)) out.push_back(left_face(sd));
  return out;
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
  if (sides_of_ == splits_) return sides_;
  // A boundary side is a constrained edge of a domain face, oriented with the face on its left.
  // Sorted by the key (s index, e index), computed once per side rather than through the vertex handles at every
  // comparison.
  std::vector<std::pair<std::uint64_t, Side>> keyed;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    for (int i = 0; i < 3; ++i)
      if (f->is_constrained(i) && f->info().in_domain()) {
        Vertex_handle s = f->vertex(CDT::ccw(i)), e = f->vertex(CDT::cw(i));
        keyed.push_back({static_cast<std::uint64_t>(s->info()) << 32 | static_cast<std::uint32_t>(e->info()), {s, e}});
      }
  std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  sides_.clear();
  for (const auto& [key, side] : keyed) sides_.push_back(side);
  sides_of_ = splits_;
  return sides_;
}

void State::enqueue_all() {
  for (const Side& side : boundary_sides()) queue.push_back(side);
}

template <class Crosses, class Visit>
void State::walk(const std::vector<Face_handle>& start, Crosses&& crosses, Visit&& visit, int lane) const {
  const unsigned walk = new_walk(lane);
  std::vector<Face_handle> stack(start);
  for (Face_handle f : start) f->info().visit[lane] = walk;
  while (!stack.empty()) {
    Face_handle f = stack.back();
    stack.pop_back();
    if (visit(f)) return;
    for (int i = 0; i < 3; ++i) {
      if (f->is_constrained(i)) continue;
      Face_handle g = f->neighbor(i);
      if (g->info().visit[lane] == walk || cdt.is_infinite(g)) continue;
      if (!crosses(f->vertex(CDT::ccw(i))->point(), f->vertex(CDT::cw(i))->point())) continue;
      g->info().visit[lane] = walk;
      stack.push_back(g);
    }
  }
}

template <class Visit>
void State::walk_disk(const std::vector<Face_handle>& start, const Point& a, const Point& b, Visit&& visit,
                      int lane) const {
  double cx = 0.5 * (a.x() + b.x()), cy = 0.5 * (a.y() + b.y());
  double r2 = 0.25 * CGAL::to_double(CGAL::squared_distance(a, b));
  double reach = r2 * (1 + 1e-9) + 1e-300;  // pruning slack: walk a little too far rather than too little
  // The union of (face ∩ disk) along the walk stays connected: consecutive faces share a piece of the crossed
  // edge inside the disk.
  walk(
      start, [&](const Point& u, const Point& w) { return distance2_to_segment(cx, cy, u, w) <= reach; }, visit, lane);
}

DiskWalk State::walk_diametral_disk(const Side& side, int lane) const {
  DiskWalk out;
  const Point &s = side.s->point(), &e = side.e->point();
  const bool left = is_boundary_side(side), right = is_boundary_side({side.e, side.s});
  auto on_domain_side = [&](const Point& q) { return (left && encroaches(s, e, q)) || (right && encroaches(e, s, q)); };
  std::vector<Vertex_handle> reached;  // the vertices of the faces reached (walks skip infinite faces), once each
  const unsigned stamp = ++vertex_lists_[lane];
  std::vector<unsigned>& listed = vertex_walk_[lane];
  walk_disk(domain_faces(side), s, e, [&](Face_handle f) {
    for (int i = 0; i < 3; ++i) {
      const auto index = static_cast<std::size_t>(f->vertex(i)->info());
      if (index >= listed.size()) listed.resize(index + 1, 0);
      if (listed[index] != stamp) {
        listed[index] = stamp;
        reached.push_back(f->vertex(i));
      }
      Vertex_handle u = f->vertex(CDT::ccw(i)), w = f->vertex(CDT::cw(i));
      if (f->is_constrained(i) && !((u == side.s && w == side.e) || (u == side.e && w == side.s)))
        out.obstacles.emplace_back(u->point(), w->point());
    }
    return false;
  }, lane);
  for (Vertex_handle v : reached)
    if (v != side.s && v != side.e && on_domain_side(v->point())) out.encroachers.push_back(v);
  // Deterministic order (the walk order depends on face handles): by vertex index.
  std::sort(out.encroachers.begin(), out.encroachers.end(),
            [](Vertex_handle a, Vertex_handle b) { return a->info() < b->info(); });
  return out;
}

std::vector<Side> State::sides_broken_by(const Side& side, const Point& p) const {
  std::vector<Side> out;
  const Side reverse{side.e, side.s};
  std::vector<Face_handle> stack = domain_faces(side);
  const unsigned walk = new_walk(0);
  for (Face_handle f : stack) f->info().visit[0] = walk;
  while (!stack.empty()) {
    Face_handle f = stack.back();
    stack.pop_back();
    for (int i = 0; i < 3; ++i) {
      Side edge{f->vertex(CDT::ccw(i)), f->vertex(CDT::cw(i))};  // f is on its left
      if (f->is_constrained(i)) {
        if (!same_side(edge, side) && !same_side(edge, reverse) && is_boundary_side(edge) &&
            encroaches(edge.s->point(), edge.e->point(), p))
          out.push_back(edge);
        continue;
      }
      Face_handle g = f->neighbor(i);
      if (g->info().visit[0] == walk || cdt.is_infinite(g)) continue;
      g->info().visit[0] = walk;
      if (CGAL::side_of_bounded_circle(g->vertex(0)->point(), g->vertex(1)->point(), g->vertex(2)->point(), p) ==
          CGAL::ON_BOUNDED_SIDE)
        stack.push_back(g);
    }
  }
  return out;
}

bool State::sees(const Side& start, const Point& a, const Point& b, Vertex_handle v, Sight sight) const {
  if (sight.obstacles != nullptr) return !covered_from(v->point(), a, b, *sight.obstacles);
  bool found = false;
  walk_disk(domain_faces(start), a, b, [&](Face_handle f) { return found = f->has_vertex(v); });
  return found;
}

double State::greedy_parameter(const Side& start, const Point& s, const Point& e, const std::vector<Vertex_handle>& q,
                               Sight sight, Vertex_handle* blocker) const {
  double dx = e.x() - s.x(), dy = e.y() - s.y();
  std::vector<std::pair<double, Vertex_handle>> order;
  for (Vertex_handle v : q) {
    double wx = v->point().x() - s.x(), wy = v->point().y() - s.y();
    double den = wx * dx + wy * dy;  // > |w|^2 > 0 for an encroacher: (q - s).(e - s) = |q - s|^2 - (s - q).(e - q)
    if (den > 0) order.emplace_back((wx * wx + wy * wy) / den, v);
  }
  std::sort(order.begin(), order.end(),
            [](const auto& a, const auto& b) { return std::make_pair(a.first, a.second->info()) <
                                                      std::make_pair(b.first, b.second->info()); });
  // q blocks at the first t >= t_q where [s, s + t d] sees it (paper 4.4: only visible vertices encroach).
  // Subsegments and their disks grow with t, so seeing (either sight) is monotone in t: bisect when q is hidden at
  // t_q (behind a reflex spike, it may come into view later).
  auto seen = [&](double t, Vertex_handle v) { return sees(start, s, Point(s.x() + t * dx, s.y() + t * dy), v, sight); };
  double best = 1.0;
  for (const auto& [tq, v] : order) {
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

RankedCandidates ranked_candidates(const Point& s, const Point& e, double t) {
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
  // Points snapped to the line: for each double x within 2 ulps of the rounded point, the doubles within 2 ulps
  // of the line's y there (and symmetrically with x and y swapped): off the line by at most a few ulps of the
  // finer coordinate, which matters when a neighbouring apex lies nearly on the line (a sliver outside).
  double x0 = s.x() + t * dx, y0 = s.y() + t * dy, inf = std::numeric_limits<double>::infinity();
  auto step = [&](double v, int k) {
    for (; k > 0; --k) v = std::nextafter(v, inf);
    for (; k < 0; ++k) v = std::nextafter(v, -inf);
    return v;
  };
  for (int i = -2; i <= 2; ++i) {
    double x = step(x0, i), y = step(y0, i);
    double y_at = dx != 0 ? s.y() + (x - s.x()) * (dy / dx) : y0;
    double x_at = dy != 0 ? s.x() + (y - s.y()) * (dx / dy) : x0;
    for (int j = -2; j <= 2; ++j) {
      out.emplace_back(x, step(y_at, j));
      out.emplace_back(step(x_at, j), y);
    }
  }
  // A grid reaching 8 ulps (of the larger coordinate) outward from the rounded point.
  double u = std::max(step(std::abs(x0), 1) - std::abs(x0), step(std::abs(y0), 1) - std::abs(y0));
  double len = std::hypot(dx, dy), tx = dx / len, ty = dy / len;  // right normal: (ty, -tx)
  for (int i = -2; i <= 2; ++i)
    for (int j = 1; j <= 8; ++j) out.emplace_back(x0 + u * (i * tx + j * ty), y0 + u * (i * ty - j * tx));
  out.erase(std::remove_if(out.begin(), out.end(),
                           [&](const Point& q) {
                             // A coordinate over a subnormal slope can overflow: no infinities into predicates.
                             return !std::isfinite(q.x()) || !std::isfinite(q.y()) || q == s || q == e ||
                                    !obtuse(s, q, e);
                           }),
            out.end());
  // Collinear first, then outside (right of s -> e), then inside by ulps; each by distance from the target along
  // the line (nearest first; ties: the one nearer s).
  // Each rank computed once (the orientation is exact); ties keep the order above.
  const double target = t * (dx * dx + dy * dy);
  RankedCandidates ranked;
  ranked.rank.reserve(out.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    const Point& q = out[k];
    auto o = CGAL::orientation(s, e, q);
    int group = o == CGAL::COLLINEAR ? 0 : o == CGAL::RIGHT_TURN ? 1 : 2;
    double along = (q.x() - s.x()) * dx + (q.y() - s.y()) * dy;
    ranked.rank.emplace_back(group, std::abs(along - target), along, k);
  }
  ranked.points = std::move(out);
  return ranked;
}

std::vector<Point> candidates_near(const Point& s, const Point& e, double t) {
  RankedCandidates c = ranked_candidates(s, e, t);
  std::sort(c.rank.begin(), c.rank.end());
  std::vector<Point> sorted;
  sorted.reserve(c.points.size());
  for (const auto& r : c.rank) sorted.push_back(c.points[std::get<3>(r)]);
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  return sorted;
}

State::Wings State::wings(const Side& side) const {
  Face_handle fl = left_face(side);
  if (fl == nullptr) throw InternalError("refine2d: split of an edge that is not a constraint");
  int i = 0;
  while (fl->vertex(i) == side.s || fl->vertex(i) == side.e) ++i;
  Face_handle fr = fl->neighbor(i);
  return {fl, fr, i, fr->vertex(fr->index(fl))};
}

bool State::splits_in_place(const Side& side, const Wings& w, const Point& p) const {
  const Point &s = side.s->point(), &e = side.e->point();
  for (Vertex_handle c : {w.left->vertex(w.i), w.right_apex}) {
    if (cdt.is_infinite(c)) continue;
    auto o = CGAL::orientation(s, e, c->point());
    if (CGAL::orientation(s, p, c->point()) != o || CGAL::orientation(p, e, c->point()) != o) return false;
  }
  if (!cdt.is_infinite(w.right)) return true;
  // An edge of CGAL's convex hull, which must stay convex: r, s, p, e, n (the hull counter-clockwise, r before s
  // and n after e) must never turn right.
  Face_handle before = w.right->neighbor(w.right->index(side.e)), after = w.right->neighbor(w.right->index(side.s));
  const Point &r = before->vertex(before->index(w.right))->point(), &n = after->vertex(after->index(w.right))->point();
  return CGAL::orientation(r, s, p) != CGAL::RIGHT_TURN && CGAL::orientation(s, p, e) != CGAL::RIGHT_TURN &&
         CGAL::orientation(p, e, n) != CGAL::RIGHT_TURN;
}

bool State::splittable(const Side& side, const Point& p) const {
  const Wings w = wings(side);
  if (splits_in_place(side, w, p)) return true;
  const Point &s = side.s->point(), &e = side.e->point();
  const Vertex_handle cl = w.left->vertex(w.i), cr = w.right_apex;
  const auto o = CGAL::orientation(s, e, p);  // not COLLINEAR: a point on the line splits in place
  // The apex on p's side; the infinite vertex (p outside the hull) means the polyline meets nothing there.
  const auto side_of_cl = cdt.is_infinite(cl) ? -CGAL::orientation(s, e, cr->point()) : CGAL::orientation(s, e, cl->point());
  const Vertex_handle c = side_of_cl == o ? cl : cr;
  if (cdt.is_infinite(c)) return true;
  return CGAL::orientation(e, c->point(), p) == o && CGAL::orientation(c->point(), s, p) == o;
}

Vertex_handle State::split(const Side& side, const Point& p) {
  ++splits_;
  const Wings w = wings(side);
  const cdt::FaceInfo left = w.left->info(), right = w.right->info();
  const int edge = edge_of(side);
  Vertex_handle v;
  if (splits_in_place(side, w, p)) {
    v = cdt.insert(p, CDT::EDGE, w.left, w.i);  // splits the constraint and both triangles, then flips
    // CGAL flips the edges opposite v, which restores the constrained Delaunay property when p lies on the edge.
    // A p some ulps off the line can leave an edge at v itself not locally Delaunay (seen outside the domain, at
    // v's apex across a pocket): flip from every edge at v as well.
    if (CGAL::orientation(side.s->point(), side.e->point(), p) != CGAL::COLLINEAR) {
      CDT::List_edges at_v;
      auto ec = cdt.incident_edges(v), done = ec;
      do at_v.push_back(*ec); while (++ec != done);
      cdt.propagating_flip(at_v);
    }
  } else {
    // p is off the line and a neighbouring apex lies nearly on it (a sliver), or p bends a convex hull edge
    // inward: splitting in place would invert a triangle or the hull. Replace the constraint (s, e) by the
    // polyline s-p-e instead; CGAL inserts p (inside or outside the hull) and retriangulates exactly.
    std::size_t before = cdt.number_of_vertices();
    cdt.remove_constrained_edge(w.left, w.i);
    v = cdt.insert(p, side.s->face());
    if (cdt.number_of_vertices() == before) {  // p coincides with a vertex: give up on this point
      cdt.insert_constraint(side.s, side.e);
      return nullptr;
    }
    try {
      cdt.insert_constraint(side.s, v);
      cdt.insert_constraint(v, side.e);
    } catch (const CDT::Intersection_of_constraints_exception&) {
      throw InternalError("refine2d: the refined boundary s-p-e crosses a constraint");
    }
  }
  v->info() = n_input + static_cast<int>(placed);
  steiner_edge_.push_back(edge);
  ++edges[edge].steiner_points;
  ++placed;
  // Subsegments between two input vertices on the new polyline (a constraint through a vertex) belong to edge.
  for (Vertex_handle end : {side.s, side.e})
    for (Vertex_handle a = v, b; a != end; a = b) {
      b = next_on_constraint(a, end);
      if (a->info() < n_input && b->info() < n_input)
        edge_index_[edge_key(a->info(), b->info())] = edge;
    }
  remark_around(v, next_on_constraint(v, side.e), next_on_constraint(v, side.s), left, right);
  if (check_every_split) check_invariants();
  return v;
}

void State::check_invariants() {
  if (!cdt.is_valid()) throw InternalError("refine2d: the triangulation is invalid after a split");
  // (in domain, region attribute) of every face; components may be numbered differently by a new marking.
  auto marks = [this] {
    std::vector<std::pair<bool, double>> out;
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
      out.emplace_back(f->info().in_domain(), f->info().in_domain() ? cdt.region(f) : 0.0);
    return out;
  };
  const auto kept = marks();
  cdt::mark_domain(cdt, domain);  // the marks from scratch; equal to the maintained ones when remark_around is right
  if (marks() != kept)
    throw InternalError("refine2d: domain marks maintained by split differ from mark_domain");
}

Vertex_handle State::next_on_constraint(Vertex_handle from, Vertex_handle end) const {
  auto ec = cdt.incident_edges(from), stop = ec;
  do {
    Vertex_handle a = ec->first->vertex(CDT::ccw(ec->second)), b = ec->first->vertex(CDT::cw(ec->second));
    Vertex_handle w = a == from ? b : a;
    if (cdt.is_constrained(*ec) &&
        (w == end || (CGAL::orientation(from->point(), end->point(), w->point()) == CGAL::COLLINEAR &&
                      CGAL::collinear_are_ordered_along_line(from->point(), w->point(), end->point()))))
      return w;
  } while (++ec != stop);
  throw InternalError("refine2d: a split vertex is not on its subsegment");
}

void State::remark_around(Vertex_handle v, Vertex_handle to_e, Vertex_handle to_s, const cdt::FaceInfo& left,
                          const cdt::FaceInfo& right) {
  // Around v, counter-clockwise from the face on the left of v -> to_e up to the constraint (v, to_s): the left
  // side's marks; the rest: the right side's. Faces changed away from v (only on the polyline path) are reached
  // from there across unconstrained edges: marks spread while they differ. Sides of every face touched are
  // queued: their triangles may have a new apex.
  std::vector<std::pair<Face_handle, const cdt::FaceInfo*>> stack;
  auto fc = cdt.incident_faces(v), done = fc;
  while (fc->vertex(CDT::ccw(fc->index(v))) != to_e) ++fc;  // terminates: (v, to_e) is an edge
  done = fc;
  bool on_left = true;
  do {
    stack.emplace_back(fc, on_left ? &left : &right);
    if (fc->vertex(CDT::cw(fc->index(v))) == to_s) on_left = false;
  } while (++fc != done);
  std::unordered_set<Face_handle> set;
  while (!stack.empty()) {
    auto [f, info] = stack.back();
    stack.pop_back();
    if (!set.insert(f).second) continue;
    f->info() = *info;
    for (int j = 0; j < 3; ++j) {
      if (f->is_constrained(j)) {
        queue.push_back({f->vertex(CDT::ccw(j)), f->vertex(CDT::cw(j))});
        queue.push_back({f->vertex(CDT::cw(j)), f->vertex(CDT::ccw(j))});
        continue;
      }
      Face_handle g = f->neighbor(j);
      if (!set.count(g) && g->info().component != info->component)
        stack.emplace_back(g, info);
    }
  }
}

int State::edge_of(const Side& side) const {
  for (Vertex_handle v : {side.s, side.e})
    if (v->info() >= n_input) return steiner_edge_.at(v->info() - n_input);
  int a = side.s->info(), b = side.e->info();
  auto it = edge_index_.find(edge_key(a, b));
  if (it == edge_index_.end()) throw InternalError("refine2d: a boundary subsegment outside the input boundary");
  return it->second;
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
  auto before = [&v](const Point& p, const Point& q) { return CGAL::orientation(v, p, q) == CGAL::LEFT_TURN; };
  const K::Triangle_2 tri(v, a, b);
  std::vector<Segment2> shades;
  const auto v_side = CGAL::orientation(a, b, v);
  auto in_front = [&](const Point& c1, const Point& c2) {
    if (c1 == a || c1 == b) return CGAL::orientation(a, b, c2) == v_side;
    if (c2 == a || c2 == b) return CGAL::orientation(a, b, c1) == v_side;
    // Both ends strictly beyond one side's line: it misses the triangle (a cheap exact test first).
    for (const auto& [p, q, r] : {std::tie(v, a, b), std::tie(a, b, v), std::tie(b, v, a)}) {
      const auto inside = CGAL::orientation(p, q, r);
      if (CGAL::orientation(p, q, c1) == -inside && CGAL::orientation(p, q, c2) == -inside) return false;
    }
    return CGAL::do_intersect(K::Segment_2(c1, c2), tri);
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

void keep_encroaching(const Point& s, const Point& e, std::vector<Vertex_handle>& q) {
  q.erase(std::remove_if(q.begin(), q.end(), [&](Vertex_handle v) { return !inside_diametral_disk(s, e, v->point()); }),
          q.end());
}

bool State::subsegment_is_empty(const Side& start, const Point& s, const Point& p, const std::vector<Vertex_handle>& q,
                                Sight sight) const {
  std::vector<Vertex_handle> inside;
  for (Vertex_handle v : q)
    if (inside_diametral_disk(s, p, v->point())) inside.push_back(v);
  if (inside.empty()) return true;
  if (sight.obstacles != nullptr)
    return std::none_of(inside.begin(), inside.end(), [&](Vertex_handle v) { return sees(start, s, p, v, sight); });
  // Reach: one walk for all of them (v is reachable iff some face of the whole walk has it).
  std::sort(inside.begin(), inside.end());
  bool seen = false;
  walk_disk(domain_faces(start), s, p, [&](Face_handle f) {
    for (int i = 0; i < 3; ++i) seen = seen || std::binary_search(inside.begin(), inside.end(), f->vertex(i));
    return seen;
  });
  return !seen;
}

int State::greedy_count(const Side& side, const DiskWalk& walk) const {
  std::vector<Vertex_handle> q = walk.encroachers;
  const Sight sight{&walk.obstacles};
  Point x = side.s->point();
  const Point& e = side.e->point();
  int count = 0;
  // Each step places a point strictly between x and e; the count of the exact greedy is at most |q| (projecting
  // every vertex works), the bound below only guards against rounding making steps degenerate.
  for (std::size_t step = 0; step < 2 * q.size() + 8; ++step) {
    keep_encroaching(x, e, q);
    if (q.empty()) break;
    double t = greedy_parameter(side, x, e, q, sight);
    if (t >= 1) break;
    Point p;
    auto empty = [&](const Point& c) { return subsegment_is_empty(side, x, c, q, sight); };
    if (!pick_point_at_or_before(x, e, t, empty, p)) break;
    x = p;
    ++count;
  }
  return count;
}

}  // namespace nonobtuse::refine2d
