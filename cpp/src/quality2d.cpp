// Interior quality refinement: Ruppert's and Chew's Delaunay refinement with Triangle's off-centers, after the
// boundary refinement, keeping every constraint subsegment's open diametral disk empty.
//
// A bad triangle (smallest angle below the bound, or area above the limit at its place) gets a new vertex c: its
// circumcenter, or the off-center of its shortest edge pq (Triangle, after Ungor: the point on pq's bisector at
// height 0.475 cot(bound / 2) |pq|, whose triangle with pq has an angle just above the bound) when that is nearer
// to pq. c goes in only if it lies in no open diametral disk of a constraint subsegment bounding its Delaunay
// cavity (exact: CGAL::angle(s, c, e) == OBTUSE; a c on the circle makes a right apex, which the certificate
// allows, as Triangle -D's encroachment test does: measured on bench_quality2d, the closed disk split face.poly's
// subsegments for circumcenters on their circles, 46 boundary points against Triangle's 42, 42 with the open one)
// and, when a constraint is crossed on the way from the triangle to c, not in that constraint's closed diametral
// disk (the triangle's circumdisk holds no vertex it sees, so a c behind a subsegment lies in that subsegment's
// diametral disk, Ruppert's lemma; c goes in nowhere then). Otherwise the subsegment is
// split at its midpoint (or a concentric shell at an acute input angle), and so is every boundary side the split
// leaves obtuse (Ruppert's encroachment splits; the greedy rule takes a side no such point fixes). Midpoints keep
// the boundary spacing even: greedy repairs, optimal for the boundary alone, left short subsegments that the
// interior refinement then had to match (measured: 1.8x Triangle's vertices on p2t_dude instead of 1.7x, 2.5x
// instead of 1.8x on the demo cross-section).
//
// The boundary comes first, as in Triangle: run() starts by splitting every boundary side with an obtuse apex
// (a no-op when a strategy already made the boundary nonobtuse; quality2d_boundary.cpp says how, and what was
// measured). Each new interior vertex is outside the open diametral disk of every constrained edge of its
// cavity, so every triangle it makes on a subsegment has an acute or right apex: interior points never make a
// boundary side obtuse, and the certificate of refine2d.cpp still holds.
//
// Before a skinny triangle's encroachment splits a subsegment, one more point is tried: the point of its selection
// disk (Chernikov and Chrisochoides 2006: centered at the circumcenter, radius R - l / (2 sin bound)) farthest
// from the encroached subsegments; it goes in when it encroaches nothing it sees. Measured on bench_quality2d at
// 25 and 30 degrees: boundary Steiner points 1276 -> 1274 on the demo at 25, 53 -> 49 on face and clusters,
// 361 -> 352 on la, 21 -> 18 on p2t_bird, 42 -> 39 on p2t_dude, 34 -> 31 on p2t_tank (fewer than Triangle's on
// 5 of 18 instead of 4), A 49 -> 51; vertices median 1.00x, max 1.67x Triangle's.
//
// Termination (Ruppert 1995, Shewchuk 1997/2002): with input angles of at least 60 degrees and a bound of at
// most 20.7 degrees (arcsin(1 / (2 sqrt 2))), each new vertex is at least as far from every other vertex as a
// constant times the local feature size, so finitely many fit. A selection-disk point keeps that argument (the
// disk is chosen so that the new vertex is at least the bound's constant times l from every vertex: Chernikov and
// Chrisochoides' Generalized Delaunay refinement; its floating point rounding is the only gap, and the budgets
// stop the run). Off-centers keep that argument and in practice
// terminate up to about 33 degrees (Ungor; Triangle). The boundary splits are midpoints and shells, as in the proof
// (the first pass splits sides whose open diametral disk holds their apex: Ruppert's encroachment by a vertex);
// only the greedy repair (of a side no midpoint or shell fixes, or one at a small corner of two boundary edges in
// the first pass, where the proof's premise fails anyway) adds points the proof does not cover; at a junction with
// an interface or dangling segment the shells are Shewchuk's (a split at the junction lands at a power of two of
// at least a third of the subsegment, so two constraints there are split at the same radii and never encroach
// each other, concentric_shells.cpp), and the
// strategies other than greedy leave their own boundary points before: the budgets are the hard stop.
//
// Small input angles (two input constraints meeting at less than 60 degrees, the domain inside the angle) defeat
// every such bound: a triangle in the wedge is skinny whatever is inserted. The corner of a hole or of the exterior
// is none: no domain triangle lies in it and no vertex of one of its edges sees the other edge's subsegments
// through the domain, so the two edges never encroach each other (the case the 60 degree premise of the proof
// excludes); its sides get midpoints like any other (measured on bench_quality2d: A.poly 51 -> 41 boundary
// points, Triangle 42; face 49 -> 46, p2t_dude 39 -> 38). As Triangle does, such triangles are left alone: (1) a
// skinny triangle whose shortest edge joins two different input constraints that meet at an angle below 60
// degrees is not refined (Triangle skips it when the two ends are equidistant from the apex; here any such edge,
// since the greedy points are not on shells), and (2) a subsegment split asked for by a skinny triangle is
// refused when the subsegment lies on an input edge with a small angle at one of its ends and half its length
// would be shorter than the triangle's shortest edge (Shewchuk's terminator: the split would only make a new,
// smaller skinny triangle). Both are counted as small_angle_triangles; the achieved minimum angle is reported
// over the other triangles.
//
// Once nothing is left to refine, the boundary Steiner points no longer needed are taken back (quality2d_prune.cpp:
// a point goes when its subsegment joined again keeps a nonobtuse apex and the faces around it stay good; measured
// on bench_quality2d, 2026-12-03: 1270 -> 1228 boundary points on the demo section at 25 degrees, 42 -> 38 on
// face, 5 -> 4 on spiral at 30, where Triangle -pq25D / -pq30D has 1270, 42 and 5).
//
// The angle and area criteria are floating point (they decide what to refine, never what is certified).
#include "quality2d.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <utility>
#include <vector>

