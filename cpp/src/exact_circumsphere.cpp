// A tetrahedron's circumsphere, exactly (see exact_circumsphere.h).
#include "exact_circumsphere.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include "nonobtuse/control_volumes3d.h"

namespace nonobtuse {
namespace {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using ET = EK::FT::ET;

// The double nearest to x, ties to even (as Python's float(Fraction)), +-inf from the largest double plus half its
// unit in the last place on (IEEE's overflow): the two doubles around |x| from its enclosing interval, then an
// exact comparison with their midpoint.
double nearest(const ET& x) {
  if (x < 0) return -nearest(-x);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  constexpr double kMax = std::numeric_limits<double>::max();
  double lo = std::min(CGAL::to_interval(x).first, kMax);
  while (lo < kMax && ET(std::nextafter(lo, kInf)) <= x) lo = std::nextafter(lo, kInf);
  if (ET(lo) == x) return lo;
  // above the largest double the next one is 2^1024 (the overflow threshold sits halfway)
  const ET hi = lo < kMax ? ET(std::nextafter(lo, kInf)) : ET(kMax) + (ET(kMax) - ET(std::nextafter(kMax, 0.0)));
  const ET mid = (ET(lo) + hi) / 2;
  if (x < mid) return lo;
  if (mid < x || lo == kMax) return lo < kMax ? std::nextafter(lo, kInf) : kInf;  // a tie at kMax: "even" is inf
  std::uint64_t bits;
  std::memcpy(&bits, &lo, sizeof bits);
  return bits % 2 == 0 ? lo : std::nextafter(lo, kInf);  // a tie: the one with an even mantissa
}

}  // namespace

Circumsphere exact_circumsphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  auto exact = [](const Point3& p) { return EK::Point_3(p.x, p.y, p.z); };
  const EK::Point_3 ea = exact(a), eb = exact(b), ec = exact(c), ed = exact(d);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (CGAL::orientation(ea, eb, ec, ed) == CGAL::COPLANAR) return {{kInf, kInf, kInf}, kInf, 0.0};
  const EK::Point_3 center = CGAL::circumcenter(ea, eb, ec, ed);
  auto rounded = [](const EK::FT& x) { return nearest(CGAL::exact(x)); };
  return {{rounded(center.x()), rounded(center.y()), rounded(center.z())},
          rounded(CGAL::squared_distance(center, ea)), rounded(CGAL::volume(ea, eb, ec, ed))};
}

TetCircumspheres exact_tet_circumspheres(const std::vector<Point3>& points,
                                         const std::vector<std::array<int, 4>>& tets) {
  TetCircumspheres out;
  out.centers.reserve(tets.size());
  out.squared_radii.reserve(tets.size());
  out.volumes.reserve(tets.size());
  for (std::size_t t = 0; t < tets.size(); ++t) {
    for (int v : tets[t])
      if (v < 0 || static_cast<std::size_t>(v) >= points.size())
        throw InvalidInput("tet " + std::to_string(t) + ": vertex index " + std::to_string(v) + " out of range (" +
                           std::to_string(points.size()) + " points)");
    const auto& q = tets[t];
    const Circumsphere s = exact_circumsphere(points[q[0]], points[q[1]], points[q[2]], points[q[3]]);
    out.centers.push_back(s.center);
    out.squared_radii.push_back(s.squared_radius);
    out.volumes.push_back(s.volume);
  }
  return out;
}

}  // namespace nonobtuse
