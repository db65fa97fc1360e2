// Internal: the Delaunay tetrahedralization of the interior quality refinement (quality3d_interior.cpp), its cells
// labelled with their regions (-1: outside the domain).
#pragma once
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <array>
#include <vector>

#include "gabriel3d_plc.h"
#include "nonobtuse/types.h"

namespace nonobtuse::quality3d {

using Vb = CGAL::Triangulation_vertex_base_with_info_3<int, gabriel3d::K>;  // info: the point's index
using Cb = CGAL::Triangulation_cell_base_with_info_3<int, gabriel3d::K,
                                                     CGAL::Delaunay_triangulation_cell_base_3<gabriel3d::K>>;
using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb>;
using DT = CGAL::Delaunay_triangulation_3<gabriel3d::K, Tds>;
using Cell = DT::Cell_handle;
using Vertex = DT::Vertex_handle;

// The point indices of c's corners, sorted.
std::array<int, 4> corners(Cell c);
// Floods the labels of the cells labelled (>= 0) from stack into the unlabelled finite cells (-1) of dt across faces
// that are not subfacets (faces).
void flood_labels(DT& dt, const std::vector<Triangle>& faces, std::vector<Cell> stack);
// Domain cells: those of the input tets (with their labels), then by flood fill across faces that are not
// subfacets (a Delaunay tetrahedralization with every subfacet as a face holds the same domain split differently
// where points are cospherical); the others -1.
void label_cells(DT& dt, const std::vector<std::array<int, 4>>& tets, const std::vector<int>& tet_labels,
                 const std::vector<Triangle>& faces);

}  // namespace nonobtuse::quality3d
