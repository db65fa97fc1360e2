// Shared by the 2D binding files: domain and mesh conversion.
#pragma once
#include "convert.h"

namespace nonobtuse::bindings {
py::dict mesh_to_dict(const Mesh2& mesh);
Domain2 domain_from_arrays(const DoubleArray& points, const IndexArray& segments, const DoubleArray& holes,
                           const DoubleArray& region_seeds, bool convex_hull_boundary);
}  // namespace nonobtuse::bindings
