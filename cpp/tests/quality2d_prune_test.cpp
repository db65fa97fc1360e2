// Removal of boundary Steiner points after the quality refinement (quality2d_prune.cpp): by hand on a square and a
// rectangle, with the triangulation and its domain marks checked after every change (check_invariants).
#include "quality2d_prune.h"

#include <gtest/gtest.h>

#include "refine2d_state_fixtures.h"
#include "split_point.h"

namespace nonobtuse::refine2d {
namespace {

using testing::OwningState;

Domain2 rectangle(double height) {
  Domain2 d;
  d.points = {{0, 0}, {4, 0}, {4, height}, {0, height}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  return d;
}

// Splits the side s -> e at p and empties the work queue, as the quality refinement leaves it before pruning.
void split_at(State& st, Vertex_handle s, Vertex_handle e, const Point& p) {
  st.set_check_every_split(true);
  ASSERT_NE(split(st, {s, e}, p), nullptr);
  while (st.has_work()) st.next_side();
}

// Every domain face is bad, or none.
bool all_bad(Face_handle) { return true; }
bool none_bad(Face_handle) { return false; }

// The square's bottom split at (2, 0): without the point the bottom's apex is a corner of the top, a right angle
// (nonobtuse), and its two triangles are isosceles right ones: it is removed and nothing is put back.
TEST(Quality2dPrune, AnUnneededMidpointIsRemoved) {
  OwningState st(rectangle(4));
  split_at(st, st.v(0), st.v(1), Point(2, 0));
  int put_back = 0;
  EXPECT_EQ(prune_boundary_points(st, none_bad, [&](Vertex_handle) { ++put_back; }), 1);
  EXPECT_EQ(put_back, 0);
  EXPECT_EQ(st.placed(), 0);
  EXPECT_EQ(st.edges()[st.edge_of({st.v(0), st.v(1)})].steiner_points, 0);
  EXPECT_EQ(compact_added(st), std::vector<int>{-1});
  EXPECT_TRUE(st.added().empty());
  EXPECT_EQ(st.cdt().number_of_vertices(), 4u);
  EXPECT_FALSE(st.is_violated({st.v(0), st.v(1)}));
  st.check_invariants();
}

// A 4 x 1 rectangle split at (2, 0) and (2, 1): each midpoint sees the other inside the open diametral disk of the
// side it would join (the angle at (2, 1) over (0, 0)-(4, 0) has cosine -3 / 5), so neither is removed, and the
// triangulation is not touched.
TEST(Quality2dPrune, AMidpointWhoseJoinedSideWouldBeObtuseStays) {
  OwningState st(rectangle(1));
  split_at(st, st.v(0), st.v(1), Point(2, 0));
  split_at(st, st.v(2), st.v(3), Point(2, 1));
  EXPECT_EQ(prune_boundary_points(st, none_bad, [](Vertex_handle) {}), 0);
  EXPECT_EQ(st.placed(), 2);
  EXPECT_EQ(compact_added(st), (std::vector<int>{0, 1}));
}

// When the faces after the removal fail the quality test, the point is put back where it was (a new vertex, told
// to `added`) and compact_added gives it the freed index.
TEST(Quality2dPrune, AFailedRemovalIsUndone) {
  OwningState st(rectangle(4));
  split_at(st, st.v(0), st.v(1), Point(2, 0));
  int put_back = 0;
  EXPECT_EQ(prune_boundary_points(st, all_bad,
                                  [&](Vertex_handle v) {
                                    EXPECT_EQ(v->point(), Point(2, 0));
                                    ++put_back;
                                    while (st.has_work()) st.next_side();
                                  }),
            0);
  EXPECT_EQ(put_back, 1);
  EXPECT_EQ(st.placed(), 1);
  EXPECT_EQ(compact_added(st), (std::vector<int>{-1, 0}));
  ASSERT_EQ(st.added().size(), 1u);
  EXPECT_EQ(st.added()[0]->info(), 4);
  EXPECT_EQ(st.added()[0]->point(), Point(2, 0));
  st.check_invariants();
}

}  // namespace
}  // namespace nonobtuse::refine2d
