// Internal: a tetrahedron's circumsphere computed exactly and rounded, for tets that are flat or nearly so in
// floating point (the quality measure, tet_shape in quality3d_shape.cpp, and the control volumes,
// control_volumes3d.cpp).
#pragma once
#include "nonobtuse/types.h"

namespace nonobtuse {

struct Circumsphere {
  Point3 center;          // rounded; +-inf when beyond the double range
  double squared_radius;  // rounded; +inf when beyond the double range
};

// The circumsphere of tet abcd (not coplanar) in CGAL's exact kernel, each number rounded from its exact value
// (within an ulp; CGAL::to_double of a lazy number would stop at a relative precision of 1e-5).
Circumsphere exact_circumsphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

}  // namespace nonobtuse
