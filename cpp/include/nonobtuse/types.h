// Plain data types of the public C++ API: no CGAL, no Python.
#pragma once
#include <array>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace nonobtuse {

struct Point2 {
  double x = 0.0;
  double y = 0.0;
};

struct Point3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};

using Segment = std::array<int, 2>;   // indices into a point list
using Triangle = std::array<int, 3>;  // indices, counter-clockwise

// Triangle .poly "regional attribute": every triangle reachable from `at` without crossing a constraint gets
// `attribute`.
struct RegionSeed {
  Point2 at;
  double attribute = 0.0;
};

// A planar straight-line graph (PSLG) and what is inside it. The Python layer validates it (duplicates, crossings,
// points inside segments, open loops, ...) before it gets here; the core re-checks what it relies on and throws
// InvalidInput when that fails.
struct Domain2 {
  std::vector<Point2> points;
  std::vector<Segment> segments;  // boundary loops and interior constraints
  std::vector<Point2> holes;      // seeds of removed regions
  std::vector<RegionSeed> regions;
  // Point sets and open boundaries: the domain is the convex hull (minus holes), hull edges become boundary
  // segments. Otherwise the domain is what the closed segment loops enclose.
  bool convex_hull_boundary = false;
};

// A triangulated domain. The first points are the domain's points in their input order; Steiner points follow.
struct Mesh2 {
  std::vector<Point2> points;
  std::vector<Triangle> triangles;      // domain triangles only, counter-clockwise
  std::vector<Segment> segments;        // every constrained subsegment (boundary, interface, dangling)
  std::vector<double> triangle_region;  // region attribute per triangle (0 where no region seed reached)
};

// Exact classification of an angle (CGAL::angle on exact predicates).
enum class AngleClass : std::int8_t { Acute = 0, Right = 1, Obtuse = 2 };

// Why a refinement (2D refine, 3D refine_gabriel) stopped. Converged: the exact check of the returned mesh passes.
// BudgetExhausted: the Steiner budget (or 3D's time_limit) is spent. MinLengthReached (3D only): a split would
// create an edge shorter than min_length. Stalled: budget left, but no split that passes the exact checks is
// possible (2D: some violated side admits no double split point that keeps its neighbouring triangles valid, even
// after the midpoint rescue). Every stop but Converged returns the partial mesh.
enum class RefineStatus : std::int8_t { Converged = 0, BudgetExhausted = 1, MinLengthReached = 2, Stalled = 3 };

// "converged", "budget_exhausted", "min_length_reached", "stalled".
const char* to_string(RefineStatus status);

// Bad input found by the core; the message names the problem and where (indices, coordinates).
class InvalidInput : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// An invariant the core relies on failed: a bug, never the user's fault.
class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

}  // namespace nonobtuse
