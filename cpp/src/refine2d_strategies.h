// Internal: the 2D refinement strategies. Each runs on the state until its queue is empty or the budget is spent.
#pragma once

#include "refine2d_state.h"

namespace nonobtuse::refine2d {

void greedy_refine(State& state);       // greedy_refine.cpp: sensitive Greedy-Refine (paper 4.1-4.4)
void greedy_refine_queued(State& state);  // the same on the sides already queued only (after a few splits)
void projection_refine(State& state);   // projection_refine.cpp: orthogonal projection (paper 4.1)
void project_flip(State& state);        // project_flip.cpp: Project-Flip (paper 3.3)

}  // namespace nonobtuse::refine2d
