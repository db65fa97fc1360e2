// Exact signs of the 3D control-volume (two-point flux) coupling coefficients of a tetrahedral mesh.
#pragma once
#include <array>
#include <vector>

#include "nonobtuse/types.h"

namespace nonobtuse {

// The Voronoi face dual to edge e = (i, j), clipped to the mesh, is the union over the tets T around e of the
// quadrilateral (M, C_f1, C_T, C_f2): M the midpoint of e, C_f1 and C_f2 the circumcenters of the two faces of T
// that contain e, C_T the circumcenter of T (the per-tet decomposition of LaGriT and FEHM). Its signed area A_e,
// measured along i -> j, is the sum of the pieces; the coupling coefficient is A_e / |e| and the matrix entry is
// -A_e / |e|, so the control-volume matrix is an M-matrix exactly when every A_e >= 0.
struct DualAreaSigns {
  std::vector<Segment> edges;  // every edge of the mesh, (a, b) with a < b, sorted
  std::vector<int> signs;      // exact sign of A_e: -1, 0 or +1, one per edge
  int exact_evaluations = 0;   // edges the interval filter could not decide (evaluated exactly)
};

// The exact sign of every dual area A_e. sign(A_e) = sign(sum over T of ((C_f1 - M) x (C_T - M) +
// (C_T - M) x (C_f2 - M)) . (j - i)), the circumcenters taken as exact rational functions of the coordinates as
// stored: evaluated in interval arithmetic and, when the interval contains 0, exactly (multiprecision floating
// point, no division: the pieces are put over one positive common denominator).
// tets: indices into points, each positively oriented (CGAL orientation, exact); InvalidInput on an index out
// of range or a tet that is not positively oriented (flat or inverted), naming the tet and its vertices.
// Cost: O(t log t) for t tets (the sort of the 6 t edge pieces), plus exact arithmetic for undecided edges only.
DualAreaSigns dual_area_signs(const std::vector<Point3>& points, const std::vector<std::array<int, 4>>& tets);

}  // namespace nonobtuse
