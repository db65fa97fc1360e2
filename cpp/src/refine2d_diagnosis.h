// Internal: the provenance of the greedy work queue, for Refine2DDiagnosis.
#pragma once
#include <algorithm>
#include <map>
#include <utility>
#include <vector>

#include "nonobtuse/refine2d_diagnosis.h"

namespace nonobtuse::refine2d {

// Every subsegment swept carries a cause: the initial violation whose refinement queued it. A subsegment swept
// without a cause starts a new one; subsegments queued during a sweep inherit the sweep's cause (unless they
// already have one), and so do the Steiner points it places. Keys are vertex indices, unordered.
class Propagation {
 public:
  void begin(int s, int e, long long placed);
  void queued(int s, int e);
  void end(long long placed);
  int causes() const { return causes_; }
  // Cause of added vertex k (0-based among the vertices added after the input, State::added); -1 for points
  // placed outside a sweep (interior points among them).
  int steiner_cause(long long k) const {
    return k < static_cast<long long>(cause_of_point_.size()) ? cause_of_point_[k] : -1;
  }
  // Added vertex k becomes vertex to[k] (-1: removed), as State's compact_added renumbers them.
  void renumber(const std::vector<int>& to);

 private:
  static std::pair<int, int> key(int s, int e) { return {std::min(s, e), std::max(s, e)}; }
  std::map<std::pair<int, int>, int> cause_;
  std::vector<int> cause_of_point_;
  int causes_ = 0, current_ = -1;
};

class State;

// The diagnosis of a finished refinement: Steiner points per junction and per input angle (each point goes to the
// nearer end of its input edge), and the propagation of the causes. Cost: O(n + Steiner points + segments).
Refine2DDiagnosis diagnose(const State& st);

}  // namespace nonobtuse::refine2d
