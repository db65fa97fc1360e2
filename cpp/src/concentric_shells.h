// Internal: concentric power-of-two shells around acute junctions, after Ruppert and Shewchuk's Triangle.
#pragma once
#include "refine2d_state.h"

namespace nonobtuse::refine2d {

// True when v is an input vertex and some other constraint at v makes an acute angle with v -> w (exact:
// CGAL::angle(w, v, u) == ACUTE for a constrained neighbour u of v), one of the two being an interior constraint
// (domain on both sides). Two boundary edges meeting at a corner are left to the forbidden intervals, for which
// Theorem 3 holds on convex polygons (shells would cost points there).
bool is_acute_junction(const State& st, Vertex_handle v, Vertex_handle w);

// The side to sweep a violated subsegment from: `side` itself, or its reverse when only the reverse starts at an
// acute junction and the reverse is a domain side too (an interface or a dangling segment), so that the first
// split lands on a shell around the junction.
Side shell_anchor(const State& st, const Side& side);

// The shell at or before s + t (e - s), for a split of [s, e] from the acute junction s whose greedy (or
// forbidden-interval) choice is t: the largest power of two 2^k <= t |e - s|, returned as a parameter of [s, e].
double shell_at_or_before(const Point& s, const Point& e, double t);

}  // namespace nonobtuse::refine2d
