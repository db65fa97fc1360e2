// Internal: where the Gabriel refinement splits an encroached subsegment: the shells rule (powers of two from an
// input vertex) and the greedy rule (the longest piece free of the current encroachers). The refinement loop that
// calls them is gabriel3d_refine.cpp; the termination arguments are at the definitions.
#pragma once
#include <optional>

#include "gabriel3d_index.h"
#include "gabriel3d_plc.h"

namespace nonobtuse::gabriel3d {

// a + t (b - a), rounded to doubles coordinate by coordinate (every subsegment split point is this rounding).
P3 interpolate(const P3& a, const P3& b, double t);

// The shells rule's split parameter t of subsegment [pa, pb]: 0.5 unless exactly one end is an input vertex
// (a_input, b_input), then the power of two from that end that cuts the subsegment most evenly. Cost: O(1).
double shell_cutting_evenly(const P3& pa, const P3& pb, bool a_input, bool b_input);

// The greedy rule's split parameter t of subsegment (a, b) of s, against its current encroachers (the points of
// `index` strictly inside its diametral sphere, plus `pending` when given): the end of the longest free prefix from
// either end, verified exactly after rounding. nullopt (the caller uses the shells rule) when there is no
// encroacher, when the prefix or the rest would be under 1/4 of the subsegment, or when the point rounds onto an
// existing vertex. Cost: one range query of the index plus O(k) per rounding step for k encroachers.
std::optional<double> greedy_split_parameter(const PlcState& s, const PointIndex& index, int a, int b,
                                             const P3* pending);

}  // namespace nonobtuse::gabriel3d
