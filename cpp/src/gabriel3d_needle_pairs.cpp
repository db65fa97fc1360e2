// Paired points on the two segments of a needle corner.
#include "gabriel3d_needle_pairs.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "gabriel3d_split_rule.h"

namespace nonobtuse::gabriel3d {

namespace {

// Facet corners below kPairDegrees are paired. Measured with `refine_gabriel`'s defaults on tests/data/3d and the
// shared corpus (experiments/README.md, "needle corners"): at 1 degree mc_torus.off's first pass ends at min_length
// (a fan of 1.4-2.9 degree corners at vertex 556); at 2 degrees it converges but mc_gyroid.off and part.off end at
// min_length; at 3 degrees all of them converge.
constexpr double kPairDegrees = 3.0;

// The angle at v between v -> a and v -> b, in radians (atan2 of |cross| and dot: accurate near 0).
double corner_angle(const P3& v, const P3& a, const P3& b) {
  const K::Vector_3 p = a - v, q = b - v;
  return std::atan2(std::sqrt(CGAL::to_double(CGAL::cross_product(p, q).squared_length())), CGAL::to_double(p * q));
}

bool strictly_inside(const P3& p, const P3& q, const P3& x) {
  return CGAL::side_of_bounded_sphere(p, q, x) == CGAL::ON_BOUNDED_SIDE;
}

// Do p and the points of input segment `segment` (an end at v) encroach each other: p strictly inside the
// diametral sphere of one of the segment's subsegments (z, y), or one of its points strictly inside that of (u, p) or
// (p, w), the new subsegments p makes? Walks the segment's points from v in one of its facets' triangulations up to
// the distance of w from v (no sphere holds a point whose projection is outside it: |v z| < |v p| for the first,
// |v y| < |v w| for the others), exact sphere tests. Cost: O(k) for the segment's k points up to there.
bool encroaches_segment(const PlcState& s, int v, int segment, const P3& u, const P3& p, const P3& w) {
  const InputSegment& seg = s.segments[segment];
  if (seg.facets.empty()) return false;
  const Facet& facet = *s.facets[seg.facets[0]];
  const double far = std::max(distance(s.points[v], p), distance(s.points[v], w));
  int previous = -1, at = v;
  while (distance(s.points[v], s.points[at]) < far) {
    int next = -1;  // the neighbour of `at` along the segment, away from v
    auto n = facet.cdt.incident_vertices(facet.vertex.at(at)), done = n;
    do {
      const int j = facet.cdt.is_infinite(n) ? -1 : n->info();
      const auto sub = j < 0 || j == previous ? s.subsegments.end() : s.subsegments.find(key(at, j));
      if (sub != s.subsegments.end() && sub->second == segment) next = j;
    } while (next < 0 && ++n != done);
    if (next < 0) return false;
    const P3& y = s.points[next];
    if (strictly_inside(s.points[at], y, p) || strictly_inside(u, p, y) || strictly_inside(p, w, y)) return true;
    previous = at, at = next;
  }
  return false;
}

}  // namespace

NeedleCorners needle_corners(const PlcState& s) {
  const double pair_below = kPairDegrees * M_PI / 180.0;
  std::vector<std::vector<int>> on_facet(s.facets.size());
  for (std::size_t i = 0; i < s.segments.size(); ++i)
    for (int f : s.segments[i].facets) on_facet[f].push_back(static_cast<int>(i));
  std::map<int, std::vector<int>> segments_at;  // input vertex -> every input segment there
  for (std::size_t i = 0; i < s.segments.size(); ++i)
    for (int v : {s.segments[i].a, s.segments[i].b}) segments_at[v].push_back(static_cast<int>(i));
  NeedleCorners out;
  out.of_segment.resize(s.segments.size());
  std::set<std::pair<int, int>> seen;  // a corner on several facets is listed once
  for (std::size_t f = 0; f < s.facets.size(); ++f) {
    std::map<int, std::vector<int>> at;  // vertex -> the facet's segments there
    for (int i : on_facet[f]) at[s.segments[i].a].push_back(i), at[s.segments[i].b].push_back(i);
    for (const auto& [v, segs] : at) {
      auto other_end = [&, v = v](int seg) { return s.segments[seg].a == v ? s.segments[seg].b : s.segments[seg].a; };
      auto angle = [&, v = v](std::size_t i, std::size_t j) {
        return corner_angle(s.points[v], s.points[other_end(segs[i])], s.points[other_end(segs[j])]);
      };
      for (std::size_t i = 0; i < segs.size(); ++i)
        for (std::size_t j = i + 1; j < segs.size(); ++j) {
          const double theta = angle(i, j);
          // A corner is two consecutive segments around v: none of the facet's other segments at v inside it
          // (a planar direction is inside the wedge iff it makes less than theta with both sides).
          bool consecutive = theta < pair_below;
          for (std::size_t k = 0; k < segs.size() && consecutive; ++k)
            consecutive = k == i || k == j || std::max(angle(i, k), angle(k, j)) >= theta;
          if (!consecutive || !seen.insert({segs[i], segs[j]}).second) continue;
          NeedleCorner corner;
          corner.apex = v, corner.facet = static_cast<int>(f), corner.seg[0] = segs[i], corner.seg[1] = segs[j];
          corner.end[0] = other_end(segs[i]), corner.end[1] = other_end(segs[j]);
          corner.c = std::cos(theta / 2);
          for (int seg : segments_at[v])
            if (seg != segs[i] && seg != segs[j]) corner.around.push_back(seg);
          out.corners.push_back(corner);
        }
    }
  }
  for (std::size_t i = 0; i < out.corners.size(); ++i)
    for (int seg : out.corners[i].seg) out.of_segment[seg].push_back(static_cast<int>(i));
  for (NeedleCorner& corner : out.corners)  // only the unpaired segments: the paired ones get partners of their own
    corner.around.erase(std::remove_if(corner.around.begin(), corner.around.end(),
                                       [&](int seg) { return !out.of_segment[seg].empty(); }),
                        corner.around.end());
  return out;
}

// The partner rule. Segments from apex v at angle theta, unit directions a and b; a point y = rho b lies strictly
// inside the diametral sphere of [r1 a, r2 a] iff f(rho) = rho^2 - cos(theta) (r1 + r2) rho + r1 r2 < 0. Partners
// are rho = c r with cos(theta) < c = cos(theta / 2) < 1:
// (i) at the apex (r1 = 0): f(c r2) = c r2^2 (c - cos theta) > 0, and r2 a lies outside the sphere of [0, c r2 b]
//     (r2^2 (1 - c cos theta) > 0);
// (ii) elsewhere (0 < r1 < r2): f(c r1) = r1 (c r1 (c - cos theta) + r2 (1 - c cos theta)) > 0 and likewise f(c r2)
//     > 0; f is convex and, when it has roots at all ((r2 - r1) > sin(theta) (r1 + r2)), its minimum
//     cos(theta) (r1 + r2) / 2 lies in (c r1, c r2), so f > 0 at every partner c r_j of a point r_j outside
//     (r1, r2). The same holds with the roles of the segments swapped (g(r) = r^2 - c cos(theta) (r1 + r2) r +
//     c^2 r1 r2 at r1 and r2).
// So where every point of the two segments has its partner, no point of one encroaches a subsegment of the other,
// and the ping-pong of splits down the corner (measured without the rule on mc_torus.off: about 9,000 points on
// each needle segment, pieces of 5e-6) cannot start. Two consecutive pairs are never cocircular (equal radii, c = 1,
// make an isosceles trapezoid, whose diagonals tie; the foot, c = cos(theta), puts the innermost partner on its
// subsegment's sphere by Thales): the circle through r1 a, r2 a and c r2 b meets line b again at r1 / c (the power
// of v is r1 r2), beyond c r1, so the facet's Delaunay diagonal is decided with the margin
// r1 (r2 - r1) (1 - c^2) > 0, not by rounding.
// A partner is placed only where needed: where x and the subsegment (u, w) of the other segment it would split
// encroach each other (elsewhere the pair is already consistent, and a partner there is one more point, 0.0008
// from the other segment's own point: fan k=3 at 3 degrees took 26 points with partners everywhere); and never
// strictly inside the diametral sphere of a subsegment of an unpaired input segment at the apex, nor with a point
// of one inside its new subsegments' (fan k=3 at 3 degrees: corner (14, 2, 3) is 2.99999999999999 degrees, its
// neighbour (14, 3, 4) 3.0000000000000067, and partners at c r on 14-3 encroached 14-4's shell pieces: 26 -> 14
// points with both rules; mc_torus.off needs the partners that encroach paired neighbours, 19,451 points at
// min_length when those were refused too).
// Termination: a split on a paired segment adds at most one partner per corner (partners get none, one hop), and
// a refusal only places fewer, so the corner asks for no split of its own; the splits left near it are those the rest of the PLC asks for (an input
// vertex at distance h from the other segment, such as the needle's third corner, needs the pieces around its foot
// to have d1 d2 <= h^2: finitely many). Rounding: the margins are about (3/8) theta^2 r^2, above the rounding of
// coordinates of size 1 while r >> 1e-16 / theta^2; the rounded partner is checked exactly against the four
// spheres below, moved along its subsegment by relative steps of 2^-52, 2^-51, ... (at most 20 each way) until it
// passes, and refused otherwise (the refinement then goes on without it).
std::optional<PartnerSplit> partner_split(const PlcState& s, const NeedleCorner& corner, int side, int x, int xa,
                                          int xb, const std::function<int(const P3&)>& near) {
  const int other = 1 - side;
  const P3& v = s.points[corner.apex];
  const double r = distance(v, s.points[x]);
  const double rho = side == 0 ? corner.c * r : r / corner.c;
  const double t = rho / distance(v, s.points[corner.end[other]]);
  if (!(t > 0 && t < 1)) return std::nullopt;
  const Facet& facet = *s.facets[corner.facet];
  const auto apex = facet.vertex.at(corner.apex);
  const Q2 qa = apex->point(), qb = facet.vertex.at(corner.end[other])->point();
  FacetCDT::Locate_type lt;
  int li = 0;
  const int start = near(interpolate(v, s.points[corner.end[other]], t));
  const auto loc = facet.cdt.locate(qa + (qb - qa) * EK::FT(t), lt, li,
                                    (start < 0 ? apex : facet.vertex.at(start))->face());
  if (lt != FacetCDT::EDGE) return std::nullopt;  // on an existing vertex
  int u = loc->vertex(FacetCDT::cw(li))->info(), w = loc->vertex(FacetCDT::ccw(li))->info();
  const auto sub = s.subsegments.find(key(u, w));
  if (sub == s.subsegments.end() || sub->second != corner.seg[other]) return std::nullopt;
  double du = distance(v, s.points[u]), dw = distance(v, s.points[w]);
  if (du > dw) std::swap(u, w), std::swap(du, dw);
  const P3 &pu = s.points[u], &pw = s.points[w], &px = s.points[x];
  // Not needed: x and the subsegment (u, w) do not encroach each other.
  const auto encroaches_x = [&](const P3& y) {
    return strictly_inside(s.points[xa], px, y) || strictly_inside(px, s.points[xb], y);
  };
  if (!strictly_inside(pu, pw, px) && !encroaches_x(pu) && !encroaches_x(pw)) return std::nullopt;
  for (int step = -1; step < 20; ++step)
    for (double sign : {1.0, -1.0}) {
      if (step < 0 && sign < 0) continue;
      const double moved = step < 0 ? rho : rho * (1.0 + sign * std::ldexp(1.0, step - 52));
      const double tt = (moved - du) / (dw - du);
      if (!(tt > 0 && tt < 1)) continue;
      const P3 p = interpolate(pu, pw, tt);
      if (s.at.count({p.x(), p.y(), p.z()})) continue;
      if (strictly_inside(s.points[xa], px, p) || strictly_inside(px, s.points[xb], p) ||
          strictly_inside(pu, p, px) || strictly_inside(p, pw, px))
        continue;
      for (int seg : corner.around)
        if (encroaches_segment(s, corner.apex, seg, pu, p, pw)) return std::nullopt;
      return PartnerSplit{u, w, tt, p};
    }
  return std::nullopt;
}

}  // namespace nonobtuse::gabriel3d
