// Internal: why a 2D refinement stopped (Refine2DDiagnosis::stop_reason), in the words of the 3D refinement's
// stop reasons (gabriel3d_refine.cpp): the budget reached by its option's name, or what is left that no split fixes.
#pragma once
#include <string>

#include "nonobtuse/refine2d.h"

namespace nonobtuse::refine2d {

// The stop reason of `r`, whose status, counts and budgets are final; `quality`: whether an interior quality
// option was given (Quality2DOptions::enabled). Converged: what the certificate (and the quality bounds) say;
// BudgetExhausted: "max_steiner (N) reached" or "max_interior (N) reached"; Stalled: what is left and why.
std::string stop_reason(const Refine2DResult& r, bool quality);

}  // namespace nonobtuse::refine2d
