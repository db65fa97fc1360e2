// nonobtuse::refine: strategy dispatch, the midpoint rescue, the optimality flag and the exact certificate.
#include <algorithm>
#include <chrono>
#include <cmath>

#include "lower_bound.h"
#include "nonobtuse/check2d.h"
#include "quality2d.h"
#include "refine2d_strategies.h"
#include "split_point.h"
#include "stop_reason2d.h"

namespace nonobtuse {
namespace {

using refine2d::Side;
using refine2d::State;

// Refine2DResult::max_steiner_offset: for each Steiner point p on input segment [a, b], the distance from p to
// [a, b] over |b - a|, in doubles relative to a (the differences p - a are exact for points near the segment,
// Sterbenz; CGAL's point-segment distance goes through the line's equation, whose constant term cancels
// catastrophically far from the origin).
double max_steiner_offset(const Mesh2& mesh, const State& st) {
  double worst = 0.0;
  for (std::size_t i = st.n_input(); i < mesh.points.size(); ++i) {
    const int on = st.steiner_edge(static_cast<int>(i));
    if (on < 0) continue;  // an interior point
    const Segment& edge = st.edges()[on].edge;
    const Point2 &a = st.domain().points[edge[0]], &b = st.domain().points[edge[1]], &p = mesh.points[i];
    const double dx = b.x - a.x, dy = b.y - a.y, vx = p.x - a.x, vy = p.y - a.y, length2 = dx * dx + dy * dy;
    const double along = vx * dx + vy * dy;
    const double offset = along <= 0        ? std::hypot(vx, vy) / std::sqrt(length2)
                          : along >= length2 ? std::hypot(p.x - b.x, p.y - b.y) / std::sqrt(length2)
                                             : std::abs(vx * dy - vy * dx) / length2;
    worst = std::max(worst, offset);
  }
  return worst;
}

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

Refine2DResult refine(const Domain2& domain, const Refine2DOptions& options, Triangulation2* triangulation) {
  auto start = std::chrono::steady_clock::now();
  long long budget = options.max_steiner < 0 ? default_steiner_budget(domain.points.size()) : options.max_steiner;
  State st(domain, budget, triangulation);
  st.set_check_every_split(options.check_every_split || State::kCheckEverySplit);

  refine2d::lower_bound_per_edge(st, options.threads);

  auto run = [&] {
    switch (options.strategy) {
      case RefineStrategy::Greedy: refine2d::greedy_refine(st); break;
      case RefineStrategy::ProjectFlip: refine2d::project_flip(st); break;
      case RefineStrategy::Projection: refine2d::projection_refine(st); break;
    }
  };
  // With a quality option the greedy strategy's boundary is left to the quality refinement (Ruppert's midpoint
  // splits, greedy only where they fail; quality2d.cpp says why): the minimal boundary's short pieces would
  // force the interior to match them.
  const bool boundary_by_quality = options.quality.enabled() && options.strategy == RefineStrategy::Greedy &&
                                   !options.quality.minimal_boundary_first;
  if (!boundary_by_quality) run();
  // Rescue: a side can be left violated when no double point near the strategy's choice passes its exact checks
  // (greedy: every candidate lands in a subsegment's disk; any strategy: the point coincides with a vertex).
  // Split such sides near their midpoint and run the strategy again; at most 3 rounds.
  for (int round = 0; round < 3 && st.budget_left() && !boundary_by_quality; ++round) {
    std::vector<Side> stuck;
    for (const Side& side : st.boundary_sides())
      if (st.is_violated(side)) stuck.push_back(side);
    if (stuck.empty()) break;
    st.note_fallback();
    for (const Side& side : stuck) {
      refine2d::Point p;
      auto valid = [&](const refine2d::Point& c) { return refine2d::splittable(st, side, c); };
      if (st.budget_left() && st.is_violated(side) &&
          refine2d::pick_point(side.s->point(), side.e->point(), 0.5, valid, p))
        refine2d::split(st, side, p);
    }
    run();
  }

  Refine2DResult r;
  if (options.quality.enabled()) r.quality = refine2d::refine_quality(st, options.quality);
  r.mesh = cdt::to_mesh(st.cdt(), options.threads);
  // The exact certificate of the mesh as returned: the obtuse sides of boundary edges and of interfaces (each side
  // of a constrained segment or region jump checked on its own).
  r.obtuse_boundary_sides = count_obtuse_boundary_sides(r.mesh, options.threads);
  r.steiner_points = st.placed();
  r.max_steiner = budget;
  for (const auto& e : st.edges()) r.lower_bound += e.lower_bound;
  r.edges = st.edges();
  r.max_steiner_offset = max_steiner_offset(r.mesh, st);
  r.diagnosis = refine2d::diagnose(st);
  const bool budgets_left = st.budget_left() && r.quality.interior_points < r.quality.interior_budget;
  r.status = r.obtuse_boundary_sides == 0 && r.quality.bad_triangles == 0 ? RefineStatus::Converged
             : r.obtuse_boundary_sides > 0 && st.budget_left()         ? RefineStatus::Stalled
             : r.obtuse_boundary_sides > 0 || !budgets_left            ? RefineStatus::BudgetExhausted
                                                                        : RefineStatus::Stalled;
  r.diagnosis.stop_reason = refine2d::stop_reason(r, options.quality.enabled());
  if (r.quality.boundary_splits > 0)
    r.optimal = -1;  // interior quality asked for more boundary points than the boundary problem needs
  else if (r.status == RefineStatus::Converged && r.steiner_points == r.lower_bound)
    r.optimal = 1;
  else if (r.status == RefineStatus::Converged && options.strategy == RefineStrategy::Greedy && st.convex_polygon() &&
           !st.fallback_used())
    r.optimal = 1;  // Theorem 3
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace nonobtuse
