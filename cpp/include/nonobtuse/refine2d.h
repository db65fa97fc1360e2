// Nonobtuse boundary refinement: Steiner points on boundary edges so that every boundary triangle of the
// constrained Delaunay triangulation is nonobtuse at the angle opposite its boundary edge.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "nonobtuse/quality2d.h"
#include "nonobtuse/refine2d_diagnosis.h"
#include "nonobtuse/types.h"
#include "nonobtuse/validate2d.h"

namespace nonobtuse {

enum class RefineStrategy : std::int8_t {
  Greedy = 0,       // sensitive Greedy-Refine (paper sections 4.1-4.4): longest empty subsegment, forbidden intervals
  ProjectFlip = 1,  // baseline (paper section 3.3): foot of the obtuse apex, constrained Delaunay restored by flips
  Projection = 2,   // baseline (paper section 4.1): foot of every encroaching visible vertex, repeated
};

struct Refine2DOptions {
  RefineStrategy strategy = RefineStrategy::Greedy;
  // Maximum number of Steiner points; < 0 selects default_steiner_budget(n) for n input points.
  long long max_steiner = -1;
  // Threads for the passes over the whole mesh of large inputs (the lower bound and the certificate): 1, or 2 and
  // more (two are used). The result is the same for any value.
  int threads = 2;
  // After every split, check that the triangulation is valid and constrained Delaunay everywhere and that the
  // maintained domain marks equal a recomputation (InternalError otherwise): O(n) per split, for tests (debug
  // builds always check).
  bool check_every_split = false;
  // Interior quality and size (off by default): after the boundary refinement, Ruppert/Chew refinement of the
  // interior that keeps every boundary side nonobtuse (quality2d.h); the subsegments it splits, and the sides those
  // splits leave obtuse, get midpoints or concentric shells whatever the strategy.
  Quality2DOptions quality;
};

// Per boundary edge of the input: a constrained edge of the input's CDT with the domain on one side (a boundary
// edge) or on both (an interface or dangling segment, listed once, as (min, max)).
struct BoundaryEdgeStats {
  Segment edge;            // input point indices (a, b), the domain on the left of a -> b
  int steiner_points = 0;  // Steiner points placed on it
  int lower_bound = 0;     // single-edge Greedy-Refine against the input vertices (see lower_bound_per_edge)
};

struct Refine2DResult {
  Mesh2 mesh;  // the constrained Delaunay triangulation of the refined domain (input points first)
  RefineStatus status = RefineStatus::Converged;  // never MinLengthReached (2D has no length limit)
  long long steiner_points = 0;
  long long max_steiner = 0;  // the budget used (options.max_steiner, its default resolved)
  long long lower_bound = 0;
  int optimal = -1;  // 1 certainly optimal, 0 certainly not, -1 unknown (see refine's docstring)
  // Exact certificate of `mesh` as returned: constraint sides (each side of an interface or dangling segment on
  // its own) whose triangle is obtuse opposite the constrained edge. 0 whenever status == Converged.
  long long obtuse_boundary_sides = 0;
  // The largest distance of a Steiner point off its input segment, over the segment's length (0 when every point
  // lies exactly on its segment; rounding to doubles far from the origin moves points off). Float, for reporting.
  double max_steiner_offset = 0.0;
  std::vector<BoundaryEdgeStats> edges;
  Refine2DDiagnosis diagnosis;  // where the Steiner points went (junctions, input angles, propagation)
  // The interior refinement (all zero unless options.quality is enabled). steiner_points counts the points on
  // constraints only; quality.interior_points the others. With quality enabled, status is Converged only when the
  // certificate holds and no bad triangle is left outside small-input-angle regions (else BudgetExhausted when a
  // budget is spent, Stalled otherwise).
  Quality2DStats quality;
  double seconds = 0.0;
};

// Default Steiner budget for n input points: 10 n + 1000. On one edge greedy needs at most one point per
// encroaching vertex (projecting every encroacher is a solution and greedy is optimal, Theorem 2), and
// Project-Flip O(n) points on polygons (paper, section 3.3), so well-posed inputs need far fewer; the budget is
// for interference cascades (paper, Figure 6), where no polynomial bound is known.
long long default_steiner_budget(std::size_t n_points);

// Refines every constraint of `domain` (validated by the caller): boundary segments (the domain on one side, or
// the convex hull when domain.convex_hull_boundary) on their domain side, interfaces and dangling segments (the
// domain on both sides) on both sides, each side nonobtuse on its own. Steiner points go only on
// constraint subsegments; each is a rounded construction checked by exact predicates (see greedy_refine.cpp).
// The result's certificate is the exact check of the returned mesh (every side of every constraint);
// `diagnosis` says which junctions and input angles drew the points and how far one violation propagated.
//
// optimal: 1 when steiner_points == lower_bound (the bound is then attained); otherwise, for the Greedy strategy
// on a convex polygon (no holes, no interior points or constraints) that converged without a fallback step, 1 by
// Theorem 3 of the paper; -1 (unknown) in every other case (0 is never claimed: the optimum is not computed).
// Throws InvalidInput when the domain cannot be triangulated (crossing constraints, no triangle).
// Cost: O(n log n) to triangulate, plus per Steiner point the walk over the triangles meeting the diametral
// disk of the refined subsegment.
// triangulation: the one inspect_domain kept while validating; when it triangulates this very domain (compared
// exactly, O(n)) refine takes it over instead of triangulating again (the result is the same, the cost of the
// triangulation saved). Empty afterwards in any case.
Refine2DResult refine(const Domain2& domain, const Refine2DOptions& options = {},
                      Triangulation2* triangulation = nullptr);

// Benchmark peer: the Steiner points CGAL::make_conforming_Gabriel_2 adds to the domain's constrained Delaunay
// triangulation (every constrained edge Gabriel on both sides, outside the domain included).
long long conforming_gabriel_steiner_points(const Domain2& domain);

const char* to_string(RefineStrategy s);

}  // namespace nonobtuse
