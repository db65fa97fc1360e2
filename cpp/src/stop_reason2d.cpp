// Why a 2D refinement stopped: the sentence of Refine2DDiagnosis::stop_reason, chosen from the result's status and
// counts exactly as refine2d.cpp chose the status (so the two never disagree).
#include "stop_reason2d.h"

namespace nonobtuse::refine2d {

std::string stop_reason(const Refine2DResult& r, bool quality) {
  const std::string obtuse = std::to_string(r.obtuse_boundary_sides), bad = std::to_string(r.quality.bad_triangles);
  switch (r.status) {
    case RefineStatus::Converged:
      return quality ? "every boundary side has a nonobtuse apex and every triangle meets the quality bounds outside "
                       "small input angles"
                     : "every boundary side has a nonobtuse apex";
    case RefineStatus::BudgetExhausted:
      if (r.steiner_points >= r.max_steiner) return "max_steiner (" + std::to_string(r.max_steiner) + ") reached";
      return "max_interior (" + std::to_string(r.quality.interior_budget) + ") reached";
    case RefineStatus::Stalled:
      if (r.obtuse_boundary_sides > 0)
        return obtuse + " obtuse boundary sides remain but none could be split (no point passes the exact checks)";
      return bad + " bad triangles remain whose new vertices and subsegment splits all fail the exact checks";
    case RefineStatus::MinLengthReached: break;  // 2D has no length limit
  }
  return "min_length reached";
}

}  // namespace nonobtuse::refine2d
