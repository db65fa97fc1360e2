// Internal: interior quality refinement on the refinement state (quality2d.cpp).
#pragma once
#include "nonobtuse/quality2d.h"
#include "refine2d_state.h"

namespace nonobtuse::refine2d {

// Inserts p, strictly inside the domain face `located` or on one of its unconstrained edges, as an interior
// vertex (index n_input + number of vertices added so far); its faces get located's domain marks. nullptr when p
// is not there (a vertex, a constrained edge, outside located). Cost: the Delaunay cavity of p.
Vertex_handle insert_interior(State& st, const Point& p, Face_handle located);

// Ruppert/Chew refinement of the domain's bad triangles (see Quality2DOptions). First every boundary side with an
// obtuse apex is split (midpoint, or nearest_shell at an acute input angle; the greedy rule at a corner of two
// boundary edges below 60 degrees; nothing when a strategy already refined the boundary), then circumcenters or
// off-centers go in unless they lie in the open diametral disk of a constraint subsegment they would see (for a
// skinny triangle, the point of its selection disk farthest from such subsegments is tried next); that
// subsegment is split instead (nearest_shell at acute input angles, else its midpoint), and so is every boundary
// side a split leaves obtuse (the greedy rule where no such point passes the exact checks), so every boundary
// side keeps a nonobtuse apex. Stops when no bad triangle is left outside small-input-angle regions, or at a
// budget (options.max_interior, or the state's Steiner budget for the subsegment splits). When none is left, the
// boundary Steiner points no longer needed are removed (prune_boundary_points) and the added vertices renumbered
// (compact_added). Returns what it did and left.
Quality2DStats refine_quality(State& st, const Quality2DOptions& options);

}  // namespace nonobtuse::refine2d
