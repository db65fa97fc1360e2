// Internal: the vocabulary of 2D boundary refinement. A side of a constrained subsegment, and the exact tests of
// a point against the subsegment's open diametral disk (encroachment), which every other piece decides with.
#pragma once
#include <cmath>
#include <utility>

#include "cdt.h"

namespace nonobtuse::refine2d {

using cdt::CDT;
using cdt::Edge;
using cdt::Face_handle;
using cdt::K;
using cdt::Point;
using cdt::Vertex_handle;

// One side of a constrained subsegment: the side on the left of s -> e. The work queue holds sides, not edges,
// so that an interface (a constraint with domain triangles on both sides) is two independent items.
struct Side {
  Vertex_handle s, e;
};

inline bool same_side(const Side& a, const Side& b) { return a.s == b.s && a.e == b.e; }

using Segment2 = std::pair<Point, Point>;

// Exact CGAL::angle(a, apex, b) == OBTUSE, i.e. (a - apex) . (b - apex) < 0, with a static filter (Epick's Angle_2
// has none, and the disk walks evaluate it for every vertex they meet): the dot product in doubles decides when
// its magnitude exceeds 2^-50 times the sum of the absolute products, which bounds its rounding error (four
// roundings per product term, each relative 2^-53: under 4 * 2^-53 < 2^-50 of their sum); otherwise (near zero,
// or magnitudes where underflow or overflow void the bound) CGAL decides.
inline bool obtuse(const Point& a, const Point& apex, const Point& b) {
  const double ux = a.x() - apex.x(), uy = a.y() - apex.y(), vx = b.x() - apex.x(), vy = b.y() - apex.y();
  const double dot = ux * vx + uy * vy, bound = (std::abs(ux * vx) + std::abs(uy * vy)) * 0x1p-50;
  if (bound > 0x1p-900 && bound < 0x1p+900) {
    if (dot < -bound) return true;
    if (dot > bound) return false;
  }
  return CGAL::angle(a, apex, b) == CGAL::OBTUSE;
}

// Exact encroachment of q on side (s, e): q strictly left of s -> e and strictly inside the diametral disk.
inline bool encroaches(const Point& s, const Point& e, const Point& q) {
  return CGAL::orientation(s, e, q) == CGAL::LEFT_TURN && obtuse(s, q, e);
}

// Exact: q strictly inside the open diametral disk of [s, e], on either side (not on the line). The encroacher
// lists come from walk_diametral_disk, which only collects vertices on domain sides, so for a boundary edge this
// is `encroaches`, and for an interface it treats both sides at once (t* = min over both sides' encroachers).
inline bool inside_diametral_disk(const Point& s, const Point& e, const Point& q) {
  return obtuse(s, q, e) && CGAL::orientation(s, e, q) != CGAL::COLLINEAR;  // the cheap, selective test first
}

}  // namespace nonobtuse::refine2d
