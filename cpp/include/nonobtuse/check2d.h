// Exact nonobtuse-boundary certificate of a 2D mesh.
#pragma once
#include <vector>

#include "nonobtuse/types.h"

namespace nonobtuse {

// One side of a mesh edge: the triangle on that side and the exact class of the angle opposite the edge.
struct EdgeSide {
  int triangle = -1;  // -1: no domain triangle on this side
  int apex = -1;      // the triangle's vertex opposite the edge
  AngleClass angle = AngleClass::Acute;
};

enum class EdgeKind : std::int8_t { Boundary = 0, Interface = 1, Interior = 2 };

struct EdgeReport {
  Segment edge;  // (a, b) with a < b
  EdgeKind kind;
  EdgeSide left, right;     // left: the side where (a, b, apex) is counter-clockwise
  bool locally_delaunay;    // exact incircle; meaningful for Interior and Interface edges
};

// Every edge of `mesh`, classified: Boundary = an edge with one triangle (a constrained segment, or a hull
// edge); Interface = a constrained segment (listed in mesh.segments) with triangles on both sides; Interior =
// the rest. Angles and incircle tests are exact (CGAL exact-predicates kernel) on the coordinates as stored.
// Throws InvalidInput when the triangles do not form a manifold mesh (an edge with more than two triangles).
// Cost: O(m log m) for m triangles.
std::vector<EdgeReport> classify_edges(const Mesh2& mesh);

}  // namespace nonobtuse
