// A tetrahedron's circumsphere, exact where floating point cannot tell it (see quality3d_shape.h).
#include "quality3d_shape.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "exact_circumsphere.h"

namespace nonobtuse::quality3d {

TetShape tet_shape(const P3& a, const P3& b, const P3& c, const P3& d) {
  const auto u = b - a, v = c - a, w = d - a;
  const double det = u * CGAL::cross_product(v, w);  // as numpy's einsum of u and cross(v, w)
  const double l = std::sqrt(std::max({u.squared_length(), v.squared_length(), w.squared_length()}));
  if (std::abs(det) >= 0x1p-20 * (l * l * l))
    return {CGAL::circumcenter(a, b, c, d), CGAL::squared_radius(a, b, c, d), false};
  auto point = [](const P3& p) { return Point3{p.x(), p.y(), p.z()}; };
  const Circumsphere s = exact_circumsphere(point(a), point(b), point(c), point(d));
  return {P3(s.center.x, s.center.y, s.center.z), s.squared_radius, true};
}

TetQuality tet_quality(const P3& a, const P3& b, const P3& c, const P3& d, double radius_edge, double volume_bound) {
  double shortest = std::numeric_limits<double>::infinity();
  const P3* v[4] = {&a, &b, &c, &d};
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) shortest = std::min(shortest, CGAL::squared_distance(*v[i], *v[j]));
  const double ratio = std::sqrt(tet_shape(a, b, c, d).squared_radius / shortest);
  const bool over_volume = std::abs(CGAL::volume(a, b, c, d)) > volume_bound;
  const bool over = (radius_edge > 0 && ratio > radius_edge) || over_volume || !std::isfinite(ratio);
  return {ratio, std::sqrt(shortest), over, over_volume};
}

}  // namespace nonobtuse::quality3d
