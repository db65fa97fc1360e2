// The Delaunay tetrahedralization built once (points_delaunay) and restricted to the PLC's regions from the copy;
// kept across refinement rounds (DelaunayRounds).
#include "points_delaunay.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "gabriel3d_plc.h"

namespace nonobtuse {
namespace {

// A closed surface of one-triangle facets: the convex hull of points near a sphere (every hull face is a Delaunay
// face), read off the Delaunay tetrahedralization's infinite cells, with a region seed at the centre.
PLC3 hull_of_points_near_a_sphere(int n) {
  PLC3 plc;
  for (int i = 0; i < n; ++i) {  // a Fibonacci sphere, the radius varied a little
    const double z = 1 - (2 * i + 1.0) / n, r = std::sqrt(1 - z * z), phi = 2.399963229728653 * i;
    const double scale = 1 + 0.01 * std::sin(7.0 * i);
    plc.points.push_back({scale * r * std::cos(phi), scale * r * std::sin(phi), scale * z});
  }
  const PointsDelaunay dt = points_delaunay(plc.points);
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) {
    if (!dt.is_infinite(c)) continue;
    const int i = c->index(dt.infinite_vertex());
    plc.triangles.push_back({c->vertex((i + 1) % 4)->info(), c->vertex((i + 2) % 4)->info(),
                             c->vertex((i + 3) % 4)->info()});
    plc.facet_ids.push_back(static_cast<int>(plc.facet_ids.size()));
  }
  plc.regions = {{0, 0, 0, 5.0}};
  return plc;
}

// Every output array of a restriction equal to that of restrict_delaunay (`rebuilt`).
void expect_same(const gabriel3d::Restricted& other, const gabriel3d::Restricted& rebuilt) {
  ASSERT_FALSE(rebuilt.tets.empty());
  EXPECT_EQ(other.tets, rebuilt.tets);
  EXPECT_EQ(other.tet_regions, rebuilt.tet_regions);
  EXPECT_EQ(other.boundary_faces, rebuilt.boundary_faces);
  EXPECT_EQ(other.face_markers, rebuilt.face_markers);
  EXPECT_EQ(other.face_facets, rebuilt.face_facets);
}

TEST(PointsDelaunay, RestrictingTheTriangulationBuiltOnceGivesWhatARebuildGives) {
  const PLC3 plc = hull_of_points_near_a_sphere(200);
  const gabriel3d::PlcState s = gabriel3d::build_plc_state(plc);
  gabriel3d::Restricted rebuilt = gabriel3d::restrict_delaunay(s, plc);
  PointsDelaunay dt = points_delaunay(plc.points);
  const DelaunayFaces faces = faces_and_cells(dt, plc.points.size(), plc.triangles);
  EXPECT_EQ(std::count(faces.is_face.begin(), faces.is_face.end(), 1), static_cast<long>(plc.triangles.size()));
  gabriel3d::Restricted copied = gabriel3d::restrict_delaunay(s, plc, std::move(dt));
  EXPECT_EQ(dt.number_of_vertices(), 0u);  // cleared after the copy
  expect_same(copied, rebuilt);
  EXPECT_EQ(rebuilt.boundary_faces.size(), plc.triangles.size());
  for (double r : rebuilt.tet_regions) EXPECT_EQ(r, 5.0);
}

TEST(PointsDelaunay, ATriangulationOfOtherPointsIsRefused) {
  const PLC3 plc = hull_of_points_near_a_sphere(20);
  const gabriel3d::PlcState s = gabriel3d::build_plc_state(plc);
  std::vector<PlcPoint> fewer(plc.points.begin(), plc.points.end() - 1);
  EXPECT_THROW(gabriel3d::restrict_delaunay(s, plc, points_delaunay(fewer)), InternalError);
}

TEST(PointsDelaunay, CoincidentPointsAreRefused) {
  EXPECT_THROW(points_delaunay({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}}), InvalidInput);
}

