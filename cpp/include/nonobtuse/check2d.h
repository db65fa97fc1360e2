// Exact nonobtuse-boundary certificate of a 2D mesh.
#pragma once
#include <cstdint>
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
  bool locally_delaunay;    // exact incircle; meaningful for Interior and Interface edges (true for Boundary)
};

// Every edge of `mesh`, classified, sorted by (a, b):
//   Boundary  = an edge with a triangle on one side only (a constrained segment, or a hull edge);
//   Interface = an edge with triangles on both sides that is a constrained segment (listed in mesh.segments), or
//               whose two triangles carry different region attributes (a material jump: each side is weighted by
//               its own conductivity, so each side must be nonobtuse on its own);
//   Interior  = the rest.
// Angles (CGAL::angle at the apex) and incircle tests (side_of_oriented_circle) are exact (CGAL
// exact-predicates kernel) on the coordinates as stored.
// Guarantees: every edge of every triangle appears exactly once; a Boundary edge has its triangle on the left or
// on the right side and -1 on the other.
// Throws InvalidInput when a triangle is not strictly counter-clockwise (degenerate or clockwise), when the
// triangles do not form a consistently oriented manifold mesh (an edge with more than two triangles, or two on
// the same side), when the triangles around a vertex overlap (they wind around an interior vertex other than
// exactly once, or cover some direction from a boundary vertex twice: decided exactly, by coordinate comparisons
// and orientations; this local test does not detect two parts of a mesh that overlap without sharing a vertex),
// or when a listed segment is not an edge of any triangle.
// Cost: O(n + m) for n points and m triangles (half-edges bucketed by their smaller vertex), plus O(k) for k
// segments; on two threads for large meshes unless threads is 1 (the result is the same).
std::vector<EdgeReport> classify_edges(const Mesh2& mesh, int threads = 2);

// The exact nonobtuse-boundary certificate: the number of sides of Boundary and Interface edges (as classified by
// classify_edges) whose triangle is obtuse at the apex opposite the edge; 0 iff every such side is nonobtuse.
// The same checks and exceptions as classify_edges, but angles only on those sides and no incircle test.
// Cost: O(n + m) plus O(k) for k segments, on threads as classify_edges.
long long count_obtuse_boundary_sides(const Mesh2& mesh, int threads = 2);

}  // namespace nonobtuse
