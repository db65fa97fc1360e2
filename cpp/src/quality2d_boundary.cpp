// The boundary rules of the interior quality refinement (quality2d.cpp): the input angles that count as small,
// and Ruppert's and Triangle's boundary splits.
//
// The boundary comes first, as in Triangle: run() starts by splitting every boundary side with an obtuse apex the
// same way (a no-op when a strategy already made the boundary nonobtuse). With the greedy strategy refine2d.cpp
// no longer runs the minimal greedy before this: its pieces are far shorter than the input's (0.066 m on the demo
// cross-section, whose shortest input edge is 5.4 m; 0.18 on p2t_dude against Triangle's 0.5) and every one drew
// a cascade of interior points. Measured on bench_quality2d (25 and 30 degrees): vertices against Triangle
// -pq25D went from median 1.065x, max 2.70x to median 1.00x, max 1.69x (demo 1.76x -> 1.00x, p2t_dude 1.72x ->
// 1.03x, la 1.49x -> 1.02x). Sides on a boundary edge meeting another boundary edge at an input angle below 60
// degrees are left to the greedy rule in that first pass (midpoints and shells spent the whole budget at
// p2t_deadly_quad's 0.17 degree corner); where an interface or dangling segment makes the small angle, shells (the
// greedy rule there drew 1.56x Triangle's vertices on clusters.poly, shells 0.77x). The shell is Triangle's: the
// smallest power of two at least a third of the subsegment, constructed from the junction (nearest_shell).
// Splitting at the foot of the obtuse apex (clamped to the middle half) instead of the
// midpoint was measured too: max 1.28x (clusters) but the demo at 30 degrees 1.18x and more boundary points;
// midpoints kept.
#include "quality2d_boundary.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "refine2d_strategies.h"
#include "split_point.h"

