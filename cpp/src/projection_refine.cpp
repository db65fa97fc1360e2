// Baseline (paper section 4.1): orthogonal projection. For a violated boundary side, one Steiner point at the
// foot of every encroaching visible vertex (strictly inside the half-disk, found by the disk walk), then the
// new subsegments are re-examined, until no side is violated. Each foot splits the side strictly inside
// (an encroacher projects strictly between s and e), so each round makes progress; the budget bounds the rounds.
#include <algorithm>

#include "refine2d_strategies.h"
#include "split_point.h"
#include "visibility.h"

namespace nonobtuse::refine2d {

void projection_refine(State& st) {
  st.enqueue_all();
  while (st.has_work() && st.budget_left()) {
    Side side = st.next_side();
    if (!st.is_violated(side)) continue;
    std::vector<Vertex_handle> q = walk_diametral_disk(st, side).encroachers;
    const Point &s = side.s->point(), &e = side.e->point();
    std::sort(q.begin(), q.end(), [&](Vertex_handle a, Vertex_handle b) {
      return foot_parameter(s, e, a->point()) < foot_parameter(s, e, b->point());
    });
    Side cur = side;
    for (Vertex_handle v : q) {  // feet in order along s -> e: each splits the remaining subsegment [cur.s, e]
      if (!st.budget_left()) break;
      Vertex_handle p = split_at_foot(st, cur, v->point());
      if (p != nullptr) cur = {p, side.e};
    }
  }
}

}  // namespace nonobtuse::refine2d
