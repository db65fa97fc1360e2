// Internal: the CGAL constrained Delaunay triangulation every 2D algorithm works on. CGAL appears only in cpp/src.
#pragma once
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <cstdint>
#include <vector>

#include "nonobtuse/types.h"
#include "nonobtuse/validate2d.h"

namespace nonobtuse::cdt {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;

// Twelve bytes, so that a face takes 72 bytes (88 with a region attribute and a flag here): insertion and every
// pass over the faces move less memory.
struct FaceInfo {
  // mark_domain: -1 not marked, -2 exterior, -3 hole; a domain face: its connected component across unconstrained
  // edges when the domain has regions, else 0 (an index into CDT::region_attribute either way).
  int component = -1;
  unsigned visit[2] = {0, 0};  // per walk lane, the last walk that reached this face (refine2d::State::new_walk)
  bool in_domain() const { return component >= 0; }
};

// Vertex info: the vertex's index in the output point list (input points keep their input index).
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Fbb = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbb>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
// Constraints that cross away from vertices are refused (an exception), never resolved by constructing points.
using Itag = CGAL::No_constraint_intersection_requiring_constructions_tag;
// The triangulation with the region attribute of each domain component (mark_domain).
struct CDT : CGAL::Constrained_Delaunay_triangulation_2<K, Tds, Itag> {
  std::vector<double> region_attribute;
  void swap(CDT& other) {  // O(1): the data structures trade places (the constraints are marks on its faces)
    CGAL::Triangulation_2<K, Tds>::swap(other);
    region_attribute.swap(other.region_attribute);
  }
  double region(Face_handle f) const { return region_attribute[f->info().component]; }  // f in the domain
};
using Vertex_handle = CDT::Vertex_handle;
using Face_handle = CDT::Face_handle;
using Edge = CDT::Edge;

inline Point to_cgal(const Point2& p) { return Point(p.x, p.y); }
inline Point2 from_cgal(const Point& p) { return {p.x(), p.y()}; }

// Position of (x, y), 0 <= x, y < 2^16, along the Hilbert curve of order 16 from (0, 0) to (2^16 - 1, 0) (the
// insertion order of build).
std::uint32_t hilbert_index(std::uint32_t x, std::uint32_t y);

// Inserts the domain's points (spatially sorted, info = input index) and constraints (plus the convex hull edges
// when domain.convex_hull_boundary, so that every algorithm sees one kind of boundary: constrained edges), then
// marks the domain. Returns the vertex handle of every input point. Throws InvalidInput on crossing constraints.
std::vector<Vertex_handle> build(CDT& cdt, const Domain2& domain);

// Exact: no two segments cross or share a piece of positive length, no point lies strictly inside a segment and no
// segment repeats another (find_segment_intersections would report nothing); false also on duplicate points, a
// segment joining a point to itself, or all points collinear. Builds the constrained Delaunay triangulation of the
// points and segments: CGAL's constraint insertion throws at a crossing (Itag: exact predicates, no constructions)
// and splits a constraint at every point on it, so each segment is then one edge exactly when no point lies
// strictly inside it, which also rules out overlaps other than repeats (one overlapping another has an end inside
// it, or both ends equal); repeats are found by sorting. Cost: one triangulation, O(n log n) for n points in
// practice, where bounding-box candidate pairs can grow as n^2 (the long, nearly parallel edges of a star polygon).
bool is_simple_pslg(const std::vector<Point2>& points, const std::vector<Segment>& segments);

// Recomputes FaceInfo for every face and cdt.region_attribute: the exterior (flood fill from the infinite faces
// across unconstrained edges) and hole seeds are out, the rest in; when the domain has regions, components and
// their attributes by flood fill across unconstrained edges, else one component, attribute 0. Call again after
// inserting points.
void mark_domain(CDT& cdt, const Domain2& domain);

// The domains a and b are the same: equal coordinates, segments, seeds and flag (exact comparison). O(n).
bool same_domain(const Domain2& a, const Domain2& b);
// Domain triangles, every constrained subsegment bordering the domain, points indexed by vertex info. Points and
// triangles on two threads for large triangulations unless threads is 1 (the same mesh).
Mesh2 to_mesh(const CDT& cdt, int threads = 2);

}  // namespace nonobtuse::cdt

namespace nonobtuse {
struct Triangulation2::Built {
  Domain2 domain;
  cdt::CDT cdt;  // cdt::build(cdt, domain), marked by cdt::mark_domain(cdt, domain)
};
}  // namespace nonobtuse
