// Internal: one pass of the Gabriel refinement of a PLC (gabriel3d_refine_once.cpp; its Refiner is in
// gabriel3d_refiner.h). The strategy that chooses and combines passes is in gabriel3d_strategy.cpp.
#pragma once
#include <functional>

#include "nonobtuse/gabriel3d.h"

namespace nonobtuse::gabriel3d {

// The first pass's cascade floor (refine_gabriel, gabriel3d_strategy.cpp): a pass stops (min_length_reached) once a
// split leaves a subsegment shorter. The floor costs a Delaunay tetrahedralization of the input (its closest pair):
// it is evaluated only once a subsegment comes under `bound`, a cheap length >= the floor, and converging passes
// rarely come that close. bound 0: no floor; evaluate() returns the floor, 0 for none.
struct CascadeFloor {
  double bound = 0.0;
  std::function<double()> evaluate;
};

// One pass from the input with `options` (defaults resolved) and options.split's rule for the subsegments: refine the
// subfacets, restrict the Delaunay tetrahedralization, check it exactly, repair what the check finds, until clean or
// a stop (max_steiner, max_work, min_length, time_limit, stalled). ignore_frame_artifacts: do not count points of a
// facet that its 2D triangulation sees outside a subfacet's circumcircle as encroaching it (see
// Refiner::subfacet_encroached). protect: protecting balls at the apex vertices (gabriel3d_protect.h). mirror:
// mirrored facet meshes along small-dihedral segments (gabriel3d_mirror.h). stations: where the input has groups of
// near-parallel close segments (gabriel3d_stations.h), stations on them instead of protecting balls. cascade_floor: the
// first pass's guard (refine_gabriel).
// Fills everything of the result but strategy, other_attempt, max_steiner, min_length and max_work.
Refine3DResult refine_once(const PLC3& plc, const Refine3DOptions& options, bool ignore_frame_artifacts,
                           bool protect, bool mirror, bool stations = false, const CascadeFloor& cascade_floor = {});

}  // namespace nonobtuse::gabriel3d
