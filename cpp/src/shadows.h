// Internal: exact shading of a side by obstacles, seen from a vertex (paper 4.4: a vertex encroaches a subsegment
// only when some point of it sees the vertex). covered_from answers one question from scratch; ShadowIntervals
// prepares one vertex's shadows on one side once, for the many subsegments of that side the lower bound asks about.
#pragma once
#include <algorithm>
#include <array>
#include <unordered_map>
#include <vector>

#include "cdt.h"
#include "diametral_disk.h"

namespace nonobtuse::refine2d {

// Squared distance from (cx, cy) to the segment [u, w], in doubles (used only to prune walks and to order searches).
inline double distance2_to_segment(double cx, double cy, const Point& u, const Point& w) {
  double dx = w.x() - u.x(), dy = w.y() - u.y();
  double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((cx - u.x()) * dx + (cy - u.y()) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  double px = u.x() + t * dx - cx, py = u.y() + t * dy - cy;
  return px * px + py * py;
}

// Exact: the closed segments [p, q] and [c1, c2] meet. Shared ends and disjoint bounding boxes are decided by
// comparisons (an orientation of equal points is exactly zero, which only exact arithmetic certifies).
bool segments_meet(const Point& p, const Point& q, const Point& c1, const Point& c2);

// Exact: the closed segment [c1, c2] (c1 != c2) meets the closed triangle (p, q, r) (not degenerate). Orientation
// predicates only.
bool segment_meets_triangle(const Point& c1, const Point& c2, const Point& p, const Point& q, const Point& r);

// Exact: the closed segments `obstacles` block every sight line from v to the open segment (a, b) (v off its line;
// obstacles ending at v are ignored). Cost: O(k log k) for k obstacles.
bool covered_from(const Point& v, const Point& a, const Point& b, const std::vector<Segment2>& obstacles);

// A convex quadrilateral around the side [s, e] holding every point within m = 2^-30 of the largest coordinate of
// it: the corners s - m t + m n, s - m t - m n, e + m t - m n, e + m t + m n (t along the side, n its left normal),
// rounded, counter-clockwise; rounding moves them by ulps, far less than m. Every subsegment end that greedy_count
// asks about lies within ulps of the side, hence inside.
std::array<Point, 4> fat_side(const Point& s, const Point& e);

// The obstacles, in their order, that may meet a triangle (v, a, b) whose corners a and b lie within a tiny margin
// (2^-30 of the largest coordinate involved) of the closed segment [s, e]: a separating-axis test in doubles that
// drops an obstacle only when it lies beyond an edge line of (v, s, e), or (v, s, e) beyond its line, by more than
// the margin, which exceeds both the rounding of the test and how far rounded subsegment ends stray from [s, e]
// (ulps). covered_from(v, a, b, ·) only uses obstacles meeting the closed triangle (v, a, b), so it decides the
// same on the result as on all of `obstacles`. Cost: O(obstacles), in doubles.
std::vector<Segment2> obstacles_near_triangle(const Point& v, const Point& s, const Point& e,
                                              const std::vector<Segment2>& obstacles);

// covered_from(v, a, b, obstacles) for many segments (a, b) near one side, with the obstacles' shadows sorted once.
// Built from the side's fat_side quadrilateral Q. When v lies strictly beyond the line of Q's side facing it (the
// open half-plane H), the obstacles split in two:
// - sure: both ends in H, and both strictly on one side (the inner one) of one of the two lines from v through the
//   extreme corners of Q. For a and b outside H, such an obstacle is in front of (a, b) exactly when its angular
//   span from v meets the closed wedge (v, a, b): a point p of it in the wedge lies on the ray from v to a point y
//   of [a, b], and the ray leaves the half-plane H (holding v and p, not y) only once, so p lies in [v, y]. Their
//   spans, clipped to the wedge W of Q seen from v (less than 180 degrees: Q lies outside H), are merged into
//   disjoint closed intervals once, in counter-clockwise order (the inner-side condition keeps each span and W
//   within half a turn, where the orientation order of directions is valid).
// - maybe: the rest (near Q's lines, or spanning all of W); covered_from's own rule decides them per question.
// covered(a, b) then sweeps from one end of the wedge to the other over the merged intervals (binary search) and the
// maybe shadows, which decides exactly covered_from's question: both cover the wedge with the union of the closed
// shadows in front of (a, b). Otherwise (v not beyond Q's line, a or b in H, or the wedge not within W) it is
// covered_from itself. Cost: O(k log k) to build for k obstacles; a question O(log k + m log m) for m maybe
// obstacles, against covered_from's O(k log k).
class ShadowIntervals {
 public:
  ShadowIntervals(const Point& v, const std::array<Point, 4>& fat, std::vector<Segment2> obstacles);
  // covered_from(v, a, b, obstacles), exactly.
  bool covered(const Point& a, const Point& b) const;
  // Whether the merged intervals are in use (v beyond the line of fat's side facing it), and their number.
  bool prepared() const { return prepared_; }
  std::size_t intervals() const { return merged_.size(); }

 private:
  bool in_h(const Point& p) const;

  Point v_;
  std::vector<Segment2> obstacles_;
  bool prepared_ = false;
  Segment2 facing_;               // the directed line of fat's side facing v: H is strictly right of it
  Point lo_, hi_;                 // W, counter-clockwise from lo_ to hi_ seen from v
  std::vector<Segment2> merged_;  // the sure obstacles' shadows in W: disjoint, counter-clockwise, (first, last)
  std::vector<Segment2> maybe_;
};

// Exact: every closed segment from a point of the convex hull of `source` to x meets the closed segment c (x lies
// in c's umbra). The points y for which [y, x] meets c form a convex set (those on c or beyond it seen from x: a
// truncated cone, a ray or the plane), so holding the four corners suffices. The umbra is convex too (an
// intersection of such sets over the y), so a segment with both ends in it lies in it.
bool in_umbra(const std::array<Point, 4>& source, const Point& x, const Segment2& c);

// The obstacles, in their order, less those that a quick search finds wholly in the umbra (from fat, in_umbra of both
// ends) of an obstacle kept before them: nearest to [s, e] first (doubles), each against the last kUmbraTries kept.
// Which obstacles go is a matter of speed only: ObstaclesInFront uses the result as a subset of all of them.
// Cost: O(k log k + k kUmbraTries) exact orientations for k obstacles.
constexpr std::size_t kUmbraTries = 24;
std::vector<Segment2> unshaded_obstacles(const std::array<Point, 4>& fat, const Point& s, const Point& e,
                                         const std::vector<Segment2>& obstacles);

// covered_from(v, a, b, obstacles) for the vertices v asked about and subsegments (a, b) of the side [s, e]: the
// ShadowIntervals of each v, from obstacles_near_triangle(v, s, e, ·), built once, at its first question (most
// encroachers of a walk are never asked about). First from the unshaded obstacles only: covered by a subset of the
// obstacles implies covered by all (covered_from's shadows are per obstacle, their union only grows), so a yes
// there is the answer; a no is asked again of all the obstacles (a second ShadowIntervals of v, built then). On a
// spiky polygon a side's walk keeps some hundreds of obstacles of which a tenth are not behind another, and nearly
// every vertex asked about is hidden: one build over the few instead of the many (the first constraint met on a
// sight line from the side is never dropped, so the second build is rare, but the answer does not rest on that).
// Not thread-safe: one per walk.
class ObstaclesInFront {
 public:
  ObstaclesInFront(const Point& s, const Point& e, const std::vector<Segment2>& obstacles)
      : s_(s), e_(e), fat_(fat_side(s, e)), obstacles_(obstacles), unshaded_(unshaded_obstacles(fat_, s, e, obstacles)) {}
  // covered_from(v->point(), a, b, obstacles), exactly.
  bool covered(Vertex_handle v, const Point& a, const Point& b) const {
    return shadows(v, unshaded_, from_unshaded_).covered(a, b) || shadows(v, obstacles_, from_all_).covered(a, b);
  }

 private:
  using ByVertex = std::unordered_map<int, ShadowIntervals>;  // by vertex index
  const ShadowIntervals& shadows(Vertex_handle v, const std::vector<Segment2>& obstacles, ByVertex& built) const;

  Point s_, e_;
  std::array<Point, 4> fat_;
  const std::vector<Segment2>& obstacles_;
  std::vector<Segment2> unshaded_;
  mutable ByVertex from_unshaded_, from_all_;
};

}  // namespace nonobtuse::refine2d
