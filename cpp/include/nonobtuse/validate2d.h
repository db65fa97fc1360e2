// Exact geometric validation of a 2D domain (planar straight-line graph): which segments cross, which points lie
// inside a segment, which segments overlap, and what lies inside the domain. Plain lists; the Python layer
// (nonobtuse.validate) turns them into repairs or InvalidInputError messages.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "nonobtuse/types.h"

namespace nonobtuse {

// How segments and points meet, decided with exact predicates (CGAL EPICK orientation and collinear ordering).
struct SegmentIntersections {
  // (s, t), s < t: the open segments cross in a single point that is an endpoint of neither (a proper crossing).
  std::vector<std::array<int, 2>> crossings;
  // (p, s): point p lies strictly inside segment s (on it, not at an endpoint). Covers every point, segment
  // endpoints and isolated points alike.
  std::vector<std::array<int, 2>> points_on_segments;
  // (s, t), s < t: collinear segments sharing a piece of positive length (exact duplicates included).
  std::vector<std::array<int, 2>> overlaps;
};

// Preconditions (the caller reports these first): coordinates finite and pairwise distinct, every segment joins
// two distinct points. Two segments that meet only at a common endpoint, or where an endpoint of one lies inside
// the other (reported in points_on_segments instead), are not crossings.
// Every list is sorted. Cost: candidate pairs by bounding-box intersection (CGAL::box_intersection_d,
// O((n + k) log^2 n) for n boxes and k overlapping box pairs), then O(1) exact predicates per candidate pair; past
// 8 pairs per point and segment, one constrained Delaunay triangulation first (near-linear), and the pairs only
// when it finds something to report.
// Throws InvalidInput when a segment index is out of range.
SegmentIntersections find_segment_intersections(const std::vector<Point2>& points,
                                                const std::vector<Segment>& segments);

// Where a hole or region seed lies relative to the domain.
enum class SeedPlace : std::int8_t {
  Inside = 0,      // in the interior of a domain triangle or on an unconstrained edge
  Outside = 1,     // outside the convex hull, in the exterior, or (region seeds) in a hole
  OnBoundary = 2,  // exactly on an input point or on a segment: ambiguous, which side is meant?
};

// The constrained Delaunay triangulation of a domain as inspect_domain built and marked it, held so that refine
// (nonobtuse/refine2d.h) takes it over instead of triangulating the same domain again. Opaque: CGAL stays in
// cpp/src. Holds a copy of the domain it triangulates, so that refine can tell it belongs to the domain it is given.
// Move-only; empty once taken.
class Triangulation2 {
 public:
  struct Built;  // the domain and its CGAL triangulation (cpp/src/cdt.h)
  Triangulation2();
  explicit Triangulation2(std::unique_ptr<Built> built);
  Triangulation2(Triangulation2&&) noexcept;
  Triangulation2& operator=(Triangulation2&&) noexcept;
  ~Triangulation2();
  bool empty() const { return !built_; }
  Triangulation2 take();                         // the triangulation moved out: *this is empty afterwards
  Built* built() const { return built_.get(); }  // null when empty; Built is defined in cpp/src

 private:
  std::unique_ptr<Built> built_;
};

// What the constrained Delaunay triangulation of the domain (cdt::build: segments, convex hull edges when
// domain.convex_hull_boundary, exterior and holes removed by flood fill across unconstrained edges) covers.
struct DomainCoverage {
  // Some triangle is enclosed by segments: not reachable from the unbounded face without crossing a segment
  // (holes ignored). False for a point set, or segments that are all dangling.
  bool encloses_area = false;
  int domain_triangles = 0;
  // Segments with no domain triangle on either side: they lie in the exterior (an open outer boundary, a segment
  // sticking out) or inside a hole. Sorted.
  std::vector<int> segments_outside;
  // Hole seeds: Outside means in the exterior with holes ignored (the seed is inside no closed loop).
  std::vector<SeedPlace> holes;
  // Region seeds: Outside means not in a domain triangle (exterior or hole).
  std::vector<SeedPlace> regions;
  // The triangulation itself when inspect_domain was asked to keep it and the domain has a triangle; else null.
  std::shared_ptr<Triangulation2> triangulation;
};

// Preconditions: as for find_segment_intersections, and no crossings, points inside segments or overlaps
// (each segment is then one edge of the triangulation). Throws InvalidInput when a segment is not an edge of the
// triangulation (the preconditions were not met). Cost: O(n log n) expected; keep_triangulation keeps the
// triangulation (memory: about 200 bytes per point) and a copy of the domain in the result.
DomainCoverage inspect_domain(const Domain2& domain, bool keep_triangulation = false);

}  // namespace nonobtuse
