// Interior quality and size for 2D refinement: Ruppert/Chew Delaunay refinement of the domain's interior after the
// boundary refinement, which never puts a point inside a constraint subsegment's open diametral disk, so that the
// boundary stays nonobtuse (the exact certificate of refine2d.h still backs "converged").
#pragma once
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace nonobtuse {

// What makes a domain triangle bad. Every criterion is off by default (the paper's minimal mode: no interior point).
struct Quality2DOptions {
  // Smallest angle, in degrees, in [0, 34]: triangles with a smaller angle are refined. 0: no angle criterion.
  // Above 20.7 degrees Ruppert's termination proof no longer applies (Triangle's off-centers, used here, are
  // observed to terminate up to about 34 degrees); the interior budget stops the refinement in any case.
  double min_angle_degrees = 0.0;
  // Largest triangle area; <= 0 or infinite: none.
  double max_area = 0.0;
  // Largest area per region attribute: pairs (attribute, area). A triangle of a region whose attribute is listed
  // obeys the smallest area listed for it (Triangle's per-region area constraint, keyed by attribute).
  std::vector<std::pair<double, double>> region_max_area;
  // Largest area at a point (evaluated at the triangle's centroid); empty: none. Must return a positive finite
  // number (the caller's wrapper checks).
  std::function<double(double x, double y)> max_area_at;
  // Maximum number of interior points; < 0 selects default_interior_budget.
  long long max_interior = -1;
  // With the greedy strategy: false (default), the boundary is refined as Triangle does, by the quality refinement
  // (midpoints and shells of every side with an obtuse apex, quality2d_boundary.cpp); true, the paper's minimal
  // greedy boundary first, then the quality refinement (splitting only what the interior encroaches). Neither
  // wins everywhere: the minimal boundary's short pieces draw interior cascades on most inputs (the demo
  // section: 1680 boundary points against 1228), but where few pieces suffice it needs fewer points (cdt_ditch:
  // 2 against 3). nonobtuse.refine runs both and keeps the better (refinement.py). Other strategies always run
  // their own boundary first.
  bool minimal_boundary_first = false;

  bool enabled() const {
    return min_angle_degrees > 0.0 || max_area > 0.0 || !region_max_area.empty() || static_cast<bool>(max_area_at);
  }
};

// What the interior refinement did and left (all zero when Quality2DOptions is not enabled).
struct Quality2DStats {
  long long interior_points = 0;    // Steiner points strictly inside the domain (circumcenters, off-centers)
  long long interior_budget = 0;    // the budget used (max_interior, its default resolved)
  long long boundary_splits = 0;    // boundary Steiner points the interior refinement caused (encroached
                                    // subsegments split, and the sides those splits left obtuse)
  long long boundary_points_removed = 0;  // boundary Steiner points taken back after convergence (of the
                                          // strategy's or of boundary_splits; quality2d_prune.cpp)
  long long bad_triangles = 0;      // triangles still bad at the end, outside small-input-angle regions
  long long small_angle_triangles = 0;  // bad triangles left alone near small input angles (see quality2d.cpp)
  long long triangles = 0;          // domain triangles of the result
  // Smallest angle of any domain triangle, and of those not left alone near small input angles (degrees; floating
  // point, for reporting: 180 when there is no such triangle).
  double min_angle_degrees = 180.0;
  double min_angle_outside_small_angles_degrees = 180.0;
  double max_area = 0.0;  // largest domain triangle area (floating point)
};

// Default interior budget: 10 n + 100000 for n input points, plus 4 A / a where A is the domain's area and a the
// smallest fixed area limit (max_area or a region's): a mesh obeying the limit needs about 2 A / a triangles, so
// well-posed inputs stay far below it; the budget is the hard stop for size functions and small input angles.
long long default_interior_budget(std::size_t n_points, double domain_area, double smallest_area_limit);

}  // namespace nonobtuse
