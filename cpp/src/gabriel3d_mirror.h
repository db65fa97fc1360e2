// Internal: mirrored facet meshes along small-dihedral segments (the mirrored strategy of the Gabriel refinement,
// after Sastry, arXiv 2105.00656). Where two facets F and G meet along an input segment at a dihedral angle below
// 90 degrees, a point placed on F near the segment is also placed at its mirror image on G (the reflection in the
// bisector plane of F and G), so that near the segment the two facet meshes are mirror images and stop encroaching
// each other (the argument is at mirrored_point's definition). Image coordinates are rounded; every decision about
// an image is an exact predicate on its rounded coordinates.
#pragma once
#include <array>
#include <optional>
#include <vector>

#include "gabriel3d_plc.h"

namespace nonobtuse::gabriel3d {

// Facet `from` mirrored into facet `to` across their common input segment `segment` (ends a, b).
struct MirrorPair {
  int from = 0, to = 0, segment = 0;
  P3 a, b;
  std::array<double, 3> along{};  // unit direction of the segment, a to b (floating point)
  std::array<double, 3> into_from{}, into_to{};  // unit, orthogonal to it, in each facet's plane toward the facet
  std::array<double, 3> lift{};    // unit normal of from's plane, turned toward to's half-plane
};

// Every ordered pair of facets through an input segment that meet there at a dihedral angle below `below_degrees`
// (both orders: F into G and G into F); facets that lie on both sides of the segment (it is inside the facet) get
// no pair. Floating point (the choice of pairs is a strategy, not a certificate). Cost: that of dihedral_angles.
std::vector<MirrorPair> mirror_pairs(const PlcState& s, double below_degrees);

// The reflection of a point p of m.from in the pair's bisector plane (equal, on from's plane, to the rotation about
// the segment that takes from's half-plane onto to's): a + ((p - a).along) along + ((p - a).into_from) into_to,
// rounded to doubles (p's tiny component off from's plane, rounding, is dropped).
P3 reflect(const MirrorPair& m, const P3& p);

// Where a mirrored point goes in facet `to`: its rounded coordinates and its location in to's triangulation.
struct MirrorImage {
  P3 point;
  FacetCDT::Locate_type lt = FacetCDT::FACE;
  FacetCDT::Face_handle loc;
  int li = 0;
};

// The image in m.to of vertex v of m.from, when v's foot on the segment's line lies strictly between its ends
// (floating point; the whole facet is mirrored, not only a band), and the rounded image is, by exact predicates:
// strictly inside to's domain, not strictly inside the diametral ball of any subsegment of to, and not strictly
// inside the diametral sphere of any subfacet of m.from incident to v (the equality cases of the argument, which
// rounding can break, are moved out: the image goes away from from's plane by relative steps of 2^-52, 2^-51, ...,
// at most 8, until it is outside those spheres and the balls of the mirror segment's subsegments). nullopt
// otherwise. Cost: O(e + k) for e constrained edges of m.to and the k subfacets around v, plus one point location.
std::optional<MirrorImage> mirrored_point(const PlcState& s, const MirrorPair& m, int v);

}  // namespace nonobtuse::gabriel3d
