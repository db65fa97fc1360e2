// Internal: the Delaunay tetrahedralization of a PLC's points, kept between the question which triangles are its
// faces and the restriction to the PLC's regions, so that it is built once for both.
#pragma once
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <array>
#include <cstddef>
#include <vector>

#include "nonobtuse/plc_predicates.h"

namespace nonobtuse {

// Vertex info: the point's index.
using PointsDelaunay = CGAL::Delaunay_triangulation_3<
    CGAL::Epick, CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_with_info_3<int, CGAL::Epick>>>;

// The Delaunay tetrahedralization of `points` (exact predicates). Throws InvalidInput when two points coincide.
PointsDelaunay points_delaunay(const std::vector<PlcPoint>& points);

// Per triangle (indices into the `points` dt was built from) whether it is a face of dt, and dt's finite cells in
// CGAL's order (sort_cells puts them in delaunay_faces' order). One pass over the cells. Cost: O(cells).
DelaunayFaces faces_and_cells(const PointsDelaunay& dt, std::size_t points, const std::vector<PlcTriangle>& triangles);

// Sorts cells (indices below `points`) lexicographically.
void sort_cells(std::size_t points, std::vector<std::array<int, 4>>& cells);

namespace gabriel3d {
struct PlcState;
struct Restricted;
// restrict_delaunay(s, plc) (gabriel3d_plc.h) on `built`, a Delaunay tetrahedralization of s.points (vertex info:
// the index into s.points) already built: it is copied, not rebuilt (O(cells), no predicate), then cleared.
Restricted restrict_delaunay(const PlcState& s, const PLC3& plc, PointsDelaunay&& built);
}  // namespace gabriel3d

}  // namespace nonobtuse