#include "quality2d_boundary.h"
#include "quality2d_prune.h"

namespace nonobtuse {

long long default_interior_budget(std::size_t n_points, double domain_area, double smallest_area_limit) {
  double extra = smallest_area_limit > 0.0 && std::isfinite(smallest_area_limit) ? 4.0 * domain_area / smallest_area_limit : 0.0;
  extra = std::min(extra, 0x1p40);  // beyond any mesh that fits in memory
  return 10 * static_cast<long long>(n_points) + 100000 + static_cast<long long>(extra);
}

namespace refine2d {

Vertex_handle insert_interior(State& st, const Point& p, Face_handle located) {
  CDT& cdt = st.cdt_;
  CDT::Locate_type lt;
  int li;
  Face_handle f = cdt.locate(p, lt, li, located);
  if (!(lt == CDT::FACE || (lt == CDT::EDGE && !f->is_constrained(li))) || !f->info().in_domain()) return nullptr;
  const cdt::FaceInfo marks{f->info().component, {0, 0}};
  ++st.splits_;  // the triangulation changes (State::boundary_sides recomputes)
  Vertex_handle v = cdt.insert(p, lt, f, li);
  v->info() = st.n_input_ + static_cast<int>(st.added_.size());
  st.added_.push_back(v);
  st.steiner_edge_.push_back(-1);
  // CGAL's insertion and its flips only make faces incident to v, all inside p's cavity, which no constraint
  // crosses: they are in f's component.
  auto fc = cdt.incident_faces(v), done = fc;
  do fc->info() = marks;
  while (++fc != done);
  if (st.check_every_split_) st.check_invariants();
  return v;
}

namespace {

constexpr double kPi = 3.14159265358979323846;

double squared(const Point& a, const Point& b) { return CGAL::to_double(CGAL::squared_distance(a, b)); }

// A domain triangle's shape: its shortest edge (p -> q, the third vertex r on its left), smallest angle, area.
struct Shape {
  Vertex_handle p, q, r;
  double shortest2 = 0.0, min_angle = 180.0, area = 0.0;
};

Shape shape_of(Face_handle f) {
  Shape s;
  std::array<double, 3> l2;
  for (int i = 0; i < 3; ++i) l2[i] = squared(f->vertex(CDT::ccw(i))->point(), f->vertex(CDT::cw(i))->point());
  const int i = static_cast<int>(std::min_element(l2.begin(), l2.end()) - l2.begin());
  s.p = f->vertex(CDT::ccw(i)), s.q = f->vertex(CDT::cw(i)), s.r = f->vertex(i);
  s.shortest2 = l2[i];
  const double u = l2[CDT::ccw(i)], w = l2[CDT::cw(i)];
  const double cosine = std::clamp((u + w - l2[i]) / (2.0 * std::sqrt(u * w)), -1.0, 1.0);
  s.min_angle = std::acos(cosine) * 180.0 / kPi;
  s.area = std::abs(CGAL::to_double(CGAL::area(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point())));
  return s;
}

class QualityRefiner {
 public:
  QualityRefiner(State& st, const Quality2DOptions& o)
      : st_(st), o_(o), boundary_(st, [this](Vertex_handle v) { push_around(v); }) {
    for (const auto& [attribute, area] : o.region_max_area) {
      auto [it, fresh] = region_area_.emplace(attribute, area);
      if (!fresh) it->second = std::min(it->second, area);
    }
    const double b = o.min_angle_degrees * kPi / 180.0;
    off_constant_ = o.min_angle_degrees > 0.0 ? 0.475 * std::sqrt((1.0 + std::cos(b)) / (1.0 - std::cos(b))) : 0.0;
    rho_bar_ = o.min_angle_degrees > 0.0 ? 0.5 / std::sin(b) : std::numeric_limits<double>::infinity();
    double area = 0.0, smallest = o.max_area > 0.0 ? o.max_area : std::numeric_limits<double>::infinity();
    for (auto f = st.cdt().finite_faces_begin(); f != st.cdt().finite_faces_end(); ++f)
      if (f->info().in_domain()) area += shape_of(f).area;
    for (const auto& [attribute, a] : region_area_) smallest = std::min(smallest, a);
    budget_ = o.max_interior >= 0 ? o.max_interior : default_interior_budget(st.n_input(), area, smallest);
  }

