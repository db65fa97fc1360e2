// Exact validation of a planar straight-line graph: crossings, points inside segments, collinear overlaps, and
// what the domain covers. Candidate pairs come from bounding boxes (exact: the boxes are built from the input
// doubles, no rounding), or, when they are many, a constrained triangulation first rules everything out; every
// decision from an exact predicate.
#include "nonobtuse/validate2d.h"

#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <memory>
#include <string>
#include <utility>

#include "cdt.h"

namespace nonobtuse {
namespace {

using cdt::K;
using cdt::Point;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, int>;

Box segment_box(const std::vector<Point>& p, const Segment& s, int id) {
  return Box(p[s[0]].bbox() + p[s[1]].bbox(), id);
}

// Collinear segments ab and cd share a piece of positive length iff, ordering each pair lexicographically
// (the order along their common line), the later start precedes the earlier end.
bool collinear_overlap(Point a, Point b, Point c, Point d) {
  if (CGAL::compare_xy(a, b) == CGAL::LARGER) std::swap(a, b);
  if (CGAL::compare_xy(c, d) == CGAL::LARGER) std::swap(c, d);
  const Point& lo = CGAL::compare_xy(a, c) == CGAL::LARGER ? a : c;
  const Point& hi = CGAL::compare_xy(b, d) == CGAL::SMALLER ? b : d;
  return CGAL::compare_xy(lo, hi) == CGAL::SMALLER;
}

std::vector<Point> to_cgal_points(const std::vector<Point2>& points) {
  std::vector<Point> p;
  p.reserve(points.size());
  for (const auto& q : points) p.push_back(cdt::to_cgal(q));
  return p;
}

void check_indices(std::size_t n_points, const std::vector<Segment>& segments) {
  for (std::size_t s = 0; s < segments.size(); ++s)
    for (int v : segments[s])
      if (v < 0 || static_cast<std::size_t>(v) >= n_points)
        throw InvalidInput("segment " + std::to_string(s) + " refers to point " + std::to_string(v) +
                           ", but there are " + std::to_string(n_points) + " points");
}

// Below this many boxes box_intersection_d scans instead of splitting further (CGAL's default 10): the same pairs,
// each once, in a different order (the lists are sorted below); fewer levels of its recursion.
constexpr std::ptrdiff_t kBoxCutoff = 1000;

// Thrown by candidate_pairs' callbacks past their budget.
struct TooManyPairs {};

// find_segment_intersections from bounding-box candidate pairs; throws TooManyPairs after more than max_pairs
// candidates (no limit when negative).
SegmentIntersections candidate_pairs(const std::vector<Point>& p, const std::vector<Segment>& segments,
                                     long long max_pairs) {
  SegmentIntersections out;
  long long pairs = 0;
  auto count = [&] {
    if (max_pairs >= 0 && ++pairs > max_pairs) throw TooManyPairs{};
  };

  std::vector<Box> seg_boxes;
  seg_boxes.reserve(segments.size());
  for (std::size_t s = 0; s < segments.size(); ++s) seg_boxes.push_back(segment_box(p, segments[s], int(s)));

  // Segment pairs. With no common endpoint index and distinct coordinates, a pair either is collinear (overlap iff
  // they share a piece of positive length), or meets in at most one point: an endpoint of one lying on the other
  // when an orientation vanishes (left to the point pass below), else a proper crossing when each segment's
  // endpoints lie strictly on opposite sides of the other's line.
  CGAL::box_self_intersection_d(seg_boxes.begin(), seg_boxes.end(), [&](const Box& x, const Box& y) {
    count();
    int s = std::min(x.info(), y.info()), t = std::max(x.info(), y.info());
    const Point &a = p[segments[s][0]], &b = p[segments[s][1]];
    const Point &c = p[segments[t][0]], &d = p[segments[t][1]];
    // Neighbours along a chain (most pairs): a common endpoint index leaves no crossing away from the endpoints,
    // only an overlap, when the other end of t is on s's line (what the four orientations below decide too).
    const int shared = segments[t][0] == segments[s][0] || segments[t][0] == segments[s][1]   ? 0
                       : segments[t][1] == segments[s][0] || segments[t][1] == segments[s][1] ? 1
                                                                                               : -1;
    if (shared >= 0) {
      if (CGAL::orientation(a, b, shared == 0 ? d : c) == CGAL::COLLINEAR && collinear_overlap(a, b, c, d))
        out.overlaps.push_back({s, t});
      return;
    }
    auto o1 = CGAL::orientation(a, b, c), o2 = CGAL::orientation(a, b, d);
    if (o1 == CGAL::COLLINEAR && o2 == CGAL::COLLINEAR) {
      if (collinear_overlap(a, b, c, d)) out.overlaps.push_back({s, t});
      return;
    }
    auto o3 = CGAL::orientation(c, d, a), o4 = CGAL::orientation(c, d, b);
    if (o1 != CGAL::COLLINEAR && o2 != CGAL::COLLINEAR && o3 != CGAL::COLLINEAR && o4 != CGAL::COLLINEAR &&
        o1 != o2 && o3 != o4)
      out.crossings.push_back({s, t});
  }, kBoxCutoff);

  // Points against segments: a point (degenerate box) lies strictly inside a segment iff it is collinear with the
  // endpoints and strictly between them along the line.
  std::vector<Box> point_boxes;
  point_boxes.reserve(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) point_boxes.emplace_back(p[i].bbox(), int(i));
  CGAL::box_intersection_d(point_boxes.begin(), point_boxes.end(), seg_boxes.begin(), seg_boxes.end(),
                           [&](const Box& pt, const Box& sg) {
                             count();
                             if (pt.info() == segments[sg.info()][0] || pt.info() == segments[sg.info()][1]) return;
                             const Point &q = p[pt.info()], &a = p[segments[sg.info()][0]],
                                         &b = p[segments[sg.info()][1]];
                             if (CGAL::orientation(a, b, q) == CGAL::COLLINEAR &&
                                 CGAL::collinear_are_strictly_ordered_along_line(a, q, b))
                               out.points_on_segments.push_back({pt.info(), sg.info()});
                           }, kBoxCutoff);

  std::sort(out.crossings.begin(), out.crossings.end());
  std::sort(out.points_on_segments.begin(), out.points_on_segments.end());
  std::sort(out.overlaps.begin(), out.overlaps.end());
  return out;
}

}  // namespace

SegmentIntersections find_segment_intersections(const std::vector<Point2>& points,
                                                const std::vector<Segment>& segments) {
  check_indices(points.size(), segments);
  const std::vector<Point> p = to_cgal_points(points);
  // Most inputs give a few candidate pairs per segment. Past that budget (a star polygon's long, nearly parallel
  // edges give pairs growing as n^2), one constrained triangulation decides whether there is anything to report
  // (cdt::is_simple_pslg, exact), and only then are all the pairs examined.
  try {
    return candidate_pairs(p, segments, 8 * static_cast<long long>(points.size() + segments.size()) + 1024);
  } catch (const TooManyPairs&) {
  }
  if (cdt::is_simple_pslg(points, segments)) return {};
  return candidate_pairs(p, segments, -1);
}

namespace {

// Locates `at` in the triangulation; `inside(face)` decides for a face that is not on the boundary.
template <class Inside>
SeedPlace place_of(const cdt::CDT& t, const Point2& at, Inside inside) {
  cdt::CDT::Locate_type lt;
  int li = -1;
  cdt::Face_handle f = t.locate(cdt::to_cgal(at), lt, li);
  if (lt == cdt::CDT::OUTSIDE_CONVEX_HULL || lt == cdt::CDT::OUTSIDE_AFFINE_HULL) return SeedPlace::Outside;
  if (lt == cdt::CDT::VERTEX) return SeedPlace::OnBoundary;
  if (lt == cdt::CDT::EDGE && t.is_constrained(cdt::Edge(f, li))) return SeedPlace::OnBoundary;
  return inside(f) ? SeedPlace::Inside : SeedPlace::Outside;
}

}  // namespace

Triangulation2::Triangulation2() = default;
Triangulation2::Triangulation2(std::unique_ptr<Built> built) : built_(std::move(built)) {}
Triangulation2::Triangulation2(Triangulation2&&) noexcept = default;
Triangulation2& Triangulation2::operator=(Triangulation2&&) noexcept = default;
Triangulation2::~Triangulation2() = default;
Triangulation2 Triangulation2::take() { return Triangulation2(std::move(built_)); }

DomainCoverage inspect_domain(const Domain2& domain, bool keep_triangulation) {
  check_indices(domain.points.size(), domain.segments);
  auto built = std::make_unique<Triangulation2::Built>();
  cdt::CDT& t = built->cdt;
  Domain2 without_holes = domain;  // cdt::mark_domain cannot place hole seeds in a 1D triangulation
  without_holes.holes.clear();
  const std::vector<cdt::Vertex_handle> vh = cdt::build(t, without_holes);
  DomainCoverage cov;
  if (t.dimension() < 2) {  // all points collinear: no triangle, nothing inside
    for (std::size_t s = 0; s < domain.segments.size(); ++s) cov.segments_outside.push_back(int(s));
    cov.holes.assign(domain.holes.size(), SeedPlace::Outside);
    cov.regions.assign(domain.regions.size(), SeedPlace::Outside);
    return cov;
  }
  cdt::mark_domain(t, domain);
  // cdt::mark_domain: component -2 = reached from the unbounded face (exterior), -3 = hole, >= 0 = domain.
  for (auto f = t.finite_faces_begin(); f != t.finite_faces_end(); ++f) {
    cov.encloses_area = cov.encloses_area || f->info().component != -2;
    cov.domain_triangles += f->info().in_domain();
  }
  for (std::size_t s = 0; s < domain.segments.size(); ++s) {
    cdt::Face_handle f;
    int i = -1;
    if (!t.is_edge(vh[domain.segments[s][0]], vh[domain.segments[s][1]], f, i))
      throw InvalidInput("segment " + std::to_string(s) +
                         " is not an edge of the triangulation: it passes through a point or crosses a segment");
    if (!f->info().in_domain() && !f->neighbor(i)->info().in_domain()) cov.segments_outside.push_back(int(s));
  }
  for (const auto& h : domain.holes)
    cov.holes.push_back(place_of(t, h, [](cdt::Face_handle f) { return f->info().component != -2; }));
  for (const auto& r : domain.regions)
    cov.regions.push_back(place_of(t, r.at, [](cdt::Face_handle f) { return f->info().in_domain(); }));
  // t is now what cdt::build(t, domain) makes: the same insertions in the same order, marked with the holes.
  if (keep_triangulation && cov.domain_triangles > 0) {
    built->domain = domain;
    cov.triangulation = std::make_shared<Triangulation2>(std::move(built));
  }
  return cov;
}

}  // namespace nonobtuse
