// The strategy of the Gabriel refinement: the fast first pass with the requested split rule, then, where it does not
// converge, the protected strategy from the input; each pass within its own deterministic work budget.
#include <CGAL/Delaunay_triangulation_3.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "gabriel3d_index.h"
#include "gabriel3d_refine.h"

namespace nonobtuse {

namespace {

// The options with the defaults of Refine3DOptions resolved for `plc` (the field comments state them).
// max_work: 2000 units per input element (point, triangle, segment) plus 2e7, about 100-200 s of one core at the
// 5-10 us per unit measured. The converging inputs of tests/data/3d spend at most 6.3e6 units for both strategies
// together (mc_two_spheres: 1172 per element, shells then protected; mc_gyroid 5.6e6), so the default leaves them a
// margin of about 5; the small ones (<= 1000 elements) spend under 1.2e5 (Schonhardt, through the protected rerun).
Refine3DOptions with_defaults(const PLC3& plc, Refine3DOptions o) {
  if (o.max_steiner < 0) o.max_steiner = 10 * static_cast<long>(plc.points.size()) + 10000;
  if (o.max_work < 0)
    o.max_work = 2000 * static_cast<long>(plc.points.size() + plc.triangles.size() + plc.segments.size()) + 20000000;
  if (o.min_length < 0) {
    double d2 = 0;
    for (auto c : {&Point3::x, &Point3::y, &Point3::z}) {
      auto [lo, hi] = std::minmax_element(plc.points.begin(), plc.points.end(),
                                          [c](const Point3& a, const Point3& b) { return a.*c < b.*c; });
      const double extent = plc.points.empty() ? 0.0 : (*hi).*c - (*lo).*c;
      d2 += extent * extent;
    }
    o.min_length = 1e-6 * std::sqrt(d2);
  }
  return o;
}

const char* rule_name(SplitRule rule) {
  switch (rule) {
    case SplitRule::Midpoint: return "midpoint";
    case SplitRule::Shells: return "shells";
    case SplitRule::Greedy: return "greedy";
    case SplitRule::Protected: return "protected";
    case SplitRule::Mirrored: return "mirrored";
  }
  return "shells";
}

void set_limits(Refine3DResult& r, const Refine3DOptions& options) {
  r.max_steiner = options.max_steiner;
  r.min_length = options.min_length;
  r.max_work = options.max_work;
}

// First without the frame-rounding encroachers (fewest Steiner points). When that stalls (the Delaunay faces
// that cover a facet then sit on rounding-level slivers whose circumcenters coincide with existing vertices),
// once more from the input counting them: their extra points usually break the near-cospherical ties.
// The second attempt gets the work (and time) the first left; it runs only when some is left (else it would return
// the bare input).
Refine3DResult refine_with(const PLC3& plc, const Refine3DOptions& options, bool protect, bool mirror,
                           bool stations = false, const gabriel3d::CascadeFloor& cascade_floor = {}) {
  Refine3DResult first = gabriel3d::refine_once(plc, options, true, protect, mirror, stations, cascade_floor);
  set_limits(first, options);
  if (first.status != RefineStatus::Stalled || first.seconds >= options.time_limit || first.work >= options.max_work)
    return first;
  Refine3DOptions rest = options;
  rest.time_limit = std::max(0.0, options.time_limit - first.seconds);
  rest.max_work = options.max_work - first.work;
  Refine3DResult second = gabriel3d::refine_once(plc, rest, false, protect, mirror, stations, cascade_floor);
  second.seconds += first.seconds;
  second.work += first.work;
  second.diagnosis.stop_reason += " (second attempt; the first stalled: " + first.diagnosis.stop_reason + ")";
  set_limits(second, options);
  return second;
}

// The protected rerun's limits where the caller left them to the defaults (`given`; `resolved` has them resolved
// for the first pass). The protected split rules keep new points off the input's features by sizes those features
// bound (at arc_split_point, gabriel3d_protect.cpp: a segment and a facet through an apex at angle theta, outside the
// apex's ball of radius r, at least r sin(theta) apart; and at collar_split_point), so min_length is a safety net
// there, not what ends a cascade: 1e-9 of the bounding box diagonal instead of 1e-6. Such inputs also need points in
// proportion to 1 / theta along the segment (pieces ~ r sin(theta) near the ball, growing linearly away from the
// apex), which the default Steiner budget (10 n + 10,000) does not leave: 4 times that. Measured on the shared u.off
// (needle facets: segment-facet angles of 0.067 degrees at 4 apices, r sin(theta) = 4.6e-6): the protected rerun
// converges with 21,584 points (smallest subsegment 4.4e-6, closest points 2.0e-7 = 1.7e-7 of the diagonal, 1.9e6
// work units), where the shared limits stopped it at max_steiner (10,860). The work budget still bounds the pass.
// Only the fallback gets these limits: a protected run that does not converge spends up to 4 times the points, and
// split="protected" alone is the study setting of the termination map, most of whose protected cases end at a limit.
Refine3DOptions protected_limits(const Refine3DOptions& given, Refine3DOptions resolved) {
  if (!given.fallback_own_limits) return resolved;
  if (given.max_steiner < 0) resolved.max_steiner *= 4;
  if (given.min_length < 0) resolved.min_length *= 1e-3;
  return resolved;
}

// The smallest altitude of the input's triangles (a needle: a vertex that close to a segment it is not on), floating
// point; infinity without triangles.
double smallest_altitude(const PLC3& plc) {
  double scale = std::numeric_limits<double>::infinity();
  for (const Triangle& t : plc.triangles) {
    const gabriel3d::P3 a = gabriel3d::to_cgal(plc.points[t[0]]), b = gabriel3d::to_cgal(plc.points[t[1]]),
                        c = gabriel3d::to_cgal(plc.points[t[2]]);
    const double longest2 = std::max({CGAL::squared_distance(a, b), CGAL::squared_distance(b, c),
                                      CGAL::squared_distance(c, a)});
    const double twice_area = std::sqrt(CGAL::cross_product(b - a, c - a).squared_length());
    scale = std::min(scale, twice_area / std::sqrt(longest2));
  }
  return scale;
}

// The distance between the two closest input points (an edge of their Delaunay triangulation), floating point;
// infinity for fewer than two points.
double closest_pair(const PLC3& plc) {
  std::vector<gabriel3d::P3> points;
  points.reserve(plc.points.size());
  for (const Point3& p : plc.points) points.push_back(gabriel3d::to_cgal(p));
  const CGAL::Delaunay_triangulation_3<gabriel3d::K> dt(points.begin(), points.end());
  double d2 = std::numeric_limits<double>::infinity();
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e)
    d2 = std::min(d2, CGAL::squared_distance(e->first->vertex(e->second)->point(),
                                             e->first->vertex(e->third)->point()));
  return std::sqrt(d2);
}

// The first pass's cascade floor where the protected rerun follows (with its own limits, which min_length left to the
// default gives it): the pass stops once a split leaves a subsegment shorter than 1/1000 of the input's smallest scale,
// the smaller of the distance between its two closest points and the smallest altitude of its triangles. A first pass
// caught in a cascade down a small input angle splits until min_length (1e-6 of the diagonal) stops it, and the rerun
// starts from the input anyway: below the input's own scale, the first pass only costs time. Measured on the corpus
// (refine_gabriel with protected_fallback=False, 2026-12-07): converging first passes end with their smallest
// subsegments at >= 0.03 of that scale (rotor.off; anchor.off 0.044, a needle box 0.65), the cascades on the two
// Schonhardt prisms at 3-7e-6 of it (shared schonhardt.off: 1,629 points in 73 ms, 275 in 12 ms with the floor),
// part.off's at 9.3e-4; on u.off, mc_gyroid.off and step.off (needles, or points closer than min_length) the floor is
// below min_length and off. The smallest altitude is the cheap bound; the closest pair waits for a subsegment under it
// (its Delaunay tetrahedralization was 5% of refine_gabriel on fandisk.off, whose pass never comes that close).
gabriel3d::CascadeFloor cascade_floor(const PLC3& plc, const Refine3DOptions& given, const Refine3DOptions& resolved) {
  if (!resolved.protected_fallback || !given.fallback_own_limits || given.min_length >= 0) return {};
  const double altitude = smallest_altitude(plc), min_length = resolved.min_length;
  const double bound = 1e-3 * altitude;
  if (!(bound > min_length)) return {};  // (infinite without triangles: the closest pair decides)
  return {bound, [&plc, altitude, min_length] {
            const double floor = 1e-3 * std::min(closest_pair(plc), altitude);
            return floor > min_length && std::isfinite(floor) ? floor : 0.0;
          }};
}

}  // namespace

