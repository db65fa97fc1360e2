// Baseline (paper section 3.3): Project-Flip. While some boundary triangle (a, b, c) is obtuse at c, insert the
// foot d of c on (a, b); CGAL splits the constrained edge, which replaces (a, b, c) by (a, d, c) and (d, b, c),
// and restores the constrained Delaunay property by edge flips. The foot of an obtuse apex lies strictly inside
// (a, b), so each step makes progress; O(n) points on polygons (paper), and the budget bounds it in any case.
#include "refine2d_strategies.h"
#include "split_point.h"

namespace nonobtuse::refine2d {

void project_flip(State& st) {
  st.enqueue_all();
  while (st.has_work() && st.budget_left()) {
    Side side = st.next_side();
    if (st.is_violated(side)) split_at_foot(st, side, st.apex(side)->point());
  }
}

}  // namespace nonobtuse::refine2d
