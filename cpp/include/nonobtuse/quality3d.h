// 3D interior quality: which candidate interior points would enter a boundary simplex's closed diametral sphere.
// A point outside every closed diametral sphere of the subfacets and subsegments can be added to a Gabriel
// boundary without making any of them encroached (strictly) or cospherical with it (on the sphere).
#pragma once
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

}  // namespace nonobtuse
