// Internal: what the last scan found about a subfacet, kept on its face of the facet's triangulation, so that the
// next scan tests only the points added since. Points are only ever appended and never move, and whether a point
// encroaches a given triangle (or is ignored for it) never changes: a triangle found clean against points[0, n)
// stays clean against them. part.off scans its ~10k subfacets 52 times, with a handful of new points between two
// scans late in the run.
#pragma once
#include <functional>
#include <vector>

#include "gabriel3d_index.h"

namespace nonobtuse::gabriel3d {

struct ScanMemo {
  int a = -1, b = -1, c = -1;  // the triangle found clean (the corners as the scan listed them)
  int clean_below = -1;        // no point of index < clean_below but a, b, c encroaches it (-1: nothing known)
  SearchBall ball;             // the triangle's search ball
};

// deepest_encroacher(points, index, a, b, c, nullptr, ignore).vertex >= 0, the same answer: when memo holds abc
// clean below some index, only the points from there on are tested (the search ball, then the exact predicate),
// unless there are more than kMemoReach of them (then the kd-tree query). Updates memo.
constexpr int kMemoReach = 256;
bool encroached_since_memo(const std::vector<P3>& points, const PointIndex& index, int a, int b, int c,
                           ScanMemo& memo, const std::function<bool(int)>& ignore);

}  // namespace nonobtuse::gabriel3d
