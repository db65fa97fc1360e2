// Internal: the boundary rules of the interior quality refinement (quality2d_boundary.cpp): which input angles are
// small, and how a boundary side is split (midpoint, concentric shell, the greedy rule at small boundary corners).
#pragma once
#include <array>
#include <functional>
#include <set>
#include <vector>

#include "refine2d_state.h"

namespace nonobtuse::refine2d {

inline constexpr double kSmallInputAngle = 60.0;  // degrees: below it, Ruppert's argument fails (quality2d.cpp)

// Triangle's concentric shell for a split of the subsegment [s, e] from the acute junction s: the smallest power of
// two 2^k >= |e - s| / 3 (so 2^k < 2 |e - s| / 3: both pieces are at least a third), as a parameter of [s, e]
// (float; 0.5 for a degenerate or overflowing length). Unlike the largest power of two at or before the
// midpoint, a subsegment 2^(k+1) long up to rounding is halved, not cut at a quarter (measured on clusters.poly:
// shell points a few ulps short of 2^k from the junction were split at 2^(k-2), the constraints at each small angle
// got shells that did not match, and the run ended with 108 vertices instead of 49; Triangle 64).
double nearest_shell(const Point& s, const Point& e);

// The input angles of a refinement state (which pairs of input constraints meet at a small angle with the domain
// inside it, which input edges are interfaces) and the boundary splits of the quality refinement. Every vertex it
// inserts is reported to `added` right after its insertion (the interior refinement queues the faces around it).
class QualityBoundary {
 public:
  // Cost: the faces around every input vertex with two constraints or more, and one pass over the faces.
  QualityBoundary(State& st, std::function<void(Vertex_handle)> added);

  // The input edges vertex v lies on: those at an input vertex, the one of a boundary Steiner point, none inside.
  std::vector<int> input_edges_of(Vertex_handle v) const;
  // The input vertex the input edges j and k share when they meet there at an angle below `limit` degrees with
  // the domain inside that angle, or -1 (see quality2d_boundary.cpp).
  int small_angle_between(int j, int k, double limit) const;
  // Whether side lies on an input edge with an input angle below 60 degrees at one of its ends.
  bool near_small_angle(const Side& side) const;

  // Splits `side` at its midpoint, or at a concentric shell from an input end where an acute input angle is.
  // False when it is no subsegment any more or no point passes the exact checks.
  bool split_subsegment(const Side& side);
  // Restores every boundary side the splits disturbed: midpoints and shells, the greedy rule where they fail
  // (and, with greedy_at_small_corners, at once at a corner of two boundary edges below 60 degrees).
  void repair_boundary(bool greedy_at_small_corners = false);

 private:
  bool small_angle_at(int k, int z, double limit) const;
  bool at_small_boundary_corner(const Side& side) const;
  void note_exterior_wedges(Vertex_handle v);
  void note_interfaces();
  bool holds_domain_toward(Vertex_handle v, const Point& d) const;

  State& st_;
  std::function<void(Vertex_handle)> added_;
  std::vector<std::vector<int>> edges_at_;  // input vertex -> the input edges at it (indices into st.edges())
  std::vector<bool> interface_;  // input edge -> the domain on both its sides
  std::set<std::array<int, 3>> exterior_wedge_;  // (input vertex, input edge, input edge) whose angle holds no domain
};

}  // namespace nonobtuse::refine2d
