// Internal: a tetrahedron's circumsphere computed exactly and rounded, for tets that are flat or nearly so in
// floating point (the quality measure, tet_shape in quality3d_shape.cpp, and the control volumes,
// control_volumes3d.cpp).
#pragma once
#include "nonobtuse/types.h"

namespace nonobtuse {

struct Circumsphere {
  Point3 center;          // rounded; +-inf when beyond the double range
  double squared_radius;  // rounded; +inf when beyond the double range
  double volume;          // (b - a) . ((c - a) x (d - a)) / 6, rounded
};

// The circumsphere and signed volume of tet abcd in CGAL's exact kernel, each number rounded to the nearest double
// from its exact value, ties to even (CGAL::to_double of a lazy number would stop at a relative precision of 1e-5).
// A coplanar tet: center and squared radius +inf, volume 0.
Circumsphere exact_circumsphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

}  // namespace nonobtuse
