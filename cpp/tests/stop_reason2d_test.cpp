// Why a 2D refinement stopped (stop_reason2d.cpp): each status's sentence, on results built by hand and on real runs
// of Figure 5's quadrilateral (one Steiner point at (90, 0), greedy_refine_test.cpp).
#include <gtest/gtest.h>

#include <string>

#include "nonobtuse/refine2d.h"
#include "stop_reason2d.h"

namespace nonobtuse {
namespace {

Domain2 figure5() { return Domain2{{{0, 0}, {100, 0}, {90, 20}, {0, 60}}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}, {}, {}}; }

TEST(StopReason2D, EachStatusHasItsSentence) {
  Refine2DResult r;
  r.status = RefineStatus::Converged;
  EXPECT_EQ(refine2d::stop_reason(r, false), "every boundary side has a nonobtuse apex");
  EXPECT_EQ(refine2d::stop_reason(r, true).rfind("every boundary side has a nonobtuse apex and every triangle", 0), 0u);
  r.status = RefineStatus::BudgetExhausted;
  r.steiner_points = r.max_steiner = 7;
  EXPECT_EQ(refine2d::stop_reason(r, true), "max_steiner (7) reached");
  r.max_steiner = 8;
  r.quality.interior_points = r.quality.interior_budget = 12;
  EXPECT_EQ(refine2d::stop_reason(r, true), "max_interior (12) reached");
  r.status = RefineStatus::Stalled;
  r.obtuse_boundary_sides = 2;
  EXPECT_EQ(refine2d::stop_reason(r, false).rfind("2 obtuse boundary sides remain but none could be split", 0), 0u);
  r.obtuse_boundary_sides = 0;
  r.quality.bad_triangles = 3;
  EXPECT_EQ(refine2d::stop_reason(r, true).rfind("3 bad triangles remain", 0), 0u);
}

TEST(StopReason2D, RefineReportsTheBudgetItReached) {
  Refine2DResult done = refine(figure5());
  EXPECT_EQ(done.status, RefineStatus::Converged);
  EXPECT_EQ(done.diagnosis.stop_reason, "every boundary side has a nonobtuse apex");
  Refine2DOptions o;
  o.max_steiner = 0;
  Refine2DResult none = refine(figure5(), o);
  EXPECT_EQ(none.status, RefineStatus::BudgetExhausted);
  EXPECT_EQ(none.diagnosis.stop_reason, "max_steiner (0) reached");
  o.max_steiner = -1;
  o.quality.max_area = 100.0;  // the quadrilateral's area is 4,100
  o.quality.max_interior = 0;
  Refine2DResult capped = refine(figure5(), o);
  ASSERT_GT(capped.quality.bad_triangles, 0);
  EXPECT_EQ(capped.status, RefineStatus::BudgetExhausted);
  EXPECT_EQ(capped.diagnosis.stop_reason, "max_interior (0) reached");
}

}  // namespace
}  // namespace nonobtuse
