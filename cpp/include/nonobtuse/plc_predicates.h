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
// pairwise distinct (validate that first). The `max_pairs` smallest such pairs. Candidate pairs come from a box
// intersection sweep (CGAL::box_intersection_d), every one tested. Cost: O(m log m + candidate pairs).
std::vector<std::array<int, 2>> triangle_soup_self_intersections(const std::vector<PlcPoint>& points,
                                                                 const std::vector<PlcTriangle>& triangles,
                                                                 std::size_t max_pairs);

// Finite cells of the Delaunay tetrahedralization of `points` (CGAL Delaunay_triangulation_3, exact predicates),
// as indices into `points`, positively oriented. Throws InvalidInput when two points coincide (the cell would
// lose an index). Cost: O(n log n) expected.
std::vector<std::array<int, 4>> delaunay_tetrahedra(const std::vector<PlcPoint>& points);

// delaunay_tetrahedra(points) and, per triangle (indices into points), whether it is a face of that
// tetrahedralization (exact). Throws as delaunay_tetrahedra. Cost: O(n log n) expected plus O(1) per triangle.
struct DelaunayFaces {
  std::vector<std::array<int, 4>> cells;
  std::vector<char> is_face;
};
DelaunayFaces delaunay_faces(const std::vector<PlcPoint>& points, const std::vector<PlcTriangle>& triangles);

// An edge {a, b} (a < b) of `triangles` traversed more often in one direction than in the other, the smallest
// such, or {-1, -1} when there is none: the triangles then form a closed oriented surface (a 2-cycle; a closed
// 2-manifold consistently oriented, several of them, or nested shells), around which the winding number is an
// integer defined at every point off the surface. Cost: O(m log m).
std::array<int, 2> unbalanced_edge(const std::vector<PlcTriangle>& triangles);

// The winding number of the oriented triangles around each query point q, exactly: the signed count of
// triangles met by the vertical ray (+z) from q + (e, e^2, e^3), e > 0 infinitesimal (simulation of simplicity,
// so a query on the surface gets the number of the side the perturbation takes it to). +1 inside an outward
// oriented closed surface, 0 outside. For a closed oriented surface (unbalanced_edge == {-1, -1}) it is the
// generalized winding number of the perturbed point; otherwise it depends on the ray. Every sign is an exact
// predicate. Cost: O(m + k) to bucket the triangles by their xy boxes on a grid of about m columns (k bucket
// entries), plus per query the triangles of its column (a few on surfaces without long vertical stacks); queries
// run on two threads from 2^16.
std::vector<int> surface_winding_numbers(const std::vector<PlcPoint>& points,
                                         const std::vector<PlcTriangle>& triangles,
                                         const std::vector<PlcPoint>& queries);

// The cells of delaunay_tetrahedra(points) whose centroid (rounded to doubles, perturbed as in
// surface_winding_numbers) has a non-zero winding number with respect to the closed oriented surface
// `triangles` (check unbalanced_edge first): the cells inside the surface; a cell crossed by the surface is
// inside when its centroid is. Sorted. Cost: the Delaunay tetrahedralization plus one query per cell.
std::vector<std::array<int, 4>> delaunay_cells_inside_surface(const std::vector<PlcPoint>& points,
                                                              const std::vector<PlcTriangle>& triangles);
// The same of given cells (e.g. PlcDelaunay::delaunay_cells): those whose centroid the surface winds around.
std::vector<std::array<int, 4>> cells_inside_surface(const std::vector<PlcPoint>& points,
                                                     const std::vector<PlcTriangle>& triangles,
                                                     const std::vector<std::array<int, 4>>& cells);

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
  // When a facet of one triangle is not a Delaunay face: every finite Delaunay cell (sorted, as
  // delaunay_tetrahedra), for cells_inside_surface; tets, boundary_faces and their data are then empty and
  // uncovered_facets are the one-triangle facets that are not Delaunay faces (facets of several triangles are
  // not examined). Empty otherwise.
  std::vector<Tetrahedron> delaunay_cells;
};

// Regions are the components of the cells connected across faces on no facet, except the unbounded one and
// those of hole seeds, so internal facets (domain on both sides), several regions, non-manifold edges and
// vertices and dangling facets are all handled; facet orientation is not used. Every decision is exact: a
// Delaunay face is on a facet when it is a subfacet (the facet's constrained Delaunay triangulation) or, for a
// facet with cospherical points, when its corners are facet vertices and its centroid lies inside the facet;
// a facet is covered when its faces in the result are as many as its subfacets (any two triangulations of the
// facet's vertices and edges have the same number of triangles). Throws InvalidInput on malformed PLCs (as
// refine_gabriel). The one-triangle facets (most of a scanned surface's) are first checked without building the
// facets' triangulations: when one is not a Delaunay face it is not covered, and the result says so at once
// (delaunay_cells); otherwise the flood fill above runs.
// Cost: O(n log n) expected for n points, plus O(f log f) for the facets' triangulations.
PlcDelaunay delaunay_restricted_to_plc(const PLC3& plc);

}  // namespace nonobtuse