// The unit cube with one facet per square (two triangles each): its eight corners are cospherical, and so are the
// cube with its edges' midpoints, the cases where two builds can choose different tetrahedralizations.
PLC3 cube_of_square_facets() {
  PLC3 plc;
  for (int i = 0; i < 8; ++i) plc.points.push_back({double(i & 1), double(i >> 1 & 1), double(i >> 2 & 1)});
  const int squares[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (int f = 0; f < 6; ++f) {
    const int* q = squares[f];
    plc.triangles.push_back({q[0], q[1], q[2]});
    plc.triangles.push_back({q[0], q[2], q[3]});
    plc.facet_ids.push_back(f);
    plc.facet_ids.push_back(f);
  }
  return plc;
}

TEST(DelaunayRounds, TheKeptTriangulationGivesWhatARebuildGivesRoundAfterRound) {
  const PLC3 plc = cube_of_square_facets();
  gabriel3d::PlcState s = gabriel3d::build_plc_state(plc);
  gabriel3d::DelaunayRounds rounds;
  expect_same(rounds.restrict(s, plc), gabriel3d::restrict_delaunay(s, plc));
  // Three rounds: every subsegment split at its midpoint (the cube's edges, then their halves, then quarters).
  for (int round = 0; round < 3; ++round) {
    std::vector<gabriel3d::Key> pieces;
    for (const auto& [piece, parent] : s.subsegments) pieces.push_back(piece);
    for (const auto& [a, b] : pieces)
      gabriel3d::split_subsegment(s, a, b, 0.5, CGAL::midpoint(s.points[a], s.points[b]));
    const gabriel3d::Restricted kept = rounds.restrict(s, plc);
    expect_same(kept, gabriel3d::restrict_delaunay(s, plc));
    for (const Tetrahedron& t : kept.tets) EXPECT_EQ(t[0], *std::min_element(t.begin(), t.end()));
    for (const Triangle& f : kept.boundary_faces) EXPECT_EQ(f[0], *std::min_element(f.begin(), f.end()));
  }
  EXPECT_EQ(s.points.size(), 8u + 12u * 7u);
}

// Splits every subsegment of the state at its midpoint, feeding each new point to `rounds`.
void split_every_subsegment(gabriel3d::PlcState& s, gabriel3d::DelaunayRounds& rounds) {
  std::vector<gabriel3d::Key> pieces;
  for (const auto& [piece, parent] : s.subsegments) pieces.push_back(piece);
  for (const auto& [a, b] : pieces) {
    gabriel3d::split_subsegment(s, a, b, 0.5, CGAL::midpoint(s.points[a], s.points[b]));
    rounds.feed(s.points);
  }
}

TEST(DelaunayRounds, PointsInsertedWhileTheRoundRunsGiveWhatARebuildGives) {
  const PLC3 plc = cube_of_square_facets();
  gabriel3d::PlcState s = gabriel3d::build_plc_state(plc);
  gabriel3d::DelaunayRounds rounds;
  // Rounds of 12, 24, ..., 1536 new points: the last round's first 1024 in a batch the inserting thread takes while
  // the work runs, the other rounds' points when it ended; every point cospherical with many others.
  for (int round = 0; round < 8; ++round) {
    rounds.insert_while(true, [&] { split_every_subsegment(s, rounds); });
    expect_same(rounds.restrict(s, plc), gabriel3d::restrict_delaunay(s, plc));
  }
  EXPECT_EQ(s.points.size(), 8u + 12u * 255u);
}

TEST(DelaunayRounds, AnExceptionOfTheWorkIsRethrownAfterTheInsertingThreadEnded) {
  const PLC3 plc = cube_of_square_facets();
  gabriel3d::PlcState s = gabriel3d::build_plc_state(plc);
  gabriel3d::DelaunayRounds rounds;
  EXPECT_THROW(rounds.insert_while(true,
                                   [&] {
                                     split_every_subsegment(s, rounds);
                                     throw InternalError("the work failed");
                                   }),
               InternalError);
  // the points fed before the exception are in the kept triangulation, the rest follow in restrict()
  split_every_subsegment(s, rounds);
  expect_same(rounds.restrict(s, plc), gabriel3d::restrict_delaunay(s, plc));
}

}  // namespace
}  // namespace nonobtuse