  Quality2DStats run() {
    const long long placed_before = st_.placed();
    st_.enqueue_all();  // the boundary first (a no-op after a strategy left it nonobtuse), as Triangle does
    boundary_.repair_boundary(true);
    long long removed = 0;
    if (refine_all() && final_stats().bad_triangles == 0) {  // converged: take back boundary points not needed
      auto put_back = [this](Vertex_handle v) {
        push_around(v);
        boundary_.repair_boundary();
      };
      boundary_.repair_boundary();
      removed = prune_boundary_points(st_, [this](Face_handle f) { return bad(f, shape_of(f)); }, put_back);
      renumber(compact_added(st_));
      refine_all();  // nothing to do unless an undone removal came back as a different Delaunay tie
    }
    Quality2DStats out = final_stats();
    out.interior_points = st_.interior_points();
    out.interior_budget = budget_;
    out.boundary_splits = st_.placed() - placed_before + removed;
    out.boundary_points_removed = removed;
    return out;
  }

 private:
  using Key = std::array<int, 3>;  // the vertex indices of a face, sorted
  struct Bad {
    double min_angle;
    Vertex_handle a, b, c;
    bool operator<(const Bad& o) const { return min_angle > o.min_angle; }  // the skinniest first
  };

  // Refines until no bad triangle is queued or found by a full scan (true), or a budget is reached (false).
  bool refine_all() {
    for (bool more = true; more;) {  // a full scan after the queue drains catches faces changed out of sight
      more = scan() > 0;
      while (!queue_.empty() && st_.budget_left() && st_.interior_points() < budget_) refine_next();
      if (!(st_.budget_left() && st_.interior_points() < budget_)) return false;
    }
    return true;
  }
  // The face keys after compact_added renumbered the added vertices (`to`: old position -> new, -1 removed).
  void renumber(const std::vector<int>& to) {
    const int n = st_.n_input();
    for (std::set<Key>* keys : {&left_alone_, &unresolved_}) {
      std::set<Key> out;
      for (Key k : *keys) {
        for (int& i : k) i = i < n ? i : to[i - n] < 0 ? -1 : n + to[i - n];
        std::sort(k.begin(), k.end());
        if (k[0] >= 0) out.insert(k);
      }
      keys->swap(out);
    }
  }

