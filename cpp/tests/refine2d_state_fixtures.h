// Shared by the tests of the refinement's internals: a state that owns its domain, vertex handles by point index.
#pragma once
#include <string>
#include <utility>

#include "refine2d_state.h"

namespace nonobtuse::testing {

// The vertex of `st`'s triangulation with point index `index` (InternalError when there is none).
inline refine2d::Vertex_handle vertex(const refine2d::State& st, int index) {
  for (auto v = st.cdt().finite_vertices_begin(); v != st.cdt().finite_vertices_end(); ++v)
    if (v->info() == index) return refine2d::Vertex_handle(v);
  throw InternalError("no vertex " + std::to_string(index));
}

// The domain an OwningState refers to, as a base so that it is built before the State and dies after it.
struct OwnedDomain {
  const Domain2 owned;
};

// A refinement state on a domain it owns: a State keeps a reference to its Domain2, so a State built on a temporary
// domain would dangle. Not copyable or movable (the reference would follow the copy's source).
class OwningState : private OwnedDomain, public refine2d::State {
 public:
  explicit OwningState(Domain2 d, long long budget = 10) : OwnedDomain{std::move(d)}, State(owned, budget) {}
  OwningState(const OwningState&) = delete;
  OwningState& operator=(const OwningState&) = delete;

  // The vertex with point index `index` (InternalError when there is none).
  refine2d::Vertex_handle v(int index) const { return vertex(*this, index); }
};

}  // namespace nonobtuse::testing
