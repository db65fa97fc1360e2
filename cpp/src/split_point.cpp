// The split point: rounding a constructed point onto a subsegment (candidates near it, exactly on the line where a
// double point there exists), the exact test that the triangulation can take it, and the split itself.
#include "split_point.h"

#include <cstdint>
#include <deque>
#include <initializer_list>
#include <limits>
#include <unordered_set>

namespace nonobtuse::refine2d {
namespace {

// The two faces beside a constrained edge: left of s -> e (its apex at index i) and right (apex right_apex).
struct Wings {
  Face_handle left, right;
  int i;
  Vertex_handle right_apex;
};

// One edge lookup; InternalError when the side is not a constrained edge.
Wings wings(const State& st, const Side& side) {
  Face_handle fl = st.left_face(side);
  if (fl == nullptr) throw InternalError("refine2d: split of an edge that is not a constraint");
  int i = 0;
  while (fl->vertex(i) == side.s || fl->vertex(i) == side.e) ++i;
  Face_handle fr = fl->neighbor(i);
  return {fl, fr, i, fr->vertex(fr->index(fl))};
}

// Inserting p into the edge keeps both triangles beside it counter-clockwise (p may be ulps off the line, a
// neighbouring apex nearly on it) and CGAL's convex hull convex (p must not bend a hull edge inward). Exact.
bool splits_in_place(const CDT& cdt, const Side& side, const Wings& w, const Point& p) {
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

// The neighbour of `from` along the constraint toward `end` (`end`, or a vertex the constraint passes through).
Vertex_handle next_on_constraint(const CDT& cdt, Vertex_handle from, Vertex_handle end) {
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

// Domain marks of the faces changed by inserting v between to_s and to_e (see split); queues their sides.
void remark_around(CDT& cdt, std::deque<Side>& queue, Vertex_handle v, Vertex_handle to_e, Vertex_handle to_s,
                   const cdt::FaceInfo& left, const cdt::FaceInfo& right) {
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

}  // namespace

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
  // Far from the origin a subsegment may span only a few doubles (coordinates near 1e9, edges of 1e-6: 8 ulps),
  // and the points above, within ulps of the target, lie off the line by a good fraction of its length. Then
  // every double strictly between s and e in one coordinate, with the doubles nearest the line in the other
  // (computed from s, the local origin: v - s is exact there), is a candidate too; those exactly on the line
  // are collinear candidates (exact orientation below), the others are ranked by their distance off the line.
  constexpr double kFewUlps = 64;
  for (bool by_x : {true, false}) {
    const double from = by_x ? s.x() : s.y(), to = by_x ? e.x() : e.y();
    if (from == to) continue;
    const double slope = by_x ? dy / dx : dx / dy, lo = std::min(from, to), hi = std::max(from, to);
    const double m = std::max(std::abs(lo), std::abs(hi));
    if (!(hi - lo <= kFewUlps * (step(m, 1) - m))) continue;  // many doubles along: the points above suffice
    for (double v = step(lo, 1); v < hi; v = step(v, 1)) {
      const double w_at = (by_x ? s.y() : s.x()) + (v - from) * slope;
      for (int j = -1; j <= 1; ++j) out.push_back(by_x ? Point(v, step(w_at, j)) : Point(step(w_at, j), v));
    }
  }
  out.erase(std::remove_if(out.begin(), out.end(),
                           [&](const Point& q) {
                             // A coordinate over a subnormal slope can overflow: no infinities into predicates.
                             return !std::isfinite(q.x()) || !std::isfinite(q.y()) || q == s || q == e ||
                                    !obtuse(s, q, e);
                           }),
            out.end());
  // Collinear first, then outside (right of s -> e), then inside by ulps; each by distance from the target along
  // the line (nearest first; ties: the one nearer s). Last, the points off the line by more than 2^-8 of the
  // subsegment's length (only where it spans few doubles), nearest the line first, then nearest the target.
  // Each rank computed once (the orientation is exact); ties keep the order above.
  const double length2 = dx * dx + dy * dy, target = t * length2;
  RankedCandidates ranked;
  ranked.rank.reserve(out.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    const Point& q = out[k];
    auto o = CGAL::orientation(s, e, q);
    double along = (q.x() - s.x()) * dx + (q.y() - s.y()) * dy;
    double across = std::abs((q.x() - s.x()) * dy - (q.y() - s.y()) * dx);  // |e - s| times the distance off
    if (o != CGAL::COLLINEAR && across > 0x1p-8 * length2)
      ranked.rank.emplace_back(3, across, std::abs(along - target), k);
    else
      ranked.rank.emplace_back(o == CGAL::COLLINEAR ? 0 : o == CGAL::RIGHT_TURN ? 1 : 2, std::abs(along - target),
                               along, k);
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

bool splittable(const State& st, const Side& side, const Point& p) {
  const Wings w = wings(st, side);
  if (splits_in_place(st.cdt(), side, w, p)) return true;
  const Point &s = side.s->point(), &e = side.e->point();
  const Vertex_handle cl = w.left->vertex(w.i), cr = w.right_apex;
  const auto o = CGAL::orientation(s, e, p);  // not COLLINEAR: a point on the line splits in place
  // The apex on p's side; the infinite vertex (p outside the hull) means the polyline meets nothing there.
  const auto side_of_cl = st.cdt().is_infinite(cl) ? -CGAL::orientation(s, e, cr->point()) : CGAL::orientation(s, e, cl->point());
  const Vertex_handle c = side_of_cl == o ? cl : cr;
  if (st.cdt().is_infinite(c)) return true;
  return CGAL::orientation(e, c->point(), p) == o && CGAL::orientation(c->point(), s, p) == o;
}

Vertex_handle split(State& st, const Side& side, const Point& p) {
  CDT& cdt = st.cdt_;
  ++st.splits_;
  const Wings w = wings(st, side);
  const cdt::FaceInfo left = w.left->info(), right = w.right->info();
  const int edge = st.edge_of(side);
  Vertex_handle v;
  if (splits_in_place(cdt, side, w, p)) {
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
  v->info() = st.n_input_ + static_cast<int>(st.added_.size());
  st.added_.push_back(v);
  st.steiner_edge_.push_back(edge);
  ++st.edges_[edge].steiner_points;
  ++st.placed_;
  // Subsegments between two input vertices on the new polyline (a constraint through a vertex) belong to edge.
  for (Vertex_handle end : {side.s, side.e})
    for (Vertex_handle a = v, b; a != end; a = b) {
      b = next_on_constraint(cdt, a, end);
      if (a->info() < st.n_input_ && b->info() < st.n_input_)
        st.edge_index_[State::edge_key(a->info(), b->info())] = edge;
    }
  remark_around(cdt, st.queue_, v, next_on_constraint(cdt, v, side.e), next_on_constraint(cdt, v, side.s), left, right);
  if (st.check_every_split_) st.check_invariants();
  return v;
}

Vertex_handle split_at_foot(State& st, const Side& side, const Point& q) {
  Point p;
  const Point &s = side.s->point(), &e = side.e->point();
  if (!pick_point(s, e, foot_parameter(s, e, q), [&](const Point& c) { return splittable(st, side, c); }, p)) return nullptr;
  return split(st, side, p);
}

}  // namespace nonobtuse::refine2d
