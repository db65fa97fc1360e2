// Mirrored facet meshes along small-dihedral segments: the pairs of facets, the reflection, the verified image.
#include "gabriel3d_mirror.h"

#include <algorithm>
#include <cmath>

namespace nonobtuse::gabriel3d {
namespace {

using Vec = std::array<double, 3>;
Vec sub(const P3& a, const P3& b) { return {a.x() - b.x(), a.y() - b.y(), a.z() - b.z()}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec scaled(const Vec& a, double k) { return {a[0] * k, a[1] * k, a[2] * k}; }
Vec minus(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec unit(const Vec& a) { return scaled(a, 1.0 / std::sqrt(dot(a, a))); }
P3 plus(const P3& p, const Vec& d) { return P3(p.x() + d[0], p.y() + d[1], p.z() + d[2]); }

// The unit direction, orthogonal to segment ab and in the facet's plane, toward the facet's side of ab; nullopt when
// the facet lies on both sides (ab inside the facet) or on neither.
std::optional<Vec> side_direction(const PlcState& s, const Facet& f, int a, int b) {
  FacetCDT::Face_handle fh;
  int i = 0;
  if (!f.cdt.is_edge(f.vertex.at(a), f.vertex.at(b), fh, i)) return std::nullopt;
  std::optional<int> apex;
  for (auto g : {fh, fh->neighbor(i)}) {
    if (f.cdt.is_infinite(g) || !g->info().in_domain) continue;
    if (apex) return std::nullopt;
    apex = g->vertex(g == fh ? i : g->index(fh))->info();
  }
  if (!apex) return std::nullopt;
  const Vec e = sub(s.points[b], s.points[a]);
  return unit(cross(e, cross(sub(s.points[*apex], s.points[a]), e)));
}

}  // namespace

std::vector<MirrorPair> mirror_pairs(const PlcState& s, double below_degrees) {
  std::vector<MirrorPair> out;
  const double below = std::cos(below_degrees * M_PI / 180.0);
  for (std::size_t g = 0; g < s.segments.size(); ++g) {
    const InputSegment& seg = s.segments[g];
    for (int f : seg.facets)
      for (int h : seg.facets) {
        if (f == h) continue;
        const auto uf = side_direction(s, *s.facets[f], seg.a, seg.b);
        const auto ug = side_direction(s, *s.facets[h], seg.a, seg.b);
        if (!uf || !ug || dot(*uf, *ug) <= below) continue;  // dihedral angle >= below_degrees
        const Vec lift = unit(minus(*ug, scaled(*uf, dot(*uf, *ug))));  // g's direction, orthogonal to f's plane
        out.push_back({f, h, static_cast<int>(g), s.points[seg.a], s.points[seg.b],
                       unit(sub(s.points[seg.b], s.points[seg.a])), *uf, *ug, lift});
      }
  }
  return out;
}

P3 reflect(const MirrorPair& m, const P3& p) {
  const Vec d = sub(p, m.a);
  const double x = dot(d, m.along), y = dot(d, m.into_from);
  return P3(m.a.x() + x * m.along[0] + y * m.into_to[0], m.a.y() + x * m.along[1] + y * m.into_to[1],
            m.a.z() + x * m.along[2] + y * m.into_to[2]);
}

// The mirror argument. Let F and G meet along the line of segment e (the x axis) at dihedral angle delta, F in the
// plane z = 0 on the side y >= 0, and R the rotation about e by delta (on the points of F it agrees with the
// reflection in the bisector plane). For a point q = (x, y, 0) of F and a subfacet T of F with circumcenter
// c = (cx, cy, 0) and circumradius r, |R(q) - c|^2 - |q - c|^2 = 2 y cy (1 - cos delta) >= 0 when cy >= 0. So if
// F's triangulation is Delaunay (no vertex strictly inside T's circumcircle) and T's circumcenter is on F's side
// of e (what a subfacet with its angle opposite e nonobtuse gives; an obtuse one encroaches the subsegment, which
// level 1 splits first), no image R(q) of a vertex q of F is strictly inside T's diametral sphere, for every
// delta; symmetrically for G. Where the two meshes are mirror images near e, the facets stop encroaching each
// other there. The equality case (q on T's circumcircle with cy = 0 or y = 0: q a vertex of T, collar points) is
// where rounding can put the image an ulp inside T's sphere: it is checked exactly on the rounded image against the
// subfacets of F around q and moved away from F's plane (which only grows its distance to every centre in F's
// plane) until it is out. Not covered: vertices of G that are no image of a vertex of F (G's own points, images from a
// third facet: a facet with several mirrored segments, e.g. the spike's base, gets images from each of its
// neighbours; where two images conflict both are kept, one hop only, images are not mirrored again), subfacets of F
// whose circumcircle reaches beyond F's boundary (images that fall outside G's domain are not placed), subfacets
// created after an image was verified that have it in the equality case (checked only at placement; the collar
// rule refuses their circumcenter at the segment midpoint), and images refused for a protecting ball or
// min_length. There the ordinary rules apply and the budgets bound the run. Measured (split="mirrored", the
// protecting balls' sphere points mirrored once every ball has them: Refiner::place_protecting_points): spike k=10
// converges at 80 degrees (157 points) and on 23 of its 31 grid angles with the fallback's limits; at 55, 60, 65,
// 75 and 85 degrees it stops at min_length (experiments/README.md).
std::optional<MirrorImage> mirrored_point(const PlcState& s, const MirrorPair& m, int v) {
  const P3& p = s.points[v];
  const Vec e = sub(m.b, m.a), d = sub(p, m.a);
  const double along = dot(d, e);
  if (!(along > 0 && along < dot(e, e))) return std::nullopt;
  const Facet &from = *s.facets[m.from], &to = *s.facets[m.to];
  std::vector<Key> to_subsegments, equality_balls;  // equality_balls: those on the mirror segment (y = 0 above)
  for (auto c = to.cdt.finite_edges_begin(); c != to.cdt.finite_edges_end(); ++c)
    if (to.cdt.is_constrained(*c)) {
      const Key k = key(c->first->vertex(FacetCDT::cw(c->second))->info(),
                        c->first->vertex(FacetCDT::ccw(c->second))->info());
      to_subsegments.push_back(k);
      if (s.subsegments.at(k) == m.segment) equality_balls.push_back(k);
    }
  auto in_ball = [&](const std::vector<Key>& balls, const P3& y) {
    return std::any_of(balls.begin(), balls.end(), [&](const Key& k) {
      return CGAL::side_of_bounded_sphere(s.points[k.first], s.points[k.second], y) == CGAL::ON_BOUNDED_SIDE;
    });
  };
  auto in_subfacet_sphere = [&](const P3& y) {
    auto fc = from.cdt.incident_faces(from.vertex.at(v)), done = fc;
    do {
      if (from.cdt.is_infinite(fc) || !fc->info().in_domain) continue;
      if (CGAL::side_of_bounded_sphere(s.points[fc->vertex(0)->info()], s.points[fc->vertex(1)->info()],
                                       s.points[fc->vertex(2)->info()], y) == CGAL::ON_BOUNDED_SIDE)
        return true;
    } while (++fc != done);
    return false;
  };
  P3 y = reflect(m, p);
  const double size = std::max({std::abs(y.x()), std::abs(y.y()), std::abs(y.z())});
  int step = 0;
  for (; step < 8 && (in_subfacet_sphere(y) || in_ball(equality_balls, y)); ++step)
    y = plus(y, scaled(m.lift, std::ldexp(size, step - 52)));
  if (step == 8 || in_ball(to_subsegments, y)) return std::nullopt;
  MirrorImage out;
  out.point = y;
  out.loc = to.cdt.locate(to.project(y), out.lt, out.li);
  if (!strictly_in_domain(to.cdt, out.lt, out.loc, out.li)) return std::nullopt;
  return out;
}

}  // namespace nonobtuse::gabriel3d
