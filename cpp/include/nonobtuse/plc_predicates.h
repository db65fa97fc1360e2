// Exact predicates on 3D piecewise linear complexes (PLCs), used to load and validate surface inputs.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "nonobtuse/gabriel3d.h"
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

// The Delaunay tetrahedralization of a PLC's vertices (no Steiner point) restricted to the PLC's interior.
struct PlcDelaunay {
  std::vector<Tetrahedron> tets;  // positively oriented, sorted
  // Per tet: the attribute of the region seed in its region; without seeds, its region's number 1, 2, ... in
  // the order of the regions' smallest tets.
  std::vector<double> tet_regions;
  std::vector<PlcTriangle> boundary_faces;  // the Delaunay faces on facets next to an inside tet, each once
  std::vector<int> face_markers;            // input facet id of each
  // Input facet ids of the facets these faces do not cover (a Delaunay edge crosses the facet, or it has no
  // inside tet on either side). Empty iff the tetrahedralization conforms to every facet; the tets are then the
  // PLC's regions exactly. Otherwise the flood fill that found them may have leaked: tets are unreliable.
  std::vector<int> uncovered_facets;
};

// Regions are the components of the cells connected across faces on no facet, except the unbounded one and
// those of hole seeds, so internal facets (domain on both sides), several regions, non-manifold edges and
// vertices and dangling facets are all handled; facet orientation is not used. Every decision is exact: a
// Delaunay face is on a facet when it is a subfacet (the facet's constrained Delaunay triangulation) or, for a
// facet with cospherical points, when its corners are facet vertices and its centroid lies inside the facet;
// a facet is covered when its faces in the result are as many as its subfacets (any two triangulations of the
// facet's vertices and edges have the same number of triangles). Throws InvalidInput on malformed PLCs (as
// refine_gabriel). Cost: O(n log n) expected for n points, plus O(f log f) for the facets' triangulations.
PlcDelaunay delaunay_restricted_to_plc(const PLC3& plc);

}  // namespace nonobtuse
