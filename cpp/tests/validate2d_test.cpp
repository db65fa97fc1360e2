#include "nonobtuse/validate2d.h"

#include <gtest/gtest.h>

#include <cmath>

namespace nonobtuse {
namespace {

using Pairs = std::vector<std::array<int, 2>>;

TEST(Validate2dIntersections, ProperCrossingIsReported) {
  // The diagonals of the unit square cross at (0.5, 0.5), an endpoint of neither.
  auto r = find_segment_intersections({{0, 0}, {1, 1}, {0, 1}, {1, 0}}, {{0, 1}, {2, 3}});
  EXPECT_EQ(r.crossings, (Pairs{{0, 1}}));
  EXPECT_TRUE(r.points_on_segments.empty());
  EXPECT_TRUE(r.overlaps.empty());
}

TEST(Validate2dIntersections, SharedEndpointsAreNotCrossings) {
  // A closed triangle plus a segment from a vertex out of it: every pair meets at a common endpoint only.
  auto r = find_segment_intersections({{0, 0}, {4, 0}, {0, 4}, {5, 5}}, {{0, 1}, {1, 2}, {2, 0}, {1, 3}});
  EXPECT_TRUE(r.crossings.empty());
  EXPECT_TRUE(r.points_on_segments.empty());
  EXPECT_TRUE(r.overlaps.empty());
}

TEST(Validate2dIntersections, TJunctionIsAPointOnASegment) {
  // Point 2 = (1, 0) lies strictly inside segment 0 from (0, 0) to (2, 0); segment 1 starts there: a T, no crossing.
  auto r = find_segment_intersections({{0, 0}, {2, 0}, {1, 0}, {1, 1}, {3, 3}}, {{0, 1}, {2, 3}});
  EXPECT_TRUE(r.crossings.empty());
  EXPECT_EQ(r.points_on_segments, (Pairs{{2, 0}}));
  EXPECT_TRUE(r.overlaps.empty());
}

TEST(Validate2dIntersections, IsolatedPointOnASegmentAndNearMiss) {
  // (0.5, 0.5) is on the diagonal from (0,0) to (1,1); (0.5, 0.5000000000000001) is not: exact predicates.
  auto r = find_segment_intersections({{0, 0}, {1, 1}, {0.5, 0.5}, {0.5, 0.5000000000000001}}, {{0, 1}});
  EXPECT_EQ(r.points_on_segments, (Pairs{{2, 0}}));
}

TEST(Validate2dIntersections, CollinearOverlapAndCollinearTouch) {
  // On the x-axis: s0 = [0,2], s1 = [1,3] overlap on [1,2]; s2 = [3,4] only touches s1 at x = 3.
  std::vector<Point2> p{{0, 0}, {2, 0}, {1, 0}, {3, 0}, {4, 0}};
  auto r = find_segment_intersections(p, {{0, 1}, {2, 3}, {3, 4}});
  EXPECT_EQ(r.overlaps, (Pairs{{0, 1}}));
  EXPECT_TRUE(r.crossings.empty());
  // x = 1 lies inside s0, x = 2 inside s1.
  EXPECT_EQ(r.points_on_segments, (Pairs{{1, 1}, {2, 0}}));
}

TEST(Validate2dIntersections, SegmentsSharingAnEndpointOverlapOnlyWhenCollinearAndSameWay) {
  // From (0,0): s0 to (2,0) and s1 to (1,0) overlap on [0,1]; s2 to (-1,0) is collinear but on the other side;
  // s3 to (0,1) turns; s4 repeats s0 reversed. Pairs sharing an endpoint index take a shortcut: checked here.
  std::vector<Point2> p{{0, 0}, {2, 0}, {1, 0}, {-1, 0}, {0, 1}};
  auto r = find_segment_intersections(p, {{0, 1}, {0, 2}, {3, 0}, {0, 4}, {1, 0}});
  EXPECT_EQ(r.overlaps, (Pairs{{0, 1}, {0, 4}, {1, 4}}));
  EXPECT_TRUE(r.crossings.empty());
  EXPECT_EQ(r.points_on_segments, (Pairs{{2, 0}, {2, 4}}));
}

TEST(Validate2dIntersections, BadIndexIsInvalidInput) {
  EXPECT_THROW(find_segment_intersections({{0, 0}, {1, 0}}, {{0, 2}}), InvalidInput);
}

Domain2 square() {
  Domain2 d;
  d.points = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  return d;
}

TEST(Validate2dCoverage, ClosedSquareWithCrackHoleAndSeeds) {
  Domain2 d = square();
  d.points.insert(d.points.end(), {{1, 1}, {2, 1}, {1, 2}, {3, 3}, {3.5, 2}});
  d.segments.insert(d.segments.end(), {{4, 5}, {5, 6}, {6, 4}, {7, 8}});  // a triangular hole loop; a crack
  d.holes = {{1.25, 1.25}, {9, 9}, {3, 3}, {3, 1}};  // in the loop; outside the hull; on a point; in the square
  d.regions = {{{3, 1}, 1.0}, {{2, 0}, 2.0}, {{-1, 2}, 3.0}, {{1.2, 1.2}, 4.0}};  // in, on segment 0, out, in hole
  DomainCoverage c = inspect_domain(d);
  EXPECT_TRUE(c.encloses_area);
  // A hole seed inside any closed loop is Inside, even (3, 1), which removes the square's whole interior.
  EXPECT_EQ(c.holes, (std::vector<SeedPlace>{SeedPlace::Inside, SeedPlace::Outside, SeedPlace::OnBoundary,
                                             SeedPlace::Inside}));
  EXPECT_EQ(c.domain_triangles, 0);
  EXPECT_EQ(c.segments_outside, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));  // all in a hole now
  d.holes.resize(1);
  c = inspect_domain(d);
  EXPECT_TRUE(c.segments_outside.empty());  // the crack has the domain on both sides, the loop on one side
  EXPECT_EQ(c.regions, (std::vector<SeedPlace>{SeedPlace::Inside, SeedPlace::OnBoundary, SeedPlace::Outside,
                                               SeedPlace::Outside}));
  EXPECT_EQ(c.domain_triangles, 11);  // 9 points, 4 on the hull: 2*9 - 4 - 2 = 12, minus the hole triangle
}

TEST(Validate2dCoverage, OpenBoundaryLeavesSegmentsOutside) {
  // box.poly in small: a square hole loop (with a hole seed) and one side of the outer square.
  Domain2 d;
  d.points = {{0, 0}, {0, 3}, {3, 0}, {3, 3}, {1, 1}, {1, 2}, {2, 1}, {2, 2}};
  d.segments = {{0, 1}, {4, 6}, {6, 7}, {7, 5}, {5, 4}};
  d.holes = {{1.5, 1.5}};
  DomainCoverage c = inspect_domain(d);
  EXPECT_TRUE(c.encloses_area);  // the inner square
  EXPECT_EQ(c.domain_triangles, 0);
  EXPECT_EQ(c.segments_outside, (std::vector<int>{0, 1, 2, 3, 4}));
  d.convex_hull_boundary = true;  // Triangle -c: the hull closes it; 8 points, 4 on the hull: the ring has 8 triangles
  c = inspect_domain(d);
  EXPECT_EQ(c.domain_triangles, 8);
  EXPECT_TRUE(c.segments_outside.empty());
  EXPECT_EQ(c.holes, (std::vector<SeedPlace>{SeedPlace::Inside}));
}

TEST(Validate2dCoverage, DanglingSegmentsAloneEncloseNothing) {
  Domain2 d;
  d.points = {{0, 0}, {2, 0}, {1, 1}};
  d.segments = {{0, 1}};
  DomainCoverage c = inspect_domain(d);
  EXPECT_FALSE(c.encloses_area);
  EXPECT_EQ(c.segments_outside, (std::vector<int>{0}));
}

TEST(Validate2dCoverage, CollinearPointsCoverNothing) {
  Domain2 d;
  d.points = {{0, 0}, {1, 0}, {3, 0}};
  d.segments = {{0, 1}};
  d.holes = {{2, 0}};
  d.regions = {{{2, 0}, 1.0}};
  DomainCoverage c = inspect_domain(d);
  EXPECT_FALSE(c.encloses_area);
  EXPECT_EQ(c.domain_triangles, 0);
  EXPECT_EQ(c.segments_outside, (std::vector<int>{0}));
  EXPECT_EQ(c.regions, (std::vector<SeedPlace>{SeedPlace::Outside}));
  EXPECT_EQ(c.holes, (std::vector<SeedPlace>{SeedPlace::Outside}));
}

// Past the candidate-pair budget (a fan of 400 long, nearly parallel segments: about 80,000 box pairs, over
// 8 * (800 + 400) + 1024) the report is the same: empty for the fan, and the 100 crossings of a chord added to it found.
TEST(Validate2d, ManyBoxPairsStillReportExactly) {
  std::vector<Point2> p;
  std::vector<Segment> s;
  for (int i = 0; i < 400; ++i) {
    const double a = 0.7 + 1e-4 * i;
    p.push_back({0.5 * std::cos(a), 0.5 * std::sin(a)});
    p.push_back({std::cos(a), std::sin(a)});
    s.push_back({2 * i, 2 * i + 1});
  }
  EXPECT_TRUE(find_segment_intersections(p, s).crossings.empty());
  p.push_back({0.75 * std::cos(0.68), 0.75 * std::sin(0.68)});
  p.push_back({0.75 * std::cos(0.70995), 0.75 * std::sin(0.70995)});
  s.push_back({800, 801});
  const auto r = find_segment_intersections(p, s);
  EXPECT_EQ(r.crossings.size(), 100u);  // the segments at angles 0.7 .. 0.7099 cross it
  EXPECT_TRUE(r.points_on_segments.empty());
}

TEST(Validate2dCoverage, SegmentThroughAPointIsInvalidInput) {
  Domain2 d = square();
  d.points.push_back({2, 0});  // inside segment 0
  EXPECT_THROW(inspect_domain(d), InvalidInput);
}

}  // namespace
}  // namespace nonobtuse
