// Removal of boundary Steiner points after the interior quality refinement has converged.
//
// The boundary splits of quality2d.cpp are Ruppert's: a subsegment is split when a circumcenter or off-center
// would encroach it, or when its apex is obtuse. Later interior points often leave such a split unneeded: the
// point that encroached never went in, and the apex that was obtuse is gone. Triangle never takes a split back
// (it ties with us where our splits mimic its own). Here, once nothing is left to refine, each boundary Steiner
// point v (between a and b on its constraint) is removed when the mesh without it still meets everything asked
// locally: v's star becomes the constrained Delaunay triangulation of its link with the subsegment a-b (the rest
// of the mesh is unchanged: its faces were Delaunay with v and stay so without it), so it suffices that (1) a-b
// has a nonobtuse apex on each domain side, (2) every new domain face meets the quality bounds and (3) every
// other constrained side of a new domain face has a nonobtuse apex. (1) is decided before any change: the apex
// of a-b is the vertex of v's link on that side seen under the largest angle, and every link vertex is visible
// from v on a-b, so the apex is nonobtuse iff no link vertex lies in the open diametral disk of a-b (exact).
// (2) and (3) are checked on the faces after removal (the angle and area tests in floating point, as they are
// in the refinement; the apexes exactly); a removal failing them is undone by split at v's own point.
//
// Termination: a pass goes once over the boundary Steiner points present when it starts; every removal lowers
// their number by one and an undone removal leaves it unchanged, and the passes stop at the first one that removes
// nothing, so there are at most (boundary Steiner points + 1) passes.
#include "quality2d_prune.h"

#include <set>
#include <tuple>
#include <unordered_set>
#include <utility>

#include "split_point.h"

