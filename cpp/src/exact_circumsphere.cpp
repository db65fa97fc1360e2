// A tetrahedron's circumsphere, exactly (see exact_circumsphere.h).
#include "exact_circumsphere.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace nonobtuse {
namespace {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using ET = EK::FT::ET;

// The double nearest to x, ties to even (as Python's float(Fraction)): the two doubles around x from its
// enclosing interval, then an exact comparison with their midpoint.
double nearest(const ET& x) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double lo = CGAL::to_interval(x).first;
  if (!std::isfinite(lo)) return CGAL::to_double(x);
  while (std::nextafter(lo, kInf) <= std::numeric_limits<double>::max() && ET(std::nextafter(lo, kInf)) <= x)
    lo = std::nextafter(lo, kInf);
  const double hi = std::nextafter(lo, kInf);
  if (ET(lo) == x || !std::isfinite(hi)) return lo;
  const ET mid = (ET(lo) + ET(hi)) / 2;
  if (x < mid) return lo;
  if (mid < x) return hi;
  std::uint64_t bits;
  std::memcpy(&bits, &lo, sizeof bits);
  return bits % 2 == 0 ? lo : hi;  // a tie: the one with an even mantissa
}

}  // namespace

Circumsphere exact_circumsphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  auto exact = [](const Point3& p) { return EK::Point_3(p.x, p.y, p.z); };
  const EK::Point_3 ea = exact(a);
  const EK::Point_3 center = CGAL::circumcenter(ea, exact(b), exact(c), exact(d));
  auto rounded = [](const EK::FT& x) { return nearest(CGAL::exact(x)); };
  return {{rounded(center.x()), rounded(center.y()), rounded(center.z())},
          rounded(CGAL::squared_distance(center, ea))};
}

}  // namespace nonobtuse
