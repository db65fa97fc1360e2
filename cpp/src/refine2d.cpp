// nonobtuse::refine: strategy dispatch, the lower bound, the optimality flag and the exact certificate.
#include <chrono>
#include <unordered_map>

#include "refine2d_state.h"

namespace nonobtuse {
namespace {

using refine2d::Face_handle;
using refine2d::Side;
using refine2d::State;

// Exact certificate of a mesh as returned: the number of boundary segments (one triangle) whose triangle is
// obtuse at the apex opposite them (CGAL::angle on the stored doubles). Interfaces are issue 4.
long long count_obtuse_boundary(const Mesh2& mesh) {
  std::unordered_map<std::uint64_t, std::vector<int>> apexes;  // segment key -> apex of each incident triangle
  auto key = [](int a, int b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
  };
  for (const auto& s : mesh.segments) apexes[key(s[0], s[1])];
  for (const auto& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) {
      auto it = apexes.find(key(t[(i + 1) % 3], t[(i + 2) % 3]));
      if (it != apexes.end()) it->second.push_back(t[i]);
    }
  auto pt = [&](int i) { return cdt::to_cgal(mesh.points[i]); };
  long long bad = 0;
  for (const auto& s : mesh.segments) {
    const auto& a = apexes[key(s[0], s[1])];
    if (a.size() == 1 && CGAL::angle(pt(s[0]), pt(a[0]), pt(s[1])) == CGAL::OBTUSE) ++bad;
  }
  return bad;
}

// The domain is a convex polygon without holes, interior points or interior constraints: every boundary side
// has the infinite face across it, and every vertex is on a constraint.
bool is_convex_polygon(const State& st) {
  for (const Side& side : st.boundary_sides()) {
    Face_handle f = st.left_face(side);
    if (!st.cdt.is_infinite(f->neighbor(f->index(st.apex(side))))) return false;
  }
  for (auto e = st.cdt.constrained_edges_begin(); e != st.cdt.constrained_edges_end(); ++e)
    if (e->first->info().in_domain && e->first->neighbor(e->second)->info().in_domain) return false;
  for (auto v = st.cdt.finite_vertices_begin(); v != st.cdt.finite_vertices_end(); ++v)
    if (!st.cdt.are_there_incident_constraints(v)) return false;
  return true;
}

}  // namespace

long long default_steiner_budget(std::size_t n_points) { return 10 * static_cast<long long>(n_points) + 1000; }

std::string to_string(RefineStrategy s) {
  switch (s) {
    case RefineStrategy::Greedy: return "greedy";
    case RefineStrategy::ProjectFlip: return "project-flip";
    case RefineStrategy::Projection: return "projection";
  }
  return "?";
}

std::string to_string(RefineStatus s) {
  switch (s) {
    case RefineStatus::Converged: return "converged";
    case RefineStatus::BudgetExhausted: return "budget_exhausted";
    case RefineStatus::Stalled: return "stalled";
  }
  return "?";
}

RefineResult2 refine(const Domain2& domain, const RefineOptions& options) {
  auto start = std::chrono::steady_clock::now();
  long long budget = options.max_steiner < 0 ? default_steiner_budget(domain.points.size()) : options.max_steiner;
  State st(domain, budget);

  // Lower bound. For each input boundary edge E, any valid refinement's subsegments of E have empty open
  // half-disks with respect to every vertex, in particular the input vertices; Greedy-Refine of E against the
  // input vertices alone is optimal for that weaker single-edge problem (Theorem 2), and more vertices only add
  // constraints, so no refinement placing Steiner points on E uses fewer. Edges are disjoint, so the bounds add.
  // (Encroachers are the input vertices reachable inside E's half-disk without crossing a constraint; for a
  // convex domain these are exactly the visible ones.)
  std::vector<Side> sides = st.boundary_sides();
  for (std::size_t k = 0; k < sides.size(); ++k)
    st.edges[k].lower_bound = st.greedy_count(sides[k], st.walk_diametral_disk(sides[k]).encroachers);
  const bool convex = is_convex_polygon(st);

  auto run = [&] {
    switch (options.strategy) {
      case RefineStrategy::Greedy: refine2d::greedy_refine(st); break;
      case RefineStrategy::ProjectFlip: refine2d::project_flip(st); break;
      case RefineStrategy::Projection: refine2d::projection_refine(st); break;
    }
  };
  run();
  // Rescue: a side can be left violated when no double point near the strategy's choice keeps the neighbouring
  // triangles valid (an apex nearly on the line, a few ulps away). Split such sides near their midpoint, far
  // from both ends, and run the strategy again; at most 3 rounds.
  for (int round = 0; round < 3 && st.budget_left(); ++round) {
    std::vector<Side> stuck;
    for (const Side& side : st.boundary_sides())
      if (st.is_violated(side)) stuck.push_back(side);
    if (stuck.empty()) break;
    st.fallback_used = true;
    for (const Side& side : stuck) {
      refine2d::Point p;
      auto valid = [&](const refine2d::Point& c) { return st.keeps_triangles_valid(side, c); };
      if (st.budget_left() && st.is_violated(side) &&
          refine2d::pick_point(side.s->point(), side.e->point(), 0.5, valid, p))
        st.split(side, p);
    }
    run();
  }

  RefineResult2 r;
  r.mesh = cdt::to_mesh(st.cdt);
  r.obtuse_boundary_triangles = count_obtuse_boundary(r.mesh);
  r.steiner_points = st.placed;
  for (const auto& e : st.edges) r.lower_bound += e.lower_bound;
  r.edges = st.edges;
  r.status = r.obtuse_boundary_triangles == 0 ? RefineStatus::Converged
             : st.budget_left()                 ? RefineStatus::Stalled
                                                : RefineStatus::BudgetExhausted;
  if (r.status == RefineStatus::Converged && r.steiner_points == r.lower_bound)
    r.optimal = 1;
  else if (r.status == RefineStatus::Converged && options.strategy == RefineStrategy::Greedy && convex &&
           !st.fallback_used)
    r.optimal = 1;  // Theorem 3
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace nonobtuse
