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
struct ControlVolumes3D {
  std::vector<Segment> edges;       // every edge of the mesh, (a, b) with a < b, sorted
  std::vector<int> signs;           // exact sign of A_e: -1, 0 or +1, one per edge
  std::vector<double> dual_areas;   // A_e: the exact sign times the floating-point magnitude (0.0 where exactly 0)
  std::vector<double> lengths;      // |e|
  std::vector<double> volumes;      // per point: its Voronoi cell clipped to the mesh (0 for unused points)
  int exact_evaluations = 0;        // edges the interval filter could not decide (evaluated exactly)
  long flat_in_floating_point = 0;  // tets whose circumcenter denominator (b-a).((c-a)x(d-a)) is 0 in doubles
                                    // (their circumcenter is computed exactly, then rounded)
};

// The exact sign of every dual area A_e. sign(A_e) = sign(sum over T of ((C_f1 - M) x (C_T - M) +
// (C_T - M) x (C_f2 - M)) . (j - i)), the circumcenters taken as exact rational functions of the coordinates as
// stored: evaluated in interval arithmetic and, when the interval contains 0, exactly (multiprecision floating
// point, no division: the circumcenters of the tets around e, chained across their shared faces, which gives the
// same sum, put over one positive common denominator).
// The magnitudes are floating point: each tet's piece of A_e from the circumcenters in doubles, summed over the
// tets around e in tet order; a vertex's volume is the sum over its tets (in order) of the pyramids piece * |e| / 6
// over the pieces of its edges. The circumcenter of a tet that is flat in doubles (denominator 0, counted in
// flat_in_floating_point; its exact volume is positive) is computed exactly and rounded, so no piece is NaN.
// The arithmetic is the one of nonobtuse.mesh3d.control_volumes3d's numpy formulas, operation for operation.
// tets: indices into points, each positively oriented (CGAL orientation, exact); InvalidInput on an index out
// of range or a tet that is not positively oriented (flat or inverted), naming the tet and its vertices.
// Cost: O(t) for t tets (a counting sort of the 6 t edge pieces by their smaller end), plus exact arithmetic for
// undecided edges only; the interval filter and the exact arithmetic run on two threads.
ControlVolumes3D control_volumes3d(const std::vector<Point3>& points, const std::vector<std::array<int, 4>>& tets);

// control_volumes3d's edges, signs and exact_evaluations alone (the other fields empty): for callers that count
// wrong-signed couplings, without the floating-point pass over the tets (a quarter of control_volumes3d's time on
// the converged mesh of fandisk.off: 31 ms against 42).
ControlVolumes3D dual_area_signs(const std::vector<Point3>& points, const std::vector<std::array<int, 4>>& tets);

// The circumspheres and signed volumes of tets, for tets flat or nearly so in floating point (the exact route of the
// quality measures and of the Python control volumes): each number computed exactly (CGAL's exact kernel) and
// rounded to the nearest double, ties to even (as Python's float of a Fraction); +-inf beyond the double range.
// A coplanar tet gets +inf center coordinates and squared radius, and volume 0. volumes[t] is
// (b - a) . ((c - a) x (d - a)) / 6 for tet abcd. tets: indices into points (InvalidInput when out of range).
// Cost: exact arithmetic per tet (tens of microseconds each).
struct TetCircumspheres {
  std::vector<Point3> centers;
  std::vector<double> squared_radii;
  std::vector<double> volumes;
};
TetCircumspheres exact_tet_circumspheres(const std::vector<Point3>& points,
                                         const std::vector<std::array<int, 4>>& tets);

}  // namespace nonobtuse
