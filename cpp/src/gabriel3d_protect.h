// Internal: protecting balls at apex vertices (where an input segment leans over a facet through its end), the
// protected strategy of the Gabriel refinement. Sizes are floating point (a construction); every decision that
// uses a ball is an exact comparison of squared distances on the stored coordinates.
#pragma once
#include <functional>
#include <optional>
#include <set>
#include <vector>

#include "gabriel3d_plc.h"

namespace nonobtuse::gabriel3d {

// The ball of radius `radius` around input vertex `apex`.
struct ProtectingBall {
  int apex = -1;
  double radius = 0.0;
};

// The local feature size at input vertex v, in floating point: its distance to the nearest other input vertex and
// to the nearest input segment and facet triangle that do not contain v. HUGE_VAL when there is none.
// Cost: O(n + s + t) for n points, s segments and t facet triangles.
double local_feature_size(const PlcState& s, const PLC3& plc, int v);

// The protecting radius of an apex of local feature size lfs: the largest power of two <= lfs / 4. Balls of two
// vertices are then disjoint with a gap (r_a + r_b <= |ab| / 2), and no input feature that misses v comes within
// 3 r of the ball: inside the ball lie only v and (parts of) the segments and facets through v.
double protecting_radius(double lfs);

// The protecting balls: one at every input vertex where an input segment leans over a facet through that vertex at
// an angle below 90 degrees (the segment-facet angles of the diagnosis; the configurations whose refinement cascades
// to the floating-point resolution with concentric shells alone). Sorted by apex.
// Cost: O(a (n + s + t)) for a apices.
std::vector<ProtectingBall> protecting_balls(const PlcState& s, const PLC3& plc);

// The balls of a refinement with a lookup by point. Since balls are disjoint with gaps, the ball strictly containing
// a point, if any, is the one of the apex nearest to it.
class Protection {
 public:
  Protection(const PlcState& s, std::vector<ProtectingBall> balls);
  const std::vector<ProtectingBall>& balls() const { return balls_; }
  // The ball that holds p strictly inside (exact comparison of |p - apex|^2 with radius^2), or nullptr.
  const ProtectingBall* strictly_containing(const P3& p) const;

 private:
  const PlcState& s_;
  std::vector<ProtectingBall> balls_;
  std::vector<P3> apices_;
  PointIndex index_;
};

// The point of the ball's sphere on the ray from the apex through p (p != apex), rounded to doubles: on the sphere
// and in the plane of apex and p up to rounding. nullopt when p is the apex.
std::optional<P3> onto_sphere(const P3& apex, double radius, const P3& p);

// The power of two that cuts a piece of this size most evenly (the two parts within a 1:2 ratio): the shells
// rule's distance from an input vertex, and the angular shells' first arc piece.
double power_of_two_piece(double size);

// Concentric shells at each ball: for every input segment through an apex, calls place(from, to, t) to split the
// subsegment (from, to) at from + t (to - from) where the segment leaves the ball (distance r from the apex; both
// ends of a segment can be apices, r_a + r_b <= |ab| / 2). place returns the new point, or -1 when it placed none.
// Stops visiting once keep_going() is false. Cost: O(s) calls for s input segments.
void split_segments_on_spheres(const PlcState& s, const std::vector<ProtectingBall>& balls,
                               const std::function<int(int from, int to, double t)>& place,
                               const std::function<bool()>& keep_going);

// The protected strategy's split point for a point c strictly inside `ball` (apex on `facet`): on the ball's sphere
// (see the termination argument at the definition). segment_sphere_points: the points where segments leave balls
// (split_segments_on_spheres); arc_points: those placed on spheres by this rule before. nullopt when c is the apex or within
// 2^-26 r of it (exact comparison; its direction from the apex is then rounding noise).
std::optional<P3> arc_split_point(const PlcState& s, const Facet& facet, const ProtectingBall& ball, const P3& c,
                                  const std::set<int>& segment_sphere_points, const std::set<int>& arc_points);

}  // namespace nonobtuse::gabriel3d
