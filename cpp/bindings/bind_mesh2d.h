// Shared by the 2D binding files: domain conversion and the Mesh2D class.
#pragma once
#include "convert.h"

namespace nonobtuse::bindings {
Domain2 domain_from_arrays(const DoubleArray& points, const IndexArray& segments, const DoubleArray& holes,
                           const DoubleArray& region_seeds, bool convex_hull_boundary);
}  // namespace nonobtuse::bindings
