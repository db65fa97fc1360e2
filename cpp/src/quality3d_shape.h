// Internal: a tetrahedron's circumcenter and circumradius for the interior quality refinement
// (quality3d_interior.cpp), robust where floating point cannot tell them.
#pragma once
#include "gabriel3d_plc.h"

namespace nonobtuse::quality3d {

using gabriel3d::P3;

struct TetShape {
  P3 center;              // the circumcenter, rounded
  double squared_radius;  // rounded; +inf when beyond the double range
  bool exact;             // computed exactly (the tet is flat or nearly so in floating point)
};

// The circumsphere of tet abcd (not coplanar: a cell of a Delaunay tetrahedralization). Floating point (CGAL's
// constructions) when the orientation determinant det = (b - a) . ((c - a) x (d - a)) is at least 2^-20 L^3, L
// the longest of b - a, c - a, d - a: its rounding error, a few ulps of L^3, is then below 2^-30 of it, and the
// center's and radius's relative errors alike. Else exactly (CGAL's exact kernel), then rounded: a tet flat in
// floating point (volume 0 or of the wrong sign by rounding: corners rounded onto a facet) gets its true ratio,
// finite or +inf, never NaN. The same rule as tet_circumspheres in nonobtuse/mesh3d/quality3d_rounds.py.
TetShape tet_shape(const P3& a, const P3& b, const P3& c, const P3& d);

// A tet's shape and size against the bounds (floating point but the circumsphere, see tet_shape).
struct TetQuality {
  double ratio;     // circumradius / shortest edge (+inf at most, never NaN)
  double shortest;  // shortest edge
  bool over;        // over a bound (radius_edge > 0 only) or of infinite ratio
  bool over_volume;
};
TetQuality tet_quality(const P3& a, const P3& b, const P3& c, const P3& d, double radius_edge, double volume_bound);

}  // namespace nonobtuse::quality3d
