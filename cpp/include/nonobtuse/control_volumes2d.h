// Exact signs of the 2D control-volume (two-point flux) coupling coefficients.
#pragma once
#include <vector>

#include "nonobtuse/check2d.h"
#include "nonobtuse/types.h"

namespace nonobtuse {

// The coupling coefficient of edge e = (a, b) in the control-volume (finite-volume, Voronoi-dual) discretisation
// of -div(k grad u) is  T_e = sum over the triangles t on each side of e of k_t * cot(angle of t opposite e) / 2
// (the signed length of the Voronoi segment dual to e, each part weighted by its triangle's conductivity,
// divided by |e|). The matrix entry is A_ab = -T_e; A is an M-matrix exactly when every T_e >= 0.
//
// Returns, for each entry of `edges` (from classify_edges(mesh)), the exact sign of T_e: -1, 0 or +1.
// cot(angle at c of triangle (a, b, c)) = dot(a - c, b - c) / cross(a - c, b - c) with cross > 0 for a
// counter-clockwise triangle, so sign(T_e) = sign(k_1 dot_1 cross_2 + k_2 dot_2 cross_1) (a single side: sign of
// dot_1). This is evaluated in interval arithmetic and, when the interval contains 0, in exact rationals on the
// doubles as stored.
// conductivity: one value per triangle, each finite and > 0 (InvalidInput otherwise); empty means k = 1.
// Cost: O(E) for E edges (rational arithmetic only for near-zero coefficients).
std::vector<int> coupling_signs(const Mesh2& mesh, const std::vector<EdgeReport>& edges,
                                const std::vector<double>& conductivity);

}  // namespace nonobtuse
