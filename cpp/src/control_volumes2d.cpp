// Exact signs of the control-volume coupling coefficients T_e = sum_t k_t cot(apex_t) / 2.
#include "nonobtuse/control_volumes2d.h"

#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>

#include <cmath>
#include <string>

namespace nonobtuse {
namespace {

// dot and cross of (u - c, v - c) for a side whose triangle is (u, v, c) counter-clockwise: cross > 0 (checked
// exactly by classify_edges), so sign(cot) = sign(dot).
template <class NT>
struct Apex {
  NT dot, cross;
};

template <class NT>
Apex<NT> apex_terms(const Point2& u, const Point2& v, const Point2& c) {
  NT ux = NT(u.x) - NT(c.x), uy = NT(u.y) - NT(c.y), vx = NT(v.x) - NT(c.x), vy = NT(v.y) - NT(c.y);
  return {ux * vx + uy * vy, ux * vy - uy * vx};
}

// The quantity whose sign is sign(T_e): one side: k dot; two sides: k_l dot_l cross_r + k_r dot_r cross_l
// (T_e multiplied by 2 cross_l cross_r > 0).
template <class NT>
NT coupling_numerator(const Mesh2& mesh, const EdgeReport& e, double k_left, double k_right) {
  const Point2 &a = mesh.points[e.edge[0]], &b = mesh.points[e.edge[1]];
  if (e.right.triangle < 0) return NT(k_left) * apex_terms<NT>(a, b, mesh.points[e.left.apex]).dot;
  if (e.left.triangle < 0) return NT(k_right) * apex_terms<NT>(b, a, mesh.points[e.right.apex]).dot;
  Apex<NT> l = apex_terms<NT>(a, b, mesh.points[e.left.apex]);
  Apex<NT> r = apex_terms<NT>(b, a, mesh.points[e.right.apex]);
  return NT(k_left) * l.dot * r.cross + NT(k_right) * r.dot * l.cross;
}

int sign_of(const Mesh2& mesh, const EdgeReport& e, double k_left, double k_right) {
  using Interval = CGAL::Interval_nt<>;  // protected rounding mode: safe bounds
  Interval x = coupling_numerator<Interval>(mesh, e, k_left, k_right);
  if (x.inf() > 0) return 1;
  if (x.sup() < 0) return -1;
  CGAL::Exact_rational q = coupling_numerator<CGAL::Exact_rational>(mesh, e, k_left, k_right);
  return CGAL::sign(q);
}

double conductivity_of(const std::vector<double>& conductivity, int triangle) {
  return triangle < 0 || conductivity.empty() ? 1.0 : conductivity[triangle];
}

}  // namespace

std::vector<int> coupling_signs(const Mesh2& mesh, const std::vector<EdgeReport>& edges,
                                const std::vector<double>& conductivity) {
  if (!conductivity.empty() && conductivity.size() != mesh.triangles.size())
    throw InvalidInput("conductivity has " + std::to_string(conductivity.size()) + " values for " +
                       std::to_string(mesh.triangles.size()) + " triangles");
  for (std::size_t t = 0; t < conductivity.size(); ++t)
    if (!(std::isfinite(conductivity[t]) && conductivity[t] > 0))
      throw InvalidInput("conductivity of triangle " + std::to_string(t) + " is " +
                         std::to_string(conductivity[t]) + "; it must be finite and > 0");
  std::vector<int> signs;
  signs.reserve(edges.size());
  for (const auto& e : edges) {
    if (e.left.triangle < 0 && e.right.triangle < 0)
      throw InternalError("coupling_signs: edge (" + std::to_string(e.edge[0]) + ", " +
                          std::to_string(e.edge[1]) + ") has no triangle");
    signs.push_back(sign_of(mesh, e, conductivity_of(conductivity, e.left.triangle),
                            conductivity_of(conductivity, e.right.triangle)));
  }
  return signs;
}

}  // namespace nonobtuse
