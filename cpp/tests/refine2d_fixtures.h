// Shared by the refinement tests: the domains of the paper's figures.
#pragma once
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "nonobtuse/refine2d.h"

namespace nonobtuse::testing {

// The boundary edge e = [(0,0), (100,0)] closed by a 200-edge polygonal arc just outside e's diametral circle
// (radius 50 (1 + 1e-6) around (50,0)): the arc vertices never encroach e, the arc edges' disks are tiny (radius
// ~0.4), so e is the only edge the interior points `inner` (below radius 48 of (50,0)) can encroach. The
// polygon is counter-clockwise: the domain is on the left of (0,0) -> (100,0), so greedy walks from (0,0).
inline Domain2 half_disk(const std::vector<Point2>& inner) {
  Domain2 d;
  const int k = 200;
  for (int i = 0; i <= k; ++i) {
    double a = M_PI * i / k, r = 50 * (1 + 1e-6);
    Point2 arc{50 + r * std::cos(a), r * std::sin(a)};
    d.points.push_back(i == 0 ? Point2{100, 0} : i == k ? Point2{0, 0} : arc);
  }
  for (int i = 0; i <= k; ++i) d.segments.push_back({i, (i + 1) % (k + 1)});
  for (const auto& p : inner) d.points.push_back(p);
  return d;
}

// Refines and, when converged, expects the exact certificate to be clean.
inline Refine2DResult run(const Domain2& d, RefineStrategy s, long long budget = -1) {
  Refine2DResult r = refine(d, {s, budget});
  if (r.status == RefineStatus::Converged) EXPECT_EQ(r.obtuse_boundary_sides, 0);
  return r;
}

}  // namespace nonobtuse::testing
