// Peers for benchmarks only: what other meshers do with the same input.
#pragma once
#include <cstddef>

#include "nonobtuse/types.h"

namespace nonobtuse {

// CGAL's make_conforming_Gabriel_2 (CGAL/Triangulation_conformer_2.h) on the constrained Delaunay triangulation of
// `domain` (its points and segments, plus the convex hull edges when domain.convex_hull_boundary): every
// constrained edge is split at midpoints (concentric shells near shared vertices) until every constrained
// subsegment is Gabriel, i.e. its open diametral disk is empty on both sides, exterior and holes included.
// Returns the number of vertices of the result (input points + Steiner points). No budget: CGAL's loop
// terminates for PSLGs with angles of at least 60 degrees between constraints and usually beyond; for benchmarks only.
// Throws InvalidInput as cdt::build does.
std::size_t conforming_gabriel_points(const Domain2& domain);

}  // namespace nonobtuse