  static Key key_of(Face_handle f) {
    Key k{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    std::sort(k.begin(), k.end());
    return k;
  }

  double area_limit(Face_handle f) const {
    double limit = o_.max_area > 0.0 ? o_.max_area : std::numeric_limits<double>::infinity();
    if (!region_area_.empty()) {
      auto it = region_area_.find(st_.cdt().region(f));
      if (it != region_area_.end()) limit = std::min(limit, it->second);
    }
    if (o_.max_area_at) {
      const Point c = CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
      limit = std::min(limit, o_.max_area_at(c.x(), c.y()));
    }
    return limit;
  }
  bool skinny(const Shape& s) const { return s.min_angle < o_.min_angle_degrees; }
  bool bad(Face_handle f, const Shape& s) const { return skinny(s) || s.area > area_limit(f); }

  // Rule (1) of the top comment: the shortest edge joins two input constraints meeting at a small angle.
  bool in_small_angle_wedge(const Shape& s) const {
    const std::vector<int> ep = boundary_.input_edges_of(s.p), eq = boundary_.input_edges_of(s.q);
    for (int j : ep)
      if (std::find(eq.begin(), eq.end(), j) != eq.end()) return false;  // pq lies along one input edge
    for (int j : ep)
      for (int k : eq)
        if (boundary_.small_angle_between(j, k, kSmallInputAngle) >= 0) return true;
    return false;
  }
  void push(Face_handle f) {
    if (st_.cdt().is_infinite(f) || !f->info().in_domain()) return;
    const Shape s = shape_of(f);
    if (bad(f, s)) queue_.push({s.min_angle, f->vertex(0), f->vertex(1), f->vertex(2)});
  }
  void push_around(Vertex_handle v) {
    auto fc = st_.cdt().incident_faces(v), done = fc;
    do push(fc);
    while (++fc != done);
  }
  // Queues every bad domain face not already left alone; returns how many.
  std::size_t scan() {
    const std::size_t before = queue_.size();
    for (auto f = st_.cdt().finite_faces_begin(); f != st_.cdt().finite_faces_end(); ++f)
      if (f->info().in_domain() && !left_alone_.count(key_of(f)) && !unresolved_.count(key_of(f))) push(f);
    return queue_.size() - before;
  }

  // The circumcenter of f, or the off-center of its shortest edge when that is nearer (Triangle's rule).
  Point new_vertex(Face_handle f, const Shape& s) const {
    const Point c = CGAL::circumcenter(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
    if (off_constant_ <= 0.0) return c;
    const Point &p = s.p->point(), &q = s.q->point();
    const double dx = q.x() - p.x(), dy = q.y() - p.y();
    const Point off(p.x() + 0.5 * dx - off_constant_ * dy, p.y() + 0.5 * dy + off_constant_ * dx);
    return squared(off, p) < squared(c, p) ? off : c;
  }

  // Walks from the centroid of f straight toward c. Returns the face holding c (closed) with blocked unset, or
  // the first constrained side crossed (its domain face, where the walk was, on its left). Exact orientations.
  Face_handle walk_to(Face_handle f, const Point& c, Side& blocked, bool& is_blocked) const {
    const CDT& t = st_.cdt();
    const Point g = CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
    is_blocked = false;
    if (t.triangle(f).bounded_side(g) != CGAL::ON_BOUNDED_SIDE) return nullptr;  // a sliver: g rounded out
    for (std::size_t steps = 0; steps <= t.number_of_faces(); ++steps) {
      int exit = -1;
      for (int i = 0; i < 3 && exit < 0; ++i) {
        const Point &a = f->vertex(CDT::ccw(i))->point(), &b = f->vertex(CDT::cw(i))->point();
        if (CGAL::orientation(a, b, c) == CGAL::RIGHT_TURN && CGAL::orientation(g, c, a) != CGAL::LEFT_TURN &&
            CGAL::orientation(g, c, b) != CGAL::RIGHT_TURN)
          exit = i;
      }
      if (exit < 0) return f;  // c is in the closed triangle
      if (f->is_constrained(exit)) {
        blocked = {f->vertex(CDT::ccw(exit)), f->vertex(CDT::cw(exit))};
        is_blocked = true;
        return f;
      }
      f = f->neighbor(exit);
      if (t.is_infinite(f) || !f->info().in_domain()) return nullptr;  // cannot happen: constraints bound the domain
    }
    return nullptr;
  }

  // The constraint sides (domain face on the left) that c would encroach from f: those bounding c's Delaunay cavity
  // whose open diametral disk holds c, or the first constraint crossed on the way to c (its closed disk holds c).
  std::vector<Side> encroached_by(Face_handle f, const Point& c, bool& ok) const {
    std::vector<Side> out;
    Side blocked;
    bool is_blocked;
    ok = true;
    Face_handle at = walk_to(f, c, blocked, is_blocked);
    auto in_closed_disk = [&](const Side& sd) { return CGAL::angle(sd.s->point(), c, sd.e->point()) != CGAL::ACUTE; };
    if (at == nullptr || (is_blocked && !in_closed_disk(blocked))) {
      ok = false;
      return out;
    }
    if (is_blocked) return {blocked};
    for (int i = 0; i < 3; ++i) {  // c on a constrained edge of its face: locate could answer the other side
      const Side sd{at->vertex(CDT::ccw(i)), at->vertex(CDT::cw(i))};
      if (at->is_constrained(i) && CGAL::orientation(sd.s->point(), sd.e->point(), c) == CGAL::COLLINEAR) return {sd};
    }
    std::vector<Face_handle> faces;
    std::vector<Edge> boundary;
    st_.cdt().get_conflicts_and_boundary(c, std::back_inserter(faces), std::back_inserter(boundary), at);
    for (const auto& [g, j] : boundary) {
      if (!g->is_constrained(j)) continue;
      const Side sd{g->vertex(CDT::cw(j)), g->vertex(CDT::ccw(j))};  // the cavity's face is on this side's left
      if (CGAL::angle(sd.s->point(), c, sd.e->point()) == CGAL::OBTUSE) out.push_back(sd);
    }
    return out;
  }

  // Rule (2) of the top comment (the terminator).
  bool refused_near_small_angle(const Side& side, const Shape& s) const {
    return boundary_.near_small_angle(side) && squared(side.s->point(), side.e->point()) < 4.0 * s.shortest2;
  }

  // Chernikov and Chrisochoides' selection disk of a skinny triangle f: centered at its circumcenter, of radius
  // R - l / (2 sin bound) (R its circumradius, l its shortest edge). Any vertex inserted there keeps Ruppert's
  // termination argument, so when the circumcenter or off-center encroaches the subsegments `encroached`, the
  // point of that disk farthest from them (the circumcenter moved by the radius, away from their midpoints) is
  // tried before splitting them: inserted when it encroaches nothing it sees. True when it was inserted.
  bool insert_in_selection_disk(Face_handle f, const Shape& s, const std::vector<Side>& encroached) {
    const Point cc = CGAL::circumcenter(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
    const double radius = std::sqrt(squared(cc, s.p->point())) - std::sqrt(s.shortest2) * rho_bar_;
    if (!(radius > 0.0) || !std::isfinite(cc.x()) || !std::isfinite(cc.y())) return false;
    double dx = 0.0, dy = 0.0;
    for (const Side& sd : encroached) {
      const Point m = CGAL::midpoint(sd.s->point(), sd.e->point());
      const double ux = cc.x() - m.x(), uy = cc.y() - m.y(), n = std::hypot(ux, uy);
      if (n > 0.0) dx += ux / n, dy += uy / n;
    }
    const double n = std::hypot(dx, dy);
    if (!(n > 0.0)) return false;
    const Point alt(cc.x() + radius * dx / n, cc.y() + radius * dy / n);
    bool ok;
    if (!encroached_by(f, alt, ok).empty() || !ok) return false;
    Vertex_handle v = insert_interior(st_, alt, f);
    if (v == nullptr) return false;
    push_around(v);
    return true;
  }

  void refine_next() {
    const Bad b = queue_.top();
    queue_.pop();
    Face_handle f;
    if (!st_.cdt().is_face(b.a, b.b, b.c, f)) return;  // gone since it was queued
    const Shape s = shape_of(f);
    if (skinny(s) && in_small_angle_wedge(s)) {
      left_alone_.insert(key_of(f));
      return;
    }
    const Point c = new_vertex(f, s);
    bool ok = std::isfinite(c.x()) && std::isfinite(c.y());
    const std::vector<Side> encroached = ok ? encroached_by(f, c, ok) : std::vector<Side>{};
    if (!ok) {
      unresolved_.insert(key_of(f));
      return;
    }
    if (encroached.empty()) {
      Vertex_handle v = insert_interior(st_, c, f);
      if (v == nullptr) {
        unresolved_.insert(key_of(f));
        return;
      }
      push_around(v);
      return;
    }
    if (skinny(s) && insert_in_selection_disk(f, s, encroached)) return;
    if (skinny(s) && std::any_of(encroached.begin(), encroached.end(),
                                 [&](const Side& sd) { return refused_near_small_angle(sd, s); })) {
      left_alone_.insert(key_of(f));
      return;
    }
    bool split_any = false;
    for (const Side& sd : encroached)
      if (st_.budget_left()) split_any = boundary_.split_subsegment(sd) || split_any;
    boundary_.repair_boundary();
    if (!split_any) {
      unresolved_.insert(key_of(f));
      return;
    }
    if (st_.cdt().is_face(b.a, b.b, b.c, f)) push(f);  // still there: try again against the split subsegments
  }

  Quality2DStats final_stats() const {
    Quality2DStats out;
    for (auto f = st_.cdt().finite_faces_begin(); f != st_.cdt().finite_faces_end(); ++f) {
      if (!f->info().in_domain()) continue;
      const Shape s = shape_of(f);
      ++out.triangles;
      out.min_angle_degrees = std::min(out.min_angle_degrees, s.min_angle);
      out.max_area = std::max(out.max_area, s.area);
      const bool is_bad = bad(f, s);
      const bool alone = is_bad && skinny(s) && (left_alone_.count(key_of(f)) || in_small_angle_wedge(s));
      if (alone) {
        ++out.small_angle_triangles;
        continue;
      }
      if (is_bad) ++out.bad_triangles;
      out.min_angle_outside_small_angles_degrees = std::min(out.min_angle_outside_small_angles_degrees, s.min_angle);
    }
    return out;
  }

  State& st_;
  const Quality2DOptions& o_;
  QualityBoundary boundary_;
  std::map<double, double> region_area_;
  double off_constant_ = 0.0;
  double rho_bar_ = 0.0;  // the circumradius-to-shortest-edge bound 1 / (2 sin bound) of good triangles
  long long budget_ = 0;
  std::priority_queue<Bad> queue_;
  std::set<Key> left_alone_, unresolved_;
};

}  // namespace

Quality2DStats refine_quality(State& st, const Quality2DOptions& options) { return QualityRefiner(st, options).run(); }

}  // namespace refine2d
}  // namespace nonobtuse