namespace nonobtuse::refine2d {

double nearest_shell(const Point& s, const Point& e) {
  const double length = std::sqrt(CGAL::to_double(CGAL::squared_distance(s, e))), third = length / 3.0;
  if (!(third > 0.0) || !std::isfinite(length)) return 0.5;
  double p = std::ldexp(1.0, std::ilogb(third));  // the largest 2^k <= |e - s| / 3
  if (p < third) p *= 2.0;
  return p / length;
}

namespace {

constexpr double kPi = 3.14159265358979323846;

// The angle at v of the triangle v, a, b in degrees (floating point).
double degrees(const Point2& v, const Point2& a, const Point2& b) {
  const double ux = a.x - v.x, uy = a.y - v.y, wx = b.x - v.x, wy = b.y - v.y;
  return std::atan2(std::abs(ux * wy - uy * wx), ux * wx + uy * wy) * 180.0 / kPi;
}

}  // namespace

QualityBoundary::QualityBoundary(State& st, std::function<void(Vertex_handle)> added)
    : st_(st), added_(std::move(added)) {
  edges_at_.resize(st.n_input());
  for (int k = 0; k < static_cast<int>(st.edges().size()); ++k)
    for (int end : st.edges()[k].edge) edges_at_[end].push_back(k);
  for (auto v = st.cdt().finite_vertices_begin(); v != st.cdt().finite_vertices_end(); ++v)
    if (v->info() < st.n_input() && edges_at_[v->info()].size() >= 2) note_exterior_wedges(v);
  note_interfaces();
}

// The input edges vertex v lies on: those at an input vertex, the one of a boundary Steiner point, none inside.
std::vector<int> QualityBoundary::input_edges_of(Vertex_handle v) const {
  const int i = v->info();
  if (i < st_.n_input()) return edges_at_[i];
  const int k = st_.steiner_edge(i);
  return k < 0 ? std::vector<int>{} : std::vector<int>{k};
}

// The input vertex the input edges j and k share when they meet there at an angle below `limit` degrees with the
// domain inside that angle, or -1. A hole's or the exterior's corner is no small input angle: no domain triangle
// lies in it, and no vertex of one edge sees a subsegment of the other through the domain (measured: A.poly's
// 45.4 degree hole corner drew 51 boundary points against Triangle's 42 as a small angle, 41 now).
int QualityBoundary::small_angle_between(int j, int k, double limit) const {
  const auto &a = st_.edges()[j].edge, &b = st_.edges()[k].edge;
  const auto& pts = st_.domain().points;
  for (int z : a)
    for (int w : b)
      if (z == w && degrees(pts[z], pts[a[0] + a[1] - z], pts[b[0] + b[1] - z]) < limit &&
          !exterior_wedge_.count({z, std::min(j, k), std::max(j, k)}))
        return z;
  return -1;
}

// Records in exterior_wedge_ every pair of input edges at input vertex v meeting at less than 90 degrees (the
// largest limit asked of small_angle_between) whose angle holds no domain: the face of v holding the angle's
// bisector is infinite or outside the domain (exact orientations about the floating point bisector; no
// constraint crosses the angle when the two edges are consecutive around v, and when they are not, a smaller
// angle between consecutive ones decides). Cost: the faces around v, per pair.
void QualityBoundary::note_exterior_wedges(Vertex_handle v) {
  const int z = v->info();
  const auto& pts = st_.domain().points;
  const std::vector<int>& at = edges_at_[z];
  for (std::size_t x = 0; x < at.size(); ++x)
    for (std::size_t y = x + 1; y < at.size(); ++y) {
      const auto &a = st_.edges()[at[x]].edge, &b = st_.edges()[at[y]].edge;
      const Point2 &p = pts[z], &u = pts[a[0] + a[1] - z], &w = pts[b[0] + b[1] - z];
      if (!(degrees(p, u, w) < 90.0)) continue;
      const double lu = std::hypot(u.x - p.x, u.y - p.y), lw = std::hypot(w.x - p.x, w.y - p.y);
      const Point d(p.x + (u.x - p.x) / lu + (w.x - p.x) / lw, p.y + (u.y - p.y) / lu + (w.y - p.y) / lw);
      if (!holds_domain_toward(v, d)) exterior_wedge_.insert({z, std::min(at[x], at[y]), std::max(at[x], at[y])});
    }
}
// Marks in interface_ every input edge with the domain on both sides (an interface or a dangling segment): a
// constrained side of a domain face whose reverse is a boundary side too. Cost: one pass over the faces.
void QualityBoundary::note_interfaces() {
  interface_.assign(st_.edges().size(), false);
  for (auto f = st_.cdt().finite_faces_begin(); f != st_.cdt().finite_faces_end(); ++f)
    for (int i = 0; i < 3; ++i)
      if (f->info().in_domain() && f->is_constrained(i)) {
        const Side reverse{f->vertex(CDT::cw(i)), f->vertex(CDT::ccw(i))};
        if (st_.is_boundary_side(reverse)) interface_[st_.edge_of(reverse)] = true;
      }
}
// Whether the face around v that the ray from v toward d enters first is a domain face.
bool QualityBoundary::holds_domain_toward(Vertex_handle v, const Point& d) const {
  auto f = st_.cdt().incident_faces(v), done = f;
  do {
    if (st_.cdt().is_infinite(f)) continue;
    const int i = f->index(v);
    const Point &u = f->vertex(CDT::ccw(i))->point(), &w = f->vertex(CDT::cw(i))->point();
    if (CGAL::orientation(v->point(), u, d) != CGAL::RIGHT_TURN &&
        CGAL::orientation(v->point(), w, d) != CGAL::LEFT_TURN)
      return f->info().in_domain();
  } while (++f != done);
  return false;
}

// Whether input edge k makes an angle below `limit` with another input constraint at its input end z.
bool QualityBoundary::small_angle_at(int k, int z, double limit) const {
  for (int j : edges_at_[z])
    if (j != k && small_angle_between(j, k, limit) == z) return true;
  return false;
}

// Splits `side` at its midpoint, or at a concentric shell from an input end where an acute input angle is (as
// Triangle does). The point is first constructed plainly from the shell's end (a + t (b - a) in doubles) and
// taken when it lies exactly on the subsegment: at an axis-parallel edge that is the exact shell (4 from the
// corner of [0, 10], where pick_point's dyadic parameters near 0.4 are ulps off and the right angle such a
// point makes with a neighbour comes out obtuse: measured on quality2d_test's L shape at 30 degrees, 5 boundary
// points instead of 2 and two triangles left alone). Else pick_point's candidates. False when it is no
// subsegment any more (split by an earlier repair) or no point passes the exact checks.
bool QualityBoundary::split_subsegment(const Side& side) {
  if (st_.left_face(side) == nullptr) return false;
  const int k = st_.edge_of(side);
  auto acute_end = [&](Vertex_handle v) { return v->info() < st_.n_input() && small_angle_at(k, v->info(), 90.0); };
  Vertex_handle from = side.s, to = side.e;
  if (acute_end(to) && !acute_end(from)) std::swap(from, to);
  const Point &a = from->point(), &b = to->point();
  const double t = acute_end(from) && !acute_end(to) ? nearest_shell(a, b) : 0.5;  // from a toward b
  auto valid = [&](const Point& c) { return splittable(st_, side, c); };
  Point p(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y()));
  const bool plain =
      CGAL::orientation(a, b, p) == CGAL::COLLINEAR && CGAL::angle(a, p, b) == CGAL::OBTUSE && valid(p);
  if (!plain && !pick_point(side.s->point(), side.e->point(), from == side.s ? t : 1.0 - t, valid, p)) return false;
  Vertex_handle v = split(st_, side, p);
  if (v == nullptr) return false;
  added_(v);
  return true;
}

