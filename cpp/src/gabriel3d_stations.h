// Internal: stations on groups of near-parallel close input segments, used by the protected rerun of the Gabriel
// refinement (gabriel3d_refine_stations.cpp). Two input segments whose ends lie pairwise within 1e-5 of their length
// are partners (a thin strip: step.off's 1-6 and 5-9, 6.4e-4 apart over 2,168, with its diagonal 5-6; a needle
// facet's two long sides); a group is a connected set of partners, joined by the segments that leave a member's end
// at under 1 degree (whose shells are centred there). A point placed on a grouped segment is placed on every other
// segment of the group (one station): at the same distance from a shared end, else at the foot of the perpendicular.
//
// Termination argument (the split rule is the shells rule; a station adds the images of each split point):
// - Two segments through an apex e at angle theta with points at radii r_i and r'_i from e: a point at radius s on
//   one is strictly inside the diametral ball of the piece [r_i, r_{i+1}] of the other iff s^2 - s (r_i + r_{i+1})
//   cos(theta) + r_i r_{i+1} < 0, never when s = r_i or s = r_{i+1} exactly and only within a relative theta^2 / 2 of
//   them: equal radii keep both segments Gabriel for any spacing (concentric shells without the powers of two). The
//   images are stretched by sin^2(theta) / 4 toward the segment of higher index (inside that window) so that two
//   pairs are never exactly cocircular (an isosceles trapezoid is cyclic: the facets' 2D triangulation and the 3D
//   Delaunay mesh then disagree by rounding).
// - Partners without a shared end at distance h: a point whose foot falls a distance delta inside a piece of length L
//   encroaches it iff h^2 < delta (L - delta); the foot gives delta = 0 up to the tilt (h times the angle, 1e-8 on
//   step.off), so no piece shorter than h^2 / (h angle) (thousands of units there) is encroached by the group.
// - So points of a group never encroach the group's pieces (in exact arithmetic); each image's rounding is searched
//   among nearby doubles until the exact tests against its station's points pass (station_rounding), and splits of
//   a grouped segment come only from encroachers outside the group, as in Ruppert's argument. The leaning facets
//   (a grouped segment over a facet through its partner, below 90 degrees) get the feet of the station's points,
//   on the perpendicular through the partner's point: a point above a facet vertex, at height d, is outside every
//   circumsphere through that vertex (margin d^2) and outside the others by the facet's Delaunay property. What is
//   not argued: the rest of the PLC (small dihedrals, handled by the protected strategy and the mirrored facet
//   meshes) and rounding below radius ~1e-3 at apices of 1e-7 rad, where no double fits the window (no verified
//   rounding: the plain one is used and the exact check of the result decides). The budgets bound the pass.
#pragma once
#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <vector>

#include "gabriel3d_plc.h"

namespace nonobtuse::gabriel3d {

// Image of a point of input segment `from` on input segment `to`: at the same distance from `apex` (their shared
// end), or at the foot of the perpendicular when apex == -1.
struct StationLink {
  int from = 0, to = 0, apex = -1;
};

class Stations {
 public:
  explicit Stations(const PlcState& s);  // finds the groups among the input segments (floating point)
  bool empty() const { return trees_.empty(); }
  bool grouped(int segment) const { return trees_.count(segment) > 0; }
  // The links to follow from a point on `segment`: a spanning tree of its group, parents before children, the
  // links through a shared end before those by the foot.
  const std::vector<StationLink>& tree(int segment) const { return trees_.at(segment); }
  // Is input vertex v an end of a grouped segment? (Protecting balls are not placed there: their sphere points,
  // 1e-4 from an apex of 1e-7 rad, cannot be matched in doubles.)
  bool at_end(int v) const { return std::binary_search(ends_.begin(), ends_.end(), v); }
  // The input vertices that are a shared end of two segments of a group (their stations are placed first).
  const std::vector<int>& apices() const { return apices_; }

 private:
  std::map<int, std::vector<StationLink>> trees_;
  std::vector<int> apices_;
  std::vector<int> ends_;
};

// The distance from link.apex of the image of p (apex links only): |p - apex| (1 + sin^2 / 4) toward the segment of
// higher index, divided by that toward the lower one, so that no two pairs of a station are exactly cocircular.
double station_radius(const PlcState& s, const StationLink& link, const P3& p);

// The parameter t in (0, 1) on input segment `link.to` (ends a, b: a + t (b - a)) of the image of point p of
// `link.from`, or nullopt when the image is not strictly inside it. Floating point.
std::optional<double> station_parameter(const PlcState& s, const StationLink& link, const P3& p);

// A double point near `ideal` for which accept() holds, or nullopt when none of the candidates tried does. With an
// apex (apex != nullptr): the points within kStationSearch ulps of `ideal` in the two coordinates along which the
// distance to the apex changes most, and in the third the few whose distance to the apex is closest to `radius`
// (floating point: differences of nearby doubles are exact), tried by increasing distance error; else the points
// within one ulp in each coordinate, fewest ulps first.
constexpr int kStationSearch = 12;
std::optional<P3> station_rounding(const P3& ideal, const P3* apex, double radius,
                                   const std::function<bool(const P3&)>& accept);

}  // namespace nonobtuse::gabriel3d
