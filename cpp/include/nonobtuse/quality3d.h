// 3D interior quality: which candidate interior points would enter a boundary simplex's closed diametral sphere.
// A point outside every closed diametral sphere of the subfacets and subsegments can be added to a Gabriel
// boundary without making any of them encroached (strictly) or cospherical with it (on the sphere).
#pragma once
#include <array>
#include <string>
#include <vector>

#include "nonobtuse/types.h"

namespace nonobtuse {

// For candidate k: closed_face[k] is the first row of `faces` whose closed diametral sphere (the smallest sphere
// through its corners, boundary included) holds candidates[k], or -1; closed_segment[k] the same for `segments`
// (the sphere with the segment as a diameter).
struct ClosedSphereHits {
  std::vector<int> closed_face;
  std::vector<int> closed_segment;
};

// Exact (CGAL side_of_bounded_sphere != ON_UNBOUNDED_SIDE on the coordinates as stored); a kd-tree over the
// candidates with a conservative floating-point search ball only proposes them. A candidate equal to a corner is
// on that sphere, so it is reported.
// Throws InvalidInput for an index out of range, a face with collinear corners or a segment with coincident ends.
// Cost: O((c + f + k) log c) when each sphere holds O(1) candidates.
ClosedSphereHits closed_diametral_sphere_hits(const std::vector<Point3>& points, const std::vector<Triangle>& faces,
                                              const std::vector<Segment>& segments,
                                              const std::vector<Point3>& candidates);

// A tetrahedral mesh of a domain whose boundary is Gabriel: every subfacet and subsegment has an empty open
// diametral sphere (refine_gabriel's converged output), so the subfacets are faces and the subsegments edges of the
// Delaunay tetrahedralization of the points.
struct InteriorMesh {
  std::vector<Point3> points;
  std::vector<std::array<int, 4>> tets;  // the domain's tets, positively oriented
  std::vector<int> tet_labels;           // per tet, an index into InteriorBounds::volume_bounds
  std::vector<Triangle> faces;           // the subfacets
  std::vector<Segment> segments;         // the subsegments
  // Points left out of the Delaunay tetrahedralization (built without them, before any insertion): interior points
  // (on no face or segment) that stood for blocked circumcenters while the boundary repair split what they
  // encroach. Leaving a point out keeps every diametral sphere as empty as it was; the cell that then holds it gets
  // its region's label (its star was in one region, it is on no subfacet), as do the cells of the input's tets.
  std::vector<int> remove;
  // Points inserted first, in order, each where it is strictly outside every closed diametral sphere, in the domain
  // and on no vertex (exact; e.g. another mesher's interior points), else dropped.
  std::vector<Point3> insert;
};

struct InteriorBounds {
  double radius_edge = 0.0;          // circumradius / shortest edge; <= 0: no bound
  std::vector<double> volume_bounds;  // per label; +inf: none
  long long max_points = 1000000;     // points to insert at most
  double time_limit = 60.0;          // seconds (checked every 64 insertions)
};

// "converged": every tet within the bounds; "blocked": the tets over a bound left have circumcenters in a closed
// diametral sphere of a subfacet or subsegment, on a mesh vertex or outside the domain (blocked_rows);
// "budget_exhausted": max_points or time_limit; "not_conforming": a subfacet or subsegment is not a face or an edge
// of the Delaunay tetrahedralization (cospherical points), before or after the removals: nothing was inserted or
// removed (the input returned).
struct InteriorRefinement {
  // the input points in order but the removed ones (a point's index drops by the removed indices below it), then
  // the points of InteriorMesh::insert placed, then the inserted circumcenters; tets index these
  std::vector<Point3> points;
  std::vector<std::array<int, 4>> tets;
  std::vector<int> tet_labels;
  std::vector<int> blocked_rows;       // rows of tets over a bound whose circumcenters could not be inserted
  std::vector<Point3> blocked_centers;  // their circumcenters (floating point)
  // per blocked row: a point strictly inside the diametral sphere that holds its center and strictly inside a
  // domain tet, high above the subfacet (see stand_in in quality3d_interior.cpp), or NaN where none was found
  std::vector<Point3> stand_ins;
  std::string status;
  long long inserted = 0;  // circumcenters
  long long placed = 0;    // points of InteriorMesh::insert
};

// Delaunay refinement of the interior with the boundary fixed (Shewchuk's rule with the boundary split left to the
// caller, Ruppert's rule): the tets over a bound, worst radius-edge ratio first, get their circumcenter inserted
// (Bowyer-Watson, CGAL Delaunay_triangulation_3, the triangulation kept between insertions) when it lies strictly
// outside every closed diametral sphere of a subfacet and subsegment (exact, on the rounded double), in the domain
// (exact point location) and on no vertex; otherwise the tet is left for the caller (blocked_rows), which splits
// the subfacets or subsegments the center encroaches. Such a point keeps every subfacet and subsegment Gabriel and
// Delaunay, and its cavity crosses no subfacet (a tet beyond subfacet f whose circumsphere held it would have its
// apex inside f's diametral sphere), so each new tet inherits the label of the tet holding the point.
// Throws InvalidInput for indices out of range, labels without a bound, collinear faces, degenerate segments or a
// removed point on a face or segment.
// Cost: O(k log n) expected for k insertions into n points, plus O(log) sphere lookups per candidate.
InteriorRefinement refine_interior(const InteriorMesh& mesh, const InteriorBounds& bounds);

}  // namespace nonobtuse
