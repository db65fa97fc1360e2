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
  // The input facet id of each subfacet (subfacets sharing one form one planar facet), or empty: the boundary is
  // then fixed (no splits).
  std::vector<int> face_facets;
  std::vector<Segment> segments;         // the subsegments
  // Points inserted first, in order, each where it is strictly outside every closed diametral sphere, in the domain
  // and on no vertex (exact; e.g. another mesher's interior points), else dropped.
  std::vector<Point3> insert;
  // Subfacets (a, b, c) and subsegments (a, b, -1), corners in any order, whose split cascaded in an earlier pass
  // (refine_quality3d's retries): a tet whose circumcenter lies in one's closed diametral sphere is left alone as
  // the small-angle rule leaves tets (small_angle_rows).
  std::vector<std::array<int, 3>> left_alone;
};

struct InteriorBounds {
  double radius_edge = 0.0;          // circumradius / shortest edge; <= 0: no bound
  std::vector<double> volume_bounds;  // per label; +inf: none
  long long max_points = 1000000;     // points to insert at most
  double time_limit = 60.0;          // seconds (checked every 64 insertions and before every boundary split)
  long long max_boundary_points = 1000000;  // boundary points to add at most
  double min_length = 0.0;           // no boundary split point closer than this to a point; 0: none
  // The small-angle rule's angles (InteriorRefinement::small_angle_rows), in degrees; 0 turns that clause off.
  // Facets meeting at a segment below sharp_dihedral_degrees make it sharp (Shewchuk's 3D proof needs 90; 85 keeps
  // the right angles of tessellated CAD models, measured at 89.9998 on joint.off, out); two subsegments meeting
  // below small_apex_degrees, or one leaning over a facet below it, make their apex sharp (Ruppert's 60, as 2D's).
  double sharp_dihedral_degrees = 85.0;
  double small_apex_degrees = 60.0;
  // For a tet over the volume bound, both angles are at most this: such a tet's split radius is bounded below by the
  // bound (refine_interior's split rule), so the rule is only needed where the cascade that split starts need not
  // end, below Ruppert's 60 degrees for a facet corner or a wedge's cross-section; 0.01 lower for inputs written
  // with few digits (gc_hourglass_ico.obj's equilateral faces have corners of 59.9988 degrees).
  double volume_sharp_degrees = 59.99;
  // Blocked circumcenters a boundary step splits for at most, worst first, each with 64 boundary points at most
  // (the step is refused beyond); 0: all, within max_boundary_points.
  long long max_step_centers = 0;
};

// "converged": every tet within the bounds but those left alone near small input angles (small_angle_rows);
// "blocked": other tets over a bound are left, their circumcenters freed by no split (in a closed diametral sphere
// whose split was refused, on a mesh vertex or outside the domain: blocked_rows);
// "budget_exhausted": max_points or time_limit; "not_conforming": a subfacet or subsegment is not a face or an edge
// of the Delaunay tetrahedralization (cospherical points): before any boundary split, nothing was inserted (the
// input returned); after one, the state before that boundary step is returned (the first certified_points points,
// tets, faces and segments: Gabriel and conforming) with the split boundary (split_*: the facets' triangulations,
// over all points) for a repair that tetrahedralizes it; "boundary_stopped": a split that would restore the Gabriel
// property was refused (min_length, max_boundary_points, an existing point, time_limit): the same.
struct InteriorRefinement {
  // the input points in order, then the points of InteriorMesh::insert placed, then the inserted circumcenters and
  // boundary points as they came; tets index these
  std::vector<Point3> points;
  std::vector<std::array<int, 4>> tets;
  std::vector<int> tet_labels;
  std::vector<int> blocked_rows;       // rows of tets over a bound whose circumcenters could not be inserted
  // The blocked rows left alone near small input angles (the small-angle rule: a tet whose circumcenter lies in the
  // closed diametral sphere of a subsegment or subfacet whose split would lie at a sharp feature, a segment where
  // facets meet below 85 degrees or an apex below 60, below volume_sharp_degrees both for a tet over the volume
  // bound, and in its protecting region, or, over the radius-edge bound alone, would be shorter than the tet's
  // shortest edge; see quality3d_boundary.h and quality3d_small_angle.h),
  // and those with four corners on one facet (flat but for rounding), sorted.
  std::vector<int> small_angle_rows;
  std::vector<Point3> blocked_centers;  // their circumcenters (floating point)
  // The boundary at the end: the subfacets (faces of the Delaunay tetrahedralization, each oriented away from a
  // domain tet behind it; the input's as given while no boundary split happened) with their input facet ids, and
  // the subsegments.
  std::vector<Triangle> faces;
  std::vector<int> face_facets;
  std::vector<Segment> segments;
  // After "not_conforming" or "boundary_stopped" from a boundary step: the points tets and faces use (the rest are
  // that step's boundary points) and the split boundary; else certified_points is points.size() and split_* empty.
  long long certified_points = 0;
  std::vector<Triangle> split_faces;
  std::vector<int> split_face_facets;
  std::vector<Segment> split_segments;
  // After "boundary_stopped": how many circumcenters that step split for, and the subfacets (a, b, c) and
  // subsegments (a, b, -1) it split for them (corners sorted; sorted).
  long long step_centers = 0;
  std::vector<std::array<int, 3>> step_elements;
  std::string status;
  long long inserted = 0;         // circumcenters
  long long placed = 0;           // points of InteriorMesh::insert
  long long boundary_points = 0;  // added by boundary splits
  long long boundary_rounds = 0;  // boundary steps that split something
  long long refused_splits = 0;   // boundary splits refused (min_length, max_boundary_points, existing point)
};

// Delaunay refinement (Shewchuk's, as TetGen's -q): the tets over a bound, worst radius-edge ratio first, get their
// circumcenter inserted (Bowyer-Watson, CGAL Delaunay_triangulation_3, the triangulation kept between insertions)
// when it lies strictly outside every closed diametral sphere of a subfacet and subsegment (exact, on the rounded
// double), in the domain (exact point location) and on no vertex. Such a point keeps every subfacet and subsegment
// Gabriel and Delaunay, and its cavity crosses no subfacet (a tet beyond subfacet f whose circumsphere held it would
// have its apex inside f's diametral sphere), so each new tet inherits the label of the tet holding the point. With
// face_facets, a center in a closed diametral sphere splits that subsegment (midpoint) or subfacet (circumcenter, or
// the subsegments that encroaches), then every encroached subsegment and subfacet is split until the boundary is
// Gabriel again (a strictly-inside test, exact), the points go into the same triangulation, and the subfacets are
// taken from it (Ruppert's rule; quality3d_boundary.h); the centers are then tried again, until none is left or
// nothing more can be split. The caller's exact check of the result is the certificate.
// Throws InvalidInput for indices out of range, labels without a bound, collinear faces, degenerate segments,
// face_facets of the wrong length, or a boundary that build_plc_state refuses.
// Cost: O(k log n) expected for k insertions into n points, plus O(log) sphere lookups per candidate; per boundary
// step O(f log n) exact encroachment queries per scan for f subfacets and a pass over the tetrahedralization.
InteriorRefinement refine_interior(const InteriorMesh& mesh, const InteriorBounds& bounds);

}  // namespace nonobtuse
