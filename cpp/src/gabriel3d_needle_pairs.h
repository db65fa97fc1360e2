// Internal: paired points on the two segments of a needle corner (two input segments of one facet meeting at a
// small angle, down to the 0.002 degrees marching cubes leaves next to a grid vertex), for the Gabriel refinement. A point
// split onto one segment at distance r from the corner gets a partner on the other at distance c r (or r / c), so
// that the facet's strip between them is a ladder whose rungs neither segment's points encroach (the termination
// argument is at partner_split's definition). Sizes are floating point; every decision about a partner is an exact
// predicate on its rounded coordinates.
#pragma once
#include <functional>
#include <optional>
#include <vector>

#include "gabriel3d_plc.h"

namespace nonobtuse::gabriel3d {

// Input segments seg[0] = (apex, end[0]) and seg[1] = (apex, end[1]) of facet `facet` meeting at the apex at angle
// theta. Partners: a point at distance r from the apex on seg[0] goes with the point at c r on seg[1];
// c = cos(theta / 2).
struct NeedleCorner {
  int apex = 0, facet = 0;
  int seg[2] = {0, 0}, end[2] = {0, 0};
  double c = 1.0;
  std::vector<int> around;  // the input segments at the apex (of any facet) that are sides of no needle corner
};

// The facet corners below kPairDegrees (two segments of a facet consecutive around their common vertex), and per
// input segment the indices of the corners it is a side of. Floating point angles: the choice of corners is a
// strategy, not a certificate. Cost: O(s log s) for s segments plus, per facet and vertex with m of the facet's
// segments, O(m^2) angles and O(m) more per pair below kPairDegrees.
struct NeedleCorners {
  std::vector<NeedleCorner> corners;
  std::vector<std::vector<int>> of_segment;
};
NeedleCorners needle_corners(const PlcState& s);

// Where the partner of point x (on corner.seg[side], between its neighbours xa and xb there) goes: subsegment (u, w)
// of the other segment, split at u + t (w - u) rounded to `point`.
struct PartnerSplit {
  int u = 0, w = 0;
  double t = 0.5;
  P3 point;
};

// The partner split of x, or nullopt (refused) when the partner would fall outside the other segment, onto an
// existing vertex, or when no rounding near it passes the exact checks: the partner strictly outside the diametral
// spheres of (xa, x) and (x, xb), and x strictly outside those of (u, partner) and (partner, w). Also refused when
// not needed (x and (u, w) do not encroach each other), and when the partner and the points of a segment in
// corner.around encroach each other's subsegments (exact). `near`: for a point on the other segment, a point of
// the facet near it where the point location in the facet's triangulation starts, or -1 (the apex); the result
// does not depend on it, only the length of the walk.
std::optional<PartnerSplit> partner_split(const PlcState& s, const NeedleCorner& corner, int side, int x, int xa,
                                          int xb, const std::function<int(const P3&)>& near);

}  // namespace nonobtuse::gabriel3d
