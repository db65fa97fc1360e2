#pragma once
#include "nonobtuse/types.h"

namespace nonobtuse {

// Constrained Delaunay triangulation of `domain` (CGAL Constrained_Delaunay_triangulation_2, exact predicates).
// Triangles outside the domain (exterior, hole seeds) are dropped; regions are flood-filled from their seeds
// across unconstrained edges. Throws InvalidInput when constraints intersect away from their endpoints (the
// caller validates first; this is the backstop) or when the domain has no triangle.
// Cost: O(n log n) expected.
Mesh2 triangulate(const Domain2& domain);

}  // namespace nonobtuse
