// Internal: the sharp features of a 3D boundary for the small-angle rule of the interior quality refinement
// (BoundarySplitter::near_small_angle; the rule's termination argument is at refine_interior's boundary split rule
// in quality3d_interior.cpp).
#pragma once
#include <array>
#include <vector>

#include "gabriel3d_plc.h"
#include "quality3d_spheres.h"

namespace nonobtuse::quality3d {

using gabriel3d::P3;

// Sharp (floating-point angles on the boundary the features are built from): a segment through two facets at a
// dihedral angle below sharp_dihedral degrees (between the half-planes, so a reflex angle over 360 - that counts
// too), and the points on it; an apex, a point where two subsegments meet below small_apex degrees or a subsegment
// leans over a facet through it below that (gabriel3d::segment_facet_angles); near it, the apex and the midpoints
// of subsegments with an end near it (the mark follows the splits along a segment from its sharp end). 0 turns a
// clause off.
// The protecting region (the rule's distance clause): the union of the closed balls around the midpoint of each
// subsegment of a sharp segment with that subsegment's length as radius (so every point within half that length of
// it), around each apex with its shortest subsegment's length as radius, and the closed diametral spheres of the
// subsegments and subfacets with an end or corner on a sharp segment or near an apex (a split point in one of
// those encroaches the boundary at the feature and starts the restoring cascade there); all as the boundary is
// when the features are built, so the region is fixed while a pass splits the boundary.
class SharpFeatures {
 public:
  SharpFeatures(const gabriel3d::PlcState& s, double sharp_dihedral, double small_apex);

  // Is subsegment ab of s (the state the features follow) on a sharp segment or with an end near a sharp apex?
  bool sharp_subsegment(const gabriel3d::PlcState& s, int a, int b) const;
  // Is point i on a sharp segment or near a sharp apex?
  bool sharp_point(int i) const { return mark_[i] != 0; }
  // Is p in the protecting region (exact, against the rounded radii of the balls)? s: the state the features
  // were built from, points appended since.
  bool protects(const gabriel3d::PlcState& s, const P3& p) const;
  // The mark of the midpoint of subsegment ab (asked before the split): near the apex an end is near, else on the
  // subsegment's segment when that is sharp.
  char midpoint_mark(const gabriel3d::PlcState& s, int a, int b) const;
  // Records the mark of point i, appended to s (0: a subfacet circumcenter or an interior point).
  void added(int i, char mark);

 private:
  static constexpr char kOnSharpSegment = 1, kNearApex = 2;
  void mark_sharp_apexes(const gabriel3d::PlcState& s, double small_apex);
  void protect(const gabriel3d::PlcState& s);
  bool guarded(const gabriel3d::PlcState& s, int i, const P3& p) const;  // is p in guard i's ball or sphere?
  std::vector<char> sharp_segment_;  // per segment of s (the parents of subsegments): at a small dihedral angle
  std::vector<char> mark_;           // per point: 0, kOnSharpSegment or kNearApex
  struct Guard {
    std::array<int, 3> element;  // a subsegment (a, b, -1) or subfacet; a ball: (-1, -1, -1) at a sharp
                                 // subsegment's midpoint, (-1 - apex, -1, -1) at an apex
    double radius2;              // a ball's squared radius
  };
  std::vector<Guard> guards_;
  std::vector<P3> centers_;  // their search balls' centers (gabriel3d::search_ball)
  BallClasses balls_;        // their search balls, by guard index
};

}  // namespace nonobtuse::quality3d
