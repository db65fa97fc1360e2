// Internal: the input checks of refine_interior and the canonical rows that keep its output independent of the
// triangulation's history (quality3d_interior.cpp).
#pragma once
#include <array>

#include "nonobtuse/quality3d.h"

namespace nonobtuse::quality3d {

std::array<int, 4> sorted_corners(std::array<int, 4> k);
// A subfacet (a, b, c) or subsegment (a, b, -1) with its corners sorted (-1 kept last): one row per boundary element.
std::array<int, 3> element(std::array<int, 3> e);
// The least of the 12 even permutations of t (they keep its orientation): one row per tet, whatever its history.
std::array<int, 4> canonical_tet(const std::array<int, 4>& t);
// Throws InvalidInput for indices out of range, face_facets of the wrong length, labels without a bound.
void check_input(const InteriorMesh& mesh, const InteriorBounds& bounds);

}  // namespace nonobtuse::quality3d
