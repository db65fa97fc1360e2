// 3D: the exact Gabriel certificate of a tetrahedral mesh's boundary (check_gabriel) and the Ruppert-like repair of
// a piecewise linear complex until every subfacet and subsegment has an empty diametral sphere (refine_gabriel).
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "nonobtuse/types.h"

namespace nonobtuse {

using Tetrahedron = std::array<int, 4>;  // indices, positively oriented

// A boundary simplex (face or segment) whose open diametral sphere holds a mesh vertex.
struct Encroachment {
  int index = -1;      // row in the faces (or segments) that were checked
  int vertex = -1;     // the deepest encroaching vertex (by floating-point depth; encroachment itself is exact)
  double depth = 0.0;  // 1 - |vertex - center| / radius, in (0, 1]; floating point, for display only
};

struct GabrielReport {
  std::vector<Encroachment> faces;
  std::vector<Encroachment> segments;
  std::size_t candidates = 0;  // (simplex, vertex) pairs the float search passed to the exact predicate
  // Faces and segments not checked because refine_gabriel's time_limit ran out during its check (the last rows);
  // always 0 from check_gabriel.
  std::size_t unchecked_faces = 0;
  std::size_t unchecked_segments = 0;
};

// For every face (a, b, c): is some point strictly inside its diametral sphere (the smallest sphere through a, b, c,
// CGAL side_of_bounded_sphere)? For every segment (a, b): is some point strictly inside the sphere with diameter ab?
// Points on a sphere do not encroach (right angles are fine). Decisions are exact on the coordinates as stored; a
// kd-tree with a provably conservative floating-point search radius only proposes candidates.
// Throws InvalidInput for a face with collinear corners or a segment with coincident ends (no diametral sphere).
// Cost: O((n + f + k) log n) for well-shaped input (each sphere holds O(1) points).
GabrielReport check_gabriel(const std::vector<Point3>& points, const std::vector<Triangle>& faces,
                            const std::vector<Segment>& segments);

// A piecewise linear complex: triangulated facets (triangles sharing a facet id form one planar facet) and segments.
struct PLC3 {
  std::vector<Point3> points;
  std::vector<Triangle> triangles;
  std::vector<int> facet_ids;  // one per triangle
  std::vector<Segment> segments;
  std::vector<Point3> holes;                   // volume-hole seeds
  std::vector<std::array<double, 4>> regions;  // x, y, z, attribute
};

// How an encroached subsegment is split: at its midpoint; by concentric shells (a power-of-two distance from its
// one input-vertex end, else the midpoint); or Greedy: the end of the longest prefix from one end whose diametral
// sphere holds none of the subsegment's current encroachers (the 2D paper's Greedy-Refine), with the shells rule
// where that prefix is short (see refine_gabriel). Protected: concentric shells plus protecting balls at every
// apex vertex (an input segment leaning over a facet through its end at less than 90 degrees): radius a power of
// two <= 1/4 of the vertex's local feature size, each segment through the apex split on the ball's sphere, and
// subfacet split points that would fall strictly inside a ball moved to its sphere (see refine_gabriel).
// Mirrored: Protected plus mirrored facet meshes: a point placed on a facet near an input segment where it meets
// another facet at a dihedral angle below 90 degrees is also placed at its mirror image on that facet (see
// refine_gabriel and cpp/src/gabriel3d_mirror.h).
enum class SplitRule : std::int8_t { Midpoint = 0, Shells = 1, Greedy = 2, Protected = 3, Mirrored = 4 };

struct Refine3DProgress {
  long steiner_points = 0;
  long encroached_segments = 0;  // found by the last scan (or exact check of the Delaunay mesh)
  long encroached_facets = 0;
  double seconds = 0.0;
};

struct Refine3DOptions {
  // Steiner budget; < 0 selects 10 n + 10,000 for n PLC points (real CAD parts need about 2-5 n).
  long max_steiner = -1;
  // No split may create a subsegment (or an edge to a facet Steiner point) shorter; 0 turns it off; < 0 selects
  // 1e-6 of the diagonal of the PLC points' bounding box (the first passes that converge on the corpus end with
  // smallest subsegments >= 1.8 times it, mc_torus.off; runs caught in a small-angle cascade end at it with
  // MinLengthReached instead of spinning down to 1e-17 subsegments until the budget or a stall).
  double min_length = -1.0;
  // Wall-clock seconds for everything (both strategies and the exact checks); infinity (the default) sets none, so
  // that the outcome does not depend on the machine's speed or load. An explicit limit is reported as such.
  double time_limit = std::numeric_limits<double>::infinity();
  // The deterministic work budget of each strategy pass (the first pass and each rerun get one each, so a rerun
  // never inherits what an earlier pass spent): one unit per exact encroachment query of a subsegment or a
  // subfacet in the repair's scans and splits, per row of each exact check of the Delaunay mesh and per point of
  // each Delaunay rebuild. Work is proportional to time on one machine and the same on every machine. < 0 selects
  // 2000 (n + t + s) + 2 10^7 for n PLC points, t triangles and s segments (see with_defaults).
  long max_work = -1;
  SplitRule split = SplitRule::Shells;
  // Run the protected strategy when the split rule's pass does not converge, and the mirrored one when that does
  // not converge either.
  bool protected_fallback = true;
  // The fallbacks' limits of their own (4 times the Steiner budget, 1/1000 of min_length where those are left to the
  // defaults; protected_limits in gabriel3d_strategy.cpp); false: the shared defaults and no mirrored pass, for
  // callers that repair many times (the 3D quality pass) and would otherwise spend up to the work budget on each
  // repair.
  bool fallback_own_limits = true;
  long progress_every = 1000;  // insertions between progress calls; one more after each exact check of the mesh
  std::function<void(const Refine3DProgress&)> progress;
};

// One small angle of the input, in degrees (floating point: a diagnosis, not a decision).
struct InputAngle {
  std::string kind;           // "segment-segment", "segment-facet" or "dihedral"
  double degrees = 0.0;
  std::vector<int> vertices;  // segment-segment: apex, end, end; segment-facet: apex, segment end; dihedral: a, b
  std::vector<int> facets;    // facet ids involved
};

struct SteinerCount {
  std::vector<int> where;  // an input vertex, or the two ends of an input segment
  long count = 0;
};

struct Refine3DDiagnosis {
  std::vector<InputAngle> smallest_angles;   // the few smallest of each kind, ascending
  std::vector<SteinerCount> per_vertex;      // Steiner points by nearest input vertex, top few
  std::vector<SteinerCount> per_segment;     // Steiner points on each input segment, top few
  // The subsegments the exact check of the returned mesh found encroached, counted by their input segment (a, b)
  // and their deepest encroacher's: where = {a, b, c, d} for a point of input segment (c, d), {a, b, v} for input
  // vertex v, {a, b} for a point inside a facet; top few. Empty after convergence.
  std::vector<SteinerCount> encroached_per_segment;
  std::string stop_reason;
};

struct Refine3DResult {
  std::vector<Point3> points;  // PLC points first, in input order, then Steiner points
  std::vector<Tetrahedron> tets;
  std::vector<Triangle> boundary_faces;  // oriented away from the tet behind them
  std::vector<int> face_markers;         // input facet id of each boundary face
  std::vector<Segment> segments;         // subsegments of the PLC segments and of the facets' boundary edges
  std::vector<double> tet_regions;
  RefineStatus status = RefineStatus::Stalled;
  long max_steiner = 0;     // the limits the run used (options' defaults resolved)
  double min_length = 0.0;
  long max_work = 0;
  long work = 0;  // the work units spent, by every attempt together (see Refine3DOptions::max_work)
  // The strategy that produced this result: the split rule's name ("shells", "greedy", "midpoint", "protected"),
  // or "<rule>+protected" when the rule's pass did not converge and the protected strategy, run from the input,
  // did, "<rule>+mirrored" when only the mirrored one did. other_attempt: "" when one strategy ran, else the status
  // and stop reason of the attempts not returned ("; " between them).
  std::string strategy;
  std::string other_attempt;
  long protecting_balls = 0;  // apex vertices protected (0 unless the protected strategy ran)
  long steiner_on_segments = 0;
  long greedy_splits = 0;  // of steiner_on_segments, placed by the greedy rule (split == Greedy)
  long steiner_on_facets = 0;
  double seconds = 0.0;
  double smallest_subsegment = 0.0;
  GabrielReport certificate;  // check_gabriel on (points, boundary_faces, segments) as returned
  // "built", or why tets is empty: when a stop leaves the Delaunay tetrahedralization not conforming to some facet
  // (its interior leaks out), boundary_faces are the subfacets instead (oriented like the input's triangles).
  std::string volume_mesh = "built";
  Refine3DDiagnosis diagnosis;
};

// Ruppert-like repair: splits encroached subsegments (midpoint, concentric shells around input vertices, or greedy) and
// encroached subfacets (at their circumcenter, or the subsegment that point encroaches or lies beyond) until every
// subsegment and subfacet has an empty open diametral sphere, then returns the Delaunay tetrahedralization of all
// vertices restricted to the PLC's interior (flood fill from outside across boundary faces; hole seeds removed).
// Steiner points lie on segments and facets (up to rounding of their coordinates). Stops at max_steiner, max_work,
// min_length, time_limit (none by default), or when no progress is possible (stalled). time_limit also bounds the exact check of the result (rows
// it did not reach: certificate.unchecked_*); only the final Delaunay tetrahedralization, O(n log n), runs past it.
// A stopped run whose tetrahedralization does not conform to every facet returns the subfacets and no tets
// (volume_mesh says so). status == Converged iff the exact check of the returned mesh passes. The facets' boundary
// edges count as segments (their subsegments are returned and checked).
// Strategy: the pass with options.split first (where the fallbacks get their own limits and min_length is left to the
// default, it stops once a split leaves a subsegment shorter than 1/1000 of the input's smallest scale, the smaller of
// its closest two points' distance and its triangles' smallest altitude: a cascade; cascade_floor in
// gabriel3d_strategy.cpp); when it ends without converging (and time is left, and
// protected_fallback is set), the protected strategy (SplitRule::Protected) runs from the input with its own
// max_steiner and min_length (4 times and 1/1000 of the defaults where those are left to them: protected_limits in
// gabriel3d_strategy.cpp; not for split == Protected alone), its own max_work and the rest of time_limit; its
// result is returned if it converged; else (when fallback_own_limits is set) the mirrored strategy
// (SplitRule::Mirrored) runs from the input with the same limits and its result is returned if it converged; else
// the first pass's
// (strategy and other_attempt say which). Protecting balls keep the split points of a
// segment and a facet meeting at a small angle off the apex, which ends the cascade there (the termination argument
// and what it does not cover are at arc_split_point in gabriel3d_protect.cpp).
// Deterministic: without a time_limit, the same input and options give the same result on every machine.
// Throws InvalidInput on malformed input (index out of range, duplicate points, degenerate
// triangles, facet edges crossing or passing through a vertex, facet vertices coinciding in the facet's plane).
Refine3DResult refine_gabriel(const PLC3& plc, const Refine3DOptions& options);

}  // namespace nonobtuse
