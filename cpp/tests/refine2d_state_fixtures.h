// Shared by the tests of the refinement's internals: vertex handles of a state by point index.
#pragma once
#include <string>

#include "refine2d_state.h"

namespace nonobtuse::testing {

// The vertex of `st`'s triangulation with point index `index` (InternalError when there is none).
inline refine2d::Vertex_handle vertex(const refine2d::State& st, int index) {
  for (auto v = st.cdt().finite_vertices_begin(); v != st.cdt().finite_vertices_end(); ++v)
    if (v->info() == index) return refine2d::Vertex_handle(v);
  throw InternalError("no vertex " + std::to_string(index));
}

}  // namespace nonobtuse::testing