namespace nonobtuse::refine2d {
namespace {

using Link = std::set<std::pair<Vertex_handle, Vertex_handle>>;

std::pair<Vertex_handle, Vertex_handle> unordered(Vertex_handle p, Vertex_handle q) {
  return p < q ? std::make_pair(p, q) : std::make_pair(q, p);
}

// The star of a boundary Steiner point v: its neighbours a, b on its constraint (the path a -> v -> b), the domain
// marks left and right of that path, the edges of its link (opposite v), and the finite link vertices but a, b on
// each side.
struct Star {
  Vertex_handle a, b;
  int left = -1, right = -1;  // FaceInfo::component
  bool flat_left = false, flat_right = false;  // the side is one face a, v, b (v ulps off the line a-b)
  Link link;
  std::vector<Vertex_handle> link_vertices;
  std::vector<Vertex_handle> on_left, on_right;
};

// False when v is not a boundary Steiner point with two constrained edges.
bool read_star(const State& st, Vertex_handle v, Star& s) {
  const CDT& t = st.cdt();
  if (v->info() < st.n_input() || st.steiner_edge(v->info()) < 0) return false;
  std::vector<Vertex_handle> ends;
  auto ec = t.incident_edges(v), edges_done = ec;
  do
    if (t.is_constrained(*ec)) {
      const Vertex_handle p = ec->first->vertex(CDT::cw(ec->second)), q = ec->first->vertex(CDT::ccw(ec->second));
      ends.push_back(p == v ? q : p);
    }
  while (++ec != edges_done);
  if (ends.size() != 2) return false;
  s.a = ends[0], s.b = ends[1];
  auto fc = t.incident_faces(v);
  while (fc->vertex(CDT::ccw(fc->index(v))) != s.b) ++fc;  // the face left of v -> b: the path's left side
  const auto done = fc;
  bool on_left = true;
  do {
    const int i = fc->index(v);
    const Vertex_handle p = fc->vertex(CDT::ccw(i)), q = fc->vertex(CDT::cw(i));
    (on_left ? s.left : s.right) = fc->info().component;
    if (unordered(p, q) == unordered(s.a, s.b)) (on_left ? s.flat_left : s.flat_right) = true;
    s.link.insert(unordered(p, q));
    s.link_vertices.push_back(p);
    if (!t.is_infinite(p) && p != s.a && p != s.b) (on_left ? s.on_left : s.on_right).push_back(p);
    if (q == s.a) on_left = false;  // counter-clockwise from v -> b, the left side ends at v -> a
  } while (++fc != done);
  return true;
}

// Condition (1) of the top comment, and every link vertex strictly on its own side of a-b (so the constraint a-b
// passes through no vertex). Exact.
bool joinable(const Star& s) {
  const Point &a = s.a->point(), &b = s.b->point();
  for (const auto& [side, turn, component] : {std::make_tuple(&s.on_left, CGAL::LEFT_TURN, s.left),
                                               std::make_tuple(&s.on_right, CGAL::RIGHT_TURN, s.right)})
    for (Vertex_handle u : *side)
      if (CGAL::orientation(a, b, u->point()) != turn ||
          (component >= 0 && CGAL::angle(a, u->point(), b) == CGAL::OBTUSE))
        return false;
  return true;
}

// Gives the faces between a-b and the link the marks of their side (flooding from a-b across edges that are neither
// constrained nor on the link; no face on a flat side, where a-b was an edge). Returns them. InternalError when a
// face outside the old star is reached.
std::vector<Face_handle> mark_new_faces(const CDT& t, const Star& s) {
  Face_handle f;
  int i;
  if (!t.is_edge(s.a, s.b, f, i)) throw InternalError("quality2d_prune: a-b is no edge after the removal");
  if (f->vertex(CDT::ccw(i)) != s.a) f = f->neighbor(i);  // f on the left of a -> b
  const std::unordered_set<Vertex_handle> link(s.link_vertices.begin(), s.link_vertices.end());
  std::vector<Face_handle> out;
  std::unordered_set<Face_handle> seen;
  std::vector<std::pair<Face_handle, int>> stack;
  if (!s.flat_left) stack.emplace_back(f, s.left);
  if (!s.flat_right) stack.emplace_back(f->neighbor(3 - f->index(s.a) - f->index(s.b)), s.right);
  while (!stack.empty()) {
    auto [g, component] = stack.back();
    stack.pop_back();
    if (!seen.insert(g).second) continue;
    for (int j = 0; j < 3; ++j)
      if (!link.count(g->vertex(j))) throw InternalError("quality2d_prune: the removal changed faces outside the star");
    g->info().component = component;
    out.push_back(g);
    for (int j = 0; j < 3; ++j)
      if (!g->is_constrained(j) && !s.link.count(unordered(g->vertex(CDT::cw(j)), g->vertex(CDT::ccw(j)))))
        stack.emplace_back(g->neighbor(j), component);
  }
  return out;
}

// Conditions (2) and (3) of the top comment on the faces `faces`.
bool still_good(const CDT& t, const std::vector<Face_handle>& faces, const std::function<bool(Face_handle)>& bad) {
  for (Face_handle f : faces) {
    if (t.is_infinite(f) || !f->info().in_domain()) continue;
    if (bad(f)) return false;
    for (int i = 0; i < 3; ++i)
      if (f->is_constrained(i) && CGAL::angle(f->vertex(CDT::ccw(i))->point(), f->vertex(i)->point(),
                                              f->vertex(CDT::cw(i))->point()) == CGAL::OBTUSE)
        return false;
  }
  return true;
}

}  // namespace

std::vector<Face_handle> remove_boundary_point(State& st, Vertex_handle v) {
  Star s;
  if (!read_star(st, v, s)) return {};
  const int at = v->info() - st.n_input_, edge = st.steiner_edge_[at];
  CDT& t = st.cdt_;
  t.CDT::Ctr::remove_incident_constraints(v);  // the flags only: CDT's own version flips around v first
  t.remove(v);                                  // v's star becomes the Delaunay triangulation of its link
  t.insert_constraint(s.a, s.b);
  st.added_[at] = Vertex_handle();
  --st.placed_;
  --st.edges_[edge].steiner_points;
  ++st.splits_;  // the triangulation changes (State::boundary_sides recomputes)
  std::vector<Face_handle> faces = mark_new_faces(t, s);
  if (st.check_every_split_) st.check_invariants();
  return faces;
}

std::vector<int> compact_added(State& st) {
  std::vector<int> to(st.added_.size(), -1);
  int kept = 0;
  for (std::size_t k = 0; k < st.added_.size(); ++k) {
    if (st.added_[k] == Vertex_handle()) continue;
    to[k] = kept;
    st.added_[kept] = st.added_[k];
    st.steiner_edge_[kept] = st.steiner_edge_[k];
    st.added_[kept]->info() = st.n_input_ + kept;
    ++kept;
  }
  st.added_.resize(kept);
  st.steiner_edge_.resize(kept);
  st.propagation_.renumber(to);
  return to;
}

long long prune_boundary_points(State& st, const std::function<bool(Face_handle)>& bad,
                                const std::function<void(Vertex_handle)>& added) {
  long long removed = 0;
  for (bool more = true; more;) {
    more = false;
    std::vector<Vertex_handle> points;
    for (Vertex_handle v : st.added())
      if (v != Vertex_handle() && st.steiner_edge(v->info()) >= 0) points.push_back(v);
    for (Vertex_handle v : points) {
      Star s;
      if (!read_star(st, v, s) || !joinable(s)) continue;
      if (st.has_work()) throw InternalError("quality2d_prune: a removal with sides queued (they could name it)");
      const Point p = v->point();
      const std::vector<Face_handle> faces = remove_boundary_point(st, v);
      if (still_good(st.cdt(), faces, bad)) {
        ++removed, more = true;
        continue;
      }
      const Vertex_handle w = split(st, s.left >= 0 ? Side{s.a, s.b} : Side{s.b, s.a}, p);  // undone
      if (w == nullptr) throw InternalError("quality2d_prune: a removed point could not be put back");
      added(w);
    }
  }
  return removed;
}

}  // namespace nonobtuse::refine2d
