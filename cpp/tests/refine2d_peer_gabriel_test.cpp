// The benchmark peer: CGAL's conforming Gabriel refinement.
#include <gtest/gtest.h>

#include "refine2d_fixtures.h"

namespace nonobtuse {
namespace {

// Figure 5's quadrilateral: c = (90, 20) is inside the diametral disk of (a, d) = (0,0)-(100,0), so the edge is not
// Gabriel and CGAL must split it at least once; the other three edges' disks are empty.
TEST(PeerConformingGabriel, SplitsTheEncroachedEdge) {
  EXPECT_GE(conforming_gabriel_steiner_points(testing::figure5_quadrilateral()), 1);
}

}  // namespace
}  // namespace nonobtuse
