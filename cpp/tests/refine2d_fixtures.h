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
// The per-split invariants (Refine2DOptions::check_every_split) are checked on every run.
inline Refine2DResult run(const Domain2& d, RefineStrategy s, long long budget = -1) {
  Refine2DOptions options;
  options.strategy = s;
  options.max_steiner = budget;
  options.check_every_split = true;
  Refine2DResult r = refine(d, options);
  if (r.status == RefineStatus::Converged) EXPECT_EQ(r.obtuse_boundary_sides, 0);
  return r;
}

// Figure 5 of the paper: the convex quadrilateral a(0,0), d(100,0), c(90,20), b(0,60), counter-clockwise; only c
// encroaches (a, d) ((90 - 50)^2 + 20^2 = 2000 < 2500), and the disk of (d, c) (centre (95, 10), r^2 125) meets
// (a, d) in x in (90, 100) (Thales: 90 is the foot of c).
inline Domain2 figure5_quadrilateral() {
  Domain2 d;
  d.points = {{0, 0}, {100, 0}, {90, 20}, {0, 60}};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  return d;
}

}  // namespace nonobtuse::testing
