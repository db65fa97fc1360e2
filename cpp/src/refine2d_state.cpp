// The refinement state: the domain's CDT, its boundary sides, the per-edge bookkeeping and the invariant check.
#include "refine2d_state.h"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace nonobtuse::refine2d {
namespace {

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

State::State(const Domain2& d, long long b, Triangulation2* prebuilt)
    : domain_(d), n_input_(static_cast<int>(d.points.size())), budget_(b) {
  Triangulation2 taken = prebuilt != nullptr ? prebuilt->take() : Triangulation2();
  if (!taken.empty() && cdt::same_domain(taken.built()->domain, domain_))
    cdt_.swap(taken.built()->cdt);  // what cdt::build(cdt_, domain_) would make, without making it again
  else
    cdt::build(cdt_, domain_);
  if (std::none_of(cdt_.finite_faces_begin(), cdt_.finite_faces_end(), [](const auto& f) { return f.info().in_domain(); }))
    throw InvalidInput("the domain contains no triangle (are all points collinear, or is everything a hole?)");
  const std::vector<Side> sides = boundary_sides();
  for (const Side& side : sides) {
    int a = side.s->info(), c = side.e->info();
    if (edge_index_.emplace(edge_key(a, c), static_cast<int>(edges_.size())).second)
      edges_.push_back({{a, c}, 0, 0});  // an interface appears once, as (min, max)
  }
  convex_polygon_ = is_convex_polygon(sides);
}

bool State::is_convex_polygon(const std::vector<Side>& sides) const {
  // A polygon has as many boundary sides as vertices; inner points or constraints break the count (a cheap test
  // first: the constrained-edge scan below visits every edge of the triangulation).
  if (sides.size() != cdt_.number_of_vertices()) return false;
  for (const Side& side : sides) {
    Face_handle f = left_face(side);
    if (!cdt_.is_infinite(f->neighbor(f->index(apex(side))))) return false;
  }
  for (auto e = cdt_.constrained_edges_begin(); e != cdt_.constrained_edges_end(); ++e)
    if (e->first->info().in_domain() && e->first->neighbor(e->second)->info().in_domain()) return false;
  for (auto v = cdt_.finite_vertices_begin(); v != cdt_.finite_vertices_end(); ++v)
    if (!cdt_.are_there_incident_constraints(v)) return false;
  return true;
}

Face_handle State::left_face(const Side& side) const {
  Face_handle f;
  int i;
  if (!find_edge(cdt_, side.s, side.e, f, i) || !f->is_constrained(i)) return nullptr;
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
  return !cdt_.is_infinite(c) && CGAL::angle(side.s->point(), c->point(), side.e->point()) == CGAL::OBTUSE;
}

std::vector<Side> State::boundary_sides() const {
  if (sides_of_ == splits_) return sides_;
  // A boundary side is a constrained edge of a domain face, oriented with the face on its left.
  // Sorted by the key (s index, e index), computed once per side rather than through the vertex handles at every
  // comparison.
  std::vector<std::pair<std::uint64_t, Side>> keyed;
  for (auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end(); ++f)
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
  for (const Side& side : boundary_sides()) queue_.push_back(side);
}

void State::check_invariants() {
  if (!cdt_.is_valid()) throw InternalError("refine2d: the triangulation is invalid after a split");
  // (in domain, region attribute) of every face; components may be numbered differently by a new marking.
  auto marks = [this] {
    std::vector<std::pair<bool, double>> out;
    for (auto f = cdt_.all_faces_begin(); f != cdt_.all_faces_end(); ++f)
      out.emplace_back(f->info().in_domain(), f->info().in_domain() ? cdt_.region(f) : 0.0);
    return out;
  };
  const auto kept = marks();
  cdt::mark_domain(cdt_, domain_);  // the marks from scratch; equal to the maintained ones when remark_around is right
  if (marks() != kept)
    throw InternalError("refine2d: domain marks maintained by split differ from mark_domain");
}

int State::edge_of(const Side& side) const {
  for (Vertex_handle v : {side.s, side.e})
    if (v->info() >= n_input_) return steiner_edge_.at(v->info() - n_input_);
  int a = side.s->info(), b = side.e->info();
  auto it = edge_index_.find(edge_key(a, b));
  if (it == edge_index_.end()) throw InternalError("refine2d: a boundary subsegment outside the input boundary");
  return it->second;
}

}  // namespace nonobtuse::refine2d
