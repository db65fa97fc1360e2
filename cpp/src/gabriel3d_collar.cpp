// Segment collars: where a split point of a facet lands in the diametral ball of one of the facet's subsegments, it
// goes on the subsegment's collar circle in the facet instead of splitting the subsegment.
#include "gabriel3d_collar.h"

#include <cmath>
#include <map>

namespace nonobtuse::gabriel3d {

// The collar rule. A circumcenter c of a subfacet of facet F strictly inside the diametral ball B of a subsegment
// sigma = [p, q] of F (the ordinary rule would split sigma) is moved to the circle C_F with diameter pq in F's plane
// (F's section of B), on the ray from sigma's midpoint m through c; the exact check keeps it out of B and out of
// the balls of the other subsegments of F. Termination argument. (1) No point placed by this rule encroaches any
// subsegment: it is on or outside B by the exact check, and outside every other ball of F's subsegments. So facet
// refinement never splits sigma; sigma is split only by a point strictly inside B that some other rule placed
// (vertex balls keep features that miss an apex lfs/4 away, so those splits are bounded by the local feature size).
// That removes the chain along a segment s shared by facets F and G at a small dihedral angle delta, which the
// shells rule runs down to rounding: there F's circumcenters near s split s, the new points make G's subfacets
// near s small, whose circumcenters split s again. (2) A collar point y on C_F never encroaches a subfacet of G
// whose three vertices are p, q and a point of C_G: by Thales the circumcircle of such a triangle is C_G, its
// diametral sphere is B's sphere, and y is on it, not strictly inside. (3) A subfacet of F with two vertices a, b
// on C_F and a third vertex x outside B is encroached by a point z of C_G only if its circumradius exceeds
// dist(z, F's plane) / 2 >= r_sigma sin(delta) sin(angle of z on C_G) / 2; the moved circumcenters of such
// subfacets cut C_F's arcs, and once the arcs near z's angle are shorter than that bound no point of G encroaches
// them: each collar point causes finitely many arc points, and with sigma fixed, the points on C_F are finitely
// many. (4) Where the rounded point cannot be verified out of every ball, or c is m, the ordinary rule (split
// sigma) applies, and the budgets bound those runs; the exact check of the result decides the status either way.
// Not covered: the collar circles of two consecutive subsegments are tangent at their shared point, and the cusp
// between them (outside both balls) still takes facet points ever closer to that point (measured on the shared
// schonhardt.off: a min_length stop at 3,250 points); overlapping collar balls would close it. Nor does (2) survive
// rounding: it needs y exactly on the sphere of [p, q], and a subfacet (p, q, x) of F with x strictly outside B has
// a diametral sphere (centre m + s u, s > 0, u in F towards x) that strictly holds every point z of B's closed half on
// x's side but p and q (|z - m - s u|^2 - r^2 - s^2 = |z - m|^2 - r^2 - 2 s (z - m).u < 0), so for delta < 90 degrees
// it holds every point of C_G: F's subfacets on sigma are Gabriel only when cospherical with C_G, and after rounding
// the exact test decides by noise. Measured on spike 80 (split="protected"): 166 of the 186 subsegment splits that
// split_subfacet makes are such Thales subfacets, all vertices and the encroacher within 1e-15 r of the sphere, whose
// circumcenter is the midpoint (refused above, so sigma is split); experiments/README.md has the variants tried.
std::optional<P3> collar_split_point(const P3& p, const P3& q, const P3& c,
                                     const std::function<bool(const P3&)>& held, const std::array<double, 3>* normal) {
  const P3 m = CGAL::midpoint(p, q);
  K::Vector_3 d = c - m;
  // In the facet's plane: c is off it by its rounding, and the move below multiplies that by radius / |c - m| (fuzz
  // seed 359: a point 0.032 off its facet at coordinates 1e6, radius / |c - m| near 1e7; the mesh enclosed 3e-8 less
  // than the input). The projected direction is off the plane by the normal's rounding only.
  if (normal) {
    const K::Vector_3 n((*normal)[0], (*normal)[1], (*normal)[2]);
    d = d - (d * n / (n * n)) * n;
  }
  const double length = std::sqrt(CGAL::to_double(d.squared_length()));
  const double radius = 0.5 * std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q)));
  // c at (or within rounding of) the midpoint: the ray's direction is then rounding noise and can leave the facet's
  // plane (measured with mirrored meshes: Thales subfacets whose circumcenter is m, moved 0.1 off it; and on a
  // 1.4e-6 sliver at 1000, fuzz seed 206: c half a unit in the last place from m, the point 1.5e-8 off the plane of
  // a facet 7e-9 from the opposite one, so the mesh enclosed 0.09% more volume than the input).
  if (noisy_direction(m, c, radius)) return std::nullopt;
  auto outside = [&](const P3& y) {
    return CGAL::side_of_bounded_sphere(p, q, y) != CGAL::ON_BOUNDED_SIDE && !held(y);
  };
  double scale = radius / length;
  for (int step = 0; step < 8; ++step) {
    const P3 y = m + d * scale;
    if (y == p || y == q) return std::nullopt;
    if (outside(y)) return y;
    scale *= 1.0 + std::ldexp(1.0, step - 52);
  }
  return std::nullopt;
}

std::vector<bool> collared_segments(const PlcState& s) {
  std::vector<bool> out(s.segments.size(), false);
  std::map<Key, int> index;
  for (std::size_t g = 0; g < s.segments.size(); ++g)
    index[key(s.segments[g].a, s.segments[g].b)] = static_cast<int>(g);
  for (const auto& angle : dihedral_angles(s))
    if (angle.degrees < 90.0) out[index.at(key(angle.vertices[0], angle.vertices[1]))] = true;
  return out;
}

std::optional<P3> facet_collar_point(const PlcState& s, const Facet& facet, const std::vector<bool>& collared,
                                     const Key& sub, const P3& c, const std::function<bool(const P3&)>& held) {
  if (!collared[s.subsegments.at(sub)]) return std::nullopt;
  const std::array<double, 3> normal = facet.normal();
  return collar_split_point(s.points[sub.first], s.points[sub.second], c, held, &normal);
}

}  // namespace nonobtuse::gabriel3d
