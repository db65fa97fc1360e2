// Internal: removal of boundary Steiner points after the interior quality refinement (quality2d_prune.cpp).
#pragma once
#include <functional>
#include <vector>

#include "refine2d_state.h"

namespace nonobtuse::refine2d {

// Removes boundary Steiner point v (exactly two constrained edges at it, v -> a and v -> b, on one input edge) and
// joins a and b by one subsegment; the faces filling v's old star get the domain marks of the side of a -> b they
// lie on. Returns those faces, or nothing (and changes nothing) when v is no such point. Its slot in added() is
// null until compact_added. Cost: the star of v.
std::vector<Face_handle> remove_boundary_point(State& st, Vertex_handle v);

// Drops the null slots of added() and renumbers the vertices after them (their info()). Returns the map from old
// position in added() to new position (-1: removed). Cost: O(added()).
std::vector<int> compact_added(State& st);

// After a converged quality refinement: removes every boundary Steiner point whose removal keeps (1) the joined
// subsegment's apexes nonobtuse (exact: no vertex of the star in its open diametral disk on a domain side), (2)
// every new domain face good (`bad` false) and (3) every constrained side of a new domain face with a nonobtuse
// apex (exact). A removal that fails (2) or (3) is undone by split at the same point; `added` is told of the new
// vertex and must empty the state's work queue (split queues sides, and a side naming a point removed later would
// dangle): InternalError when a removal finds it not empty. Passes over the points in insertion order until one
// removes nothing. Returns how many were removed.
long long prune_boundary_points(State& st, const std::function<bool(Face_handle)>& bad,
                                const std::function<void(Vertex_handle)>& added);

}  // namespace nonobtuse::refine2d