// Restores every boundary side the splits disturbed (split queues them): a violated side is split like an
// encroached one (Ruppert: midpoints and shells, which keep the spacing even); a side no such point fixes is
// left to the greedy rule. Cost: per split, the sides of the faces it changed.
// With greedy_at_small_corners, a side on a boundary edge with an input angle below 60 degrees at an end between
// it and another boundary edge goes to the greedy rule directly (measured: midpoints and shells at
// p2t_deadly_quad's 0.17 degree corner spent the whole Steiner budget, where the greedy rule needs 2 points).
// Where an interface or dangling segment makes the small angle, shells: both constraints are split at the same
// powers of two from the junction, which never encroach each other (concentric_shells.cpp). The greedy rule
// there, free to cut anywhere, put its points a few units from the far ends of clusters.poly's segments and
// the interior refinement graded down to them (measured: 46 boundary and 41 interior points against 29 and 7
// with shells; Triangle 36 and 15). This is the split of concentric_shells.h's is_acute_junction: shells where
// an interior constraint meets the junction, the greedy rule (forbidden intervals) at two boundary edges.
void QualityBoundary::repair_boundary(bool greedy_at_small_corners) {
  std::vector<Side> stuck;
  while (st_.has_work() && st_.budget_left()) {
    const Side side = st_.next_side();
    if (!st_.is_violated(side)) continue;
    if ((greedy_at_small_corners && at_small_boundary_corner(side)) || !split_subsegment(side)) stuck.push_back(side);
  }
  if (stuck.empty()) return;
  const std::size_t before = st_.added().size();
  for (const Side& side : stuck) st_.enqueue(side);
  greedy_refine_queued(st_);
  for (std::size_t i = before; i < st_.added().size(); ++i) added_(st_.added()[i]);
}


// Whether side lies on an input edge with an input angle below 60 degrees at one of its ends.
bool QualityBoundary::near_small_angle(const Side& side) const {
  const int k = st_.edge_of(side);
  const auto& edge = st_.edges()[k].edge;
  return small_angle_at(k, edge[0], kSmallInputAngle) || small_angle_at(k, edge[1], kSmallInputAngle);
}
// Whether side lies on a boundary edge (the domain on one side) meeting another boundary edge at an input angle
// below 60 degrees at one of its ends.
bool QualityBoundary::at_small_boundary_corner(const Side& side) const {
  const int k = st_.edge_of(side);
  if (interface_[k]) return false;
  for (int z : st_.edges()[k].edge)
    for (int j : edges_at_[z])
      if (j != k && !interface_[j] && small_angle_between(j, k, kSmallInputAngle) == z) return true;
  return false;
}

}  // namespace nonobtuse::refine2d
