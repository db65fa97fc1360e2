// Where the Steiner points of a 2D refinement went: junctions, input angles, propagation.
#pragma once
#include <string>
#include <vector>

#include "nonobtuse/types.h"

namespace nonobtuse {

// An input vertex where at least two input constraints meet.
struct JunctionStats {
  int vertex = -1;            // input point index
  int constraints = 0;        // input constraints meeting there
  double min_angle_degrees = 0;  // smallest angle between two of them (float, for reporting only)
  long long steiner_points = 0;  // Steiner points whose nearest end on their input edge is this vertex
};

// The angle at `vertex` between input constraints (vertex, a) and (vertex, b): b is the constraint closest in angle
// to (vertex, a); Steiner points on (vertex, a) nearest to `vertex` count here.
struct InputAngleStats {
  int vertex = -1, a = -1, b = -1;
  double degrees = 0;
  long long steiner_points = 0;
};

struct Refine2DDiagnosis {
  std::vector<JunctionStats> junctions;  // at most 10, with Steiner points, by decreasing count (then index)
  std::vector<InputAngleStats> angles;   // at most 10, likewise
  int initial_violations = 0;  // violated subsegments met first in the queue with no cause: one cause each
  // Propagation of one initial violation: the Steiner points placed while refining it and everything its points
  // queued, transitively. Depth = the most distinct input edges one cause put Steiner points on; splits = the
  // most Steiner points one cause placed (greedy strategy only; 0 for the baselines).
  int propagation_depth = 0;
  long long propagation_splits = 0;
  // Why the refinement stopped, in the 3D refinement's words (Refine3DDiagnosis::stop_reason): "every boundary
  // side has a nonobtuse apex" (and, with quality options, the bounds met), "max_steiner (N) reached",
  // "max_interior (N) reached", or what is left that no split fixes (stop_reason2d.cpp).
  std::string stop_reason;
};

}  // namespace nonobtuse