// The fast first pass with the requested rule; where it does not converge, the protected strategy from the input
// (with its own limits, protected_limits, and the time left), and where that does not converge either, the mirrored
// strategy (protected plus mirrored facet meshes along small-dihedral segments, gabriel3d_mirror.h) from the input
// with the same limits, unless fallback_own_limits is false (callers that repair many times, the 3D quality pass's
// rounds: a third pass on each failing repair would spend its work budget again). The first converged result is
// returned; else the first pass's, which costs no more points than before the fallbacks existed. Inputs the first
// pass or the protected rerun converge on never reach the mirrored pass, so their results do not change; it costs
// work only where both failed. split == Protected or Mirrored runs only that strategy.
Refine3DResult refine_gabriel(const PLC3& plc, const Refine3DOptions& given) {
  const Refine3DOptions options = with_defaults(plc, given);
  const bool alone = options.split == SplitRule::Protected || options.split == SplitRule::Mirrored;
  Refine3DOptions first_options = options;
  if (alone) first_options.split = SplitRule::Shells;
  Refine3DResult first = refine_with(plc, first_options, alone, options.split == SplitRule::Mirrored, false,
                                     alone ? gabriel3d::CascadeFloor{} : cascade_floor(plc, given, options));
  first.strategy = rule_name(options.split);
  if (alone || !options.protected_fallback || first.status == RefineStatus::Converged ||
      first.seconds >= options.time_limit)
    return first;
  auto summary = [](const Refine3DResult& r) {
    return r.strategy + ": " + to_string(r.status) + " (" + r.diagnosis.stop_reason + ")";
  };
  double seconds = first.seconds;
  long work = first.work;
  std::string others;
  for (bool mirror : {false, true}) {
    if (seconds >= options.time_limit || (mirror && !given.fallback_own_limits)) break;
    Refine3DOptions rest = protected_limits(given, options);
    rest.split = SplitRule::Shells;
    rest.time_limit = std::max(0.0, options.time_limit - seconds);
    Refine3DResult next = refine_with(plc, rest, true, mirror, true);
    seconds += next.seconds;
    work += next.work;
    next.strategy = mirror ? "mirrored" : "protected";
    if (next.status == RefineStatus::Converged) {
      next.strategy = std::string(rule_name(options.split)) + (mirror ? "+mirrored" : "+protected");
      next.other_attempt = summary(first) + others;
      next.seconds = seconds;
      next.work = work;
      return next;
    }
    others += "; " + summary(next);
  }
  first.other_attempt = others.substr(std::min<std::size_t>(2, others.size()));
  first.seconds = seconds;
  first.work = work;
  return first;
}

}  // namespace nonobtuse
