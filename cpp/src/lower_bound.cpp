// The lower bound. For each input boundary edge E, every subsegment of E in any valid refinement has an open
// half-disk free of the vertices it sees, in particular of the input vertices. Greedy-Refine of E against the
// input vertices alone is optimal for that weaker single-edge problem (Theorem 2: the greedy end is as far as
// any solution's first point can be, by the exchange argument, which holds because a piece of a valid
// subsegment is valid: its disk lies in the subsegment's and it sees no more), and more vertices only add
// constraints, so no refinement placing Steiner points on E uses fewer. Edges are disjoint, so the bounds add.
// Visibility: a vertex counts for a subsegment only when some point of the open subsegment sees it, tested
// exactly against the constraints the walk over E's disk meets (Sight, covered_from: the first constraint on
// every sight line from E inside the disk is one of them). The walk is Walked::Seen: it skips the faces behind
// the constraints it meets (the spikes of a spiky polygon that E does not see), which leaves those first
// constraints and the vertices seen, so the bound is the one the full walk gives. A vertex that the walk merely reaches, around the
// free end of a dangling segment or an end on the circle, does not count: the bound never counts a vertex that
// a valid refinement could leave in the disk, which is what makes it a lower bound.
// An interface edge is one single-edge problem with the encroachers of both sides (the walk collects both).
#include "lower_bound.h"

#include <utility>
#include <vector>

#include "fork_join.h"
#include "greedy_edge.h"

namespace nonobtuse::refine2d {

void lower_bound_per_edge(State& st, int threads) {
  std::vector<std::pair<int, Side>> first_side;  // (input edge, its first boundary side)
  std::vector<bool> bounded(st.edges().size(), false);
  for (const Side& side : st.boundary_sides()) {
    int k = st.edge_of(side);
    if (!bounded[k]) first_side.emplace_back(k, side);
    bounded[k] = true;
  }
  // Each lane writes the bounds of its own edges only.
  auto lower_bounds = [&](int lane) {
    for (std::size_t i = lane; i < first_side.size(); i += 2) {
      const auto& [k, side] = first_side[i];
      st.set_lower_bound(k, greedy_count(st, side, walk_diametral_disk(st, side, lane, Walked::Seen)));
    }
  };
  fork_join(worth_forking(st.cdt().number_of_faces(), threads), [&] { lower_bounds(0); }, [&] { lower_bounds(1); });
}

}  // namespace nonobtuse::refine2d
