// Exact predicates on 3D piecewise linear complexes (PLCs), used to load and validate surface inputs.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "nonobtuse/types.h"

namespace nonobtuse {

using PlcPoint = Point3;
using PlcTriangle = std::array<int, 3>;

// Exact sign of orient3d(a, b, c, d) for every row (a, b, c, d) of `quads`: +1 when d is on the positive side
// of the plane through a, b, c (CGAL::orientation, POSITIVE), 0 when the four points are coplanar, -1 else.
// Cost: O(rows).
std::vector<std::int8_t> orient3d_signs(const std::vector<PlcPoint>& points,
                                        const std::vector<std::array<int, 4>>& quads);

// Exact collinearity of every row (a, b, c) of `triples` (CGAL::collinear): 1 when collinear, else 0.
std::vector<std::int8_t> collinear_flags(const std::vector<PlcPoint>& points,
                                         const std::vector<PlcTriangle>& triples);

// Pairs (i, j), i < j, of triangles of a triangle soup that intersect other than in their shared vertices and
// shared edge (exact: CGAL::do_intersect on the exact-predicates kernel). Triangles must be non-degenerate and
// pairwise distinct (validate that first). Stops after `max_pairs` pairs. Candidate pairs come from a box
// intersection sweep (CGAL::box_intersection_d). Cost: O(m log m + candidate pairs).
std::vector<std::array<int, 2>> triangle_soup_self_intersections(const std::vector<PlcPoint>& points,
                                                                 const std::vector<PlcTriangle>& triangles,
                                                                 std::size_t max_pairs);

// Finite cells of the Delaunay tetrahedralization of `points` (CGAL Delaunay_triangulation_3, exact predicates),
// as indices into `points`, positively oriented. Throws InvalidInput when two points coincide (the cell would
// lose an index). Cost: O(n log n) expected.
std::vector<std::array<int, 4>> delaunay_tetrahedra(const std::vector<PlcPoint>& points);

}  // namespace nonobtuse
