// nonobtuse::refine: strategy dispatch, the lower bound, the optimality flag and the exact certificate.
#include <chrono>

#include "fork_join.h"
#include "nonobtuse/check2d.h"
#include "refine2d_state.h"

namespace nonobtuse {
namespace {

using refine2d::Side;
using refine2d::State;

}  // namespace

long long default_steiner_budget(std::size_t n_points) { return 10 * static_cast<long long>(n_points) + 1000; }

const char* to_string(RefineStrategy s) {
  switch (s) {
    case RefineStrategy::Greedy: return "greedy";
    case RefineStrategy::ProjectFlip: return "project-flip";
    case RefineStrategy::Projection: return "projection";
  }
  return "?";
}

Refine2DResult refine(const Domain2& domain, const Refine2DOptions& options) {
  auto start = std::chrono::steady_clock::now();
  long long budget = options.max_steiner < 0 ? default_steiner_budget(domain.points.size()) : options.max_steiner;
  State st(domain, budget);

  // Lower bound. For each input boundary edge E, every subsegment of E in any valid refinement has an open
  // half-disk free of the vertices it sees, in particular of the input vertices. Greedy-Refine of E against the
  // input vertices alone is optimal for that weaker single-edge problem (Theorem 2: the greedy end is as far as
  // any solution's first point can be, by the exchange argument, which holds because a piece of a valid
  // subsegment is valid: its disk lies in the subsegment's and it sees no more), and more vertices only add constraints, so no
  // refinement placing Steiner points on E uses fewer. Edges are disjoint, so the bounds add.
  // Visibility: a vertex counts for a subsegment only when some point of the open subsegment sees it, tested
  // exactly against the constraints the walk over E's disk meets (Sight, covered_from: the first constraint on
  // every sight line from E inside the disk is one of them). A vertex that the walk merely reaches, around the
  // free end of a dangling segment or an end on the circle, does not count: the bound never counts a vertex that
  // a valid refinement could leave in the disk, which is what makes it a lower bound.
  // An interface edge is one single-edge problem with the encroachers of both sides (the walk collects both).
  // Large inputs (unless options.threads is 1): the edges alternate between two threads, each walking on its own
  // lane.
  std::vector<std::pair<int, Side>> first_side;  // (input edge, its first boundary side)
  std::vector<bool> bounded(st.edges.size(), false);
  for (const Side& side : st.boundary_sides()) {
    int k = st.edge_of(side);
    if (!bounded[k]) first_side.emplace_back(k, side);
    bounded[k] = true;
  }
  auto lower_bounds = [&](int lane) {
    for (std::size_t i = lane; i < first_side.size(); i += 2) {
      const auto& [k, side] = first_side[i];
      st.edges[k].lower_bound = st.greedy_count(side, st.walk_diametral_disk(side, lane));
    }
  };
  fork_join(worth_forking(st.cdt.number_of_faces(), options.threads), [&] { lower_bounds(0); },
            [&] { lower_bounds(1); });

  auto run = [&] {
    switch (options.strategy) {
      case RefineStrategy::Greedy: refine2d::greedy_refine(st); break;
      case RefineStrategy::ProjectFlip: refine2d::project_flip(st); break;
      case RefineStrategy::Projection: refine2d::projection_refine(st); break;
    }
  };
  run();
  // Rescue: a side can be left violated when no double point near the strategy's choice passes its exact checks
  // (greedy: every candidate lands in a subsegment's disk; any strategy: the point coincides with a vertex).
  // Split such sides near their midpoint and run the strategy again; at most 3 rounds.
  for (int round = 0; round < 3 && st.budget_left(); ++round) {
    std::vector<Side> stuck;
    for (const Side& side : st.boundary_sides())
      if (st.is_violated(side)) stuck.push_back(side);
    if (stuck.empty()) break;
    st.fallback_used = true;
    for (const Side& side : stuck) {
      refine2d::Point p;
      auto valid = [&](const refine2d::Point& c) { return st.splittable(side, c); };
      if (st.budget_left() && st.is_violated(side) &&
          refine2d::pick_point(side.s->point(), side.e->point(), 0.5, valid, p))
        st.split(side, p);
    }
    run();
  }

  Refine2DResult r;
  r.mesh = cdt::to_mesh(st.cdt, options.threads);
  // The exact certificate of the mesh as returned: the obtuse sides of boundary edges and of interfaces (each side
  // of a constrained segment or region jump checked on its own).
  r.obtuse_boundary_sides = count_obtuse_boundary_sides(r.mesh, options.threads);
  r.steiner_points = st.placed;
  r.max_steiner = budget;
  for (const auto& e : st.edges) r.lower_bound += e.lower_bound;
  r.edges = st.edges;
  r.diagnosis = refine2d::diagnose(st);
  r.status = r.obtuse_boundary_sides == 0 ? RefineStatus::Converged
             : st.budget_left()                 ? RefineStatus::Stalled
                                                : RefineStatus::BudgetExhausted;
  if (r.status == RefineStatus::Converged && r.steiner_points == r.lower_bound)
    r.optimal = 1;
  else if (r.status == RefineStatus::Converged && options.strategy == RefineStrategy::Greedy && st.convex_polygon &&
           !st.fallback_used)
    r.optimal = 1;  // Theorem 3
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace nonobtuse
