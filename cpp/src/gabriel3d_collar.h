// Internal: segment collars of the protected Gabriel strategy. The collar of a subsegment [p, q] in a facet through
// it is the circle of the facet's plane with diameter pq (the facet's section of the subsegment's diametral ball);
// points of the facet near the segment go on these circles instead of splitting the segment (the termination
// argument is at collar_split_point's definition).
#pragma once
#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "gabriel3d_plc.h"

namespace nonobtuse::gabriel3d {

// The collar point for a split point c strictly inside the diametral ball of subsegment [p, q], c in a plane through
// p and q: the point of the circle with diameter pq in that plane on the ray from the midpoint through c, rounded to
// doubles and then verified with exact predicates: it is not strictly inside the diametral ball of [p, q], and
// `held` (an exact test: the point strictly inside the diametral ball of another subsegment of the facet, e.g. a
// neighbour of [p, q] on its segment, whose ball is tangent to [p, q]'s at the shared end) is false for it. A
// rounded point that fails is moved outward along the ray by relative steps of 2^-52, 2^-51, ... (at most 8 steps).
// nullopt when c is the midpoint, when the steps do not get it out, or when the point is p or q. `normal`: the unit
// normal of the facet's plane, when known; the ray's direction is then projected onto the plane, so that the
// rounding of c off the plane, which the move multiplies by radius / |c - m|, does not carry the point off it. Cost:
// at most 8 calls of held.
std::optional<P3> collar_split_point(const P3& p, const P3& q, const P3& c,
                                     const std::function<bool(const P3&)>& held,
                                     const std::array<double, 3>* normal = nullptr);

// Every dihedral angle between two facets through an input segment (kind "dihedral", vertices {a, b}, facets: the
// two facet ids), in degrees, floating point; read before refinement (unsplit segments). Cost: O(s f^2) for s
// segments through at most f facets each.
std::vector<InputAngle> dihedral_angles(const PlcState& s);

// Per input segment: it gets collars (two facets through it meet at a dihedral angle below 90 degrees, where the
// chain along the segment starts; flatter pairs, e.g. the ridges of a smooth scanned surface, keep the ordinary
// rule, which measured fewer points there). Cost: that of dihedral_angles.
std::vector<bool> collared_segments(const PlcState& s);

// collar_split_point for subsegment `sub` and a split point c of `facet` through it (with the facet's normal), when
// sub's input segment is collared (collared_segments); else nullopt. `held`: as for collar_split_point, over every
// subsegment of the facet.
std::optional<P3> facet_collar_point(const PlcState& s, const Facet& facet, const std::vector<bool>& collared,
                                     const Key& sub, const P3& c, const std::function<bool(const P3&)>& held);

}  // namespace nonobtuse::gabriel3d
