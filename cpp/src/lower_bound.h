// Internal: the lower bound on the Steiner points of any valid refinement, per input constraint edge.
#pragma once

#include "refine2d_state.h"

namespace nonobtuse::refine2d {

// Sets edges()[k].lower_bound for every input edge k of the state's (unrefined) triangulation: the single-edge
// Greedy-Refine count of the edge against the input vertices it sees (greedy_count). Call before any split.
// Large inputs (unless threads is 1): the edges alternate between two threads, each walking on its own lane.
// Cost: per edge, the triangles meeting its diametral disk, plus the greedy steps.
void lower_bound_per_edge(State& st, int threads);

}  // namespace nonobtuse::refine2d
