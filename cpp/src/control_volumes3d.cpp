// Exact signs of the 3D dual (Voronoi face) areas: interval filter, exact arithmetic when it cannot decide.
#include "nonobtuse/control_volumes3d.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Interval_nt.h>
#ifdef CGAL_HAS_MPZF
#include <CGAL/Mpzf.h>
#else
#include <CGAL/Gmpzf.h>
#endif

#include <algorithm>
#include <string>

namespace nonobtuse {
namespace {

// Exact floating point (binary mantissa of any length, no division): doubles convert exactly.
#ifdef CGAL_HAS_MPZF
using Exact = CGAL::Mpzf;
#else
using Exact = CGAL::Gmpzf;
#endif

template <class NT>
struct Vec {
  using Scalar = NT;
  NT x, y, z;
};

template <class NT>
Vec<NT> operator-(const Vec<NT>& a, const Vec<NT>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class NT>
Vec<NT> operator+(const Vec<NT>& a, const Vec<NT>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
// The scalar's type is not deduced, so GMP expression templates (a / b) convert to NT.
template <class NT>
Vec<NT> scaled(const typename Vec<NT>::Scalar& s, const Vec<NT>& a) {
  return {s * a.x, s * a.y, s * a.z};
}
template <class NT>
NT dot(const Vec<NT>& a, const Vec<NT>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class NT>
Vec<NT> cross(const Vec<NT>& a, const Vec<NT>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class NT>
Vec<NT> lift(const Point3& p) {
  return {NT(p.x), NT(p.y), NT(p.z)};
}

// One tet's piece of the face dual to edge (i, j), as a fraction num / den with den > 0: the signed area of
// (M, C(ijk), C_T, C(ijl)) along i -> j, times 8 |j - i|. With the origin at i and e = j - i, f = k - i, g = l - i:
// C(ijk) = n1 / (2 d1), n1 = |e|^2 f x w1 + |f|^2 w1 x e, w1 = e x f, d1 = |w1|^2 (likewise C(ijl) with g);
// C_T = nt / (2 dt), nt = |e|^2 f x g + |f|^2 g x e + |g|^2 e x f, dt = e . (f x g) > 0 ((i, j, k, l) is positive).
// Twice the area vector dotted with e is ((C1 - M) x (C_T - M) + (C_T - M) x (C2 - M)) . e, and as M = e / 2 is
// parallel to e the terms with M vanish: it is ((C1 - C2) x C_T) . e = ((d2 n1 - d1 n2) x nt) . e / (4 d1 d2 dt).
// No division, so exact arithmetic needs only +, -, x.
template <class NT>
struct Fraction {
  NT num, den;
};

template <class NT>
Fraction<NT> dual_piece(const Point3& pi, const Point3& pj, const Point3& pk, const Point3& pl) {
  Vec<NT> i = lift<NT>(pi);
  Vec<NT> e = lift<NT>(pj) - i, f = lift<NT>(pk) - i, g = lift<NT>(pl) - i;
  NT ee = dot(e, e), ff = dot(f, f), gg = dot(g, g);
  Vec<NT> w1 = cross(e, f), w2 = cross(e, g);
  Vec<NT> n1 = scaled(ee, cross(f, w1)) + scaled(ff, cross(w1, e));
  Vec<NT> n2 = scaled(ee, cross(g, w2)) + scaled(gg, cross(w2, e));
  Vec<NT> nt = scaled(ee, cross(f, g)) + scaled(ff, cross(g, e)) + scaled(gg, w1);
  NT d1 = dot(w1, w1), d2 = dot(w2, w2), dt = dot(e, cross(f, g));
  return {dot(cross(scaled(d2, n1) - scaled(d1, n2), nt), e), d1 * d2 * dt};
}

// The six edges (i, j) of a positive tet (0, 1, 2, 3), each with the other two vertices (k, l) ordered so that
// (i, j, k, l) is an even permutation, hence positively oriented as well.
constexpr int kEdgeFrames[6][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 2, 0, 3}, {1, 3, 2, 0}, {2, 3, 0, 1}};

struct Piece {
  Segment edge;  // a < b
  int tet, frame;
};

// The sum of the pieces of one edge's tets [first, last). Intervals: sum of num / den (den > 0 exactly; an
// interval den containing 0 only widens the result). Exact (no division): one fraction over the product of the
// dens, whose sign is the numerator's.
CGAL::Interval_nt_advanced dual_area_interval(const std::vector<Point3>& p, const std::vector<std::array<int, 4>>& tets,
                                              const Piece* first, const Piece* last) {
  CGAL::Interval_nt_advanced sum(0);
  for (const Piece* q = first; q != last; ++q) {
    const auto& t = tets[q->tet];
    const int* f = kEdgeFrames[q->frame];
    auto x = dual_piece<CGAL::Interval_nt_advanced>(p[t[f[0]]], p[t[f[1]]], p[t[f[2]]], p[t[f[3]]]);
    sum += x.num / x.den;
  }
  return sum;
}

int dual_area_exact_sign(const std::vector<Point3>& p, const std::vector<std::array<int, 4>>& tets,
                         const Piece* first, const Piece* last) {
  Exact num(0), den(1);
  for (const Piece* q = first; q != last; ++q) {
    const auto& t = tets[q->tet];
    const int* f = kEdgeFrames[q->frame];
    auto x = dual_piece<Exact>(p[t[f[0]]], p[t[f[1]]], p[t[f[2]]], p[t[f[3]]]);
    num = num * x.den + x.num * den;
    den = den * x.den;
  }
  return CGAL::sign(num);
}

void require_positive_tets(const std::vector<Point3>& p, const std::vector<std::array<int, 4>>& tets) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  auto point = [&](int v) { return K::Point_3(p[v].x, p[v].y, p[v].z); };
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const auto& c = tets[t];
    for (int v : c)
      if (v < 0 || static_cast<std::size_t>(v) >= p.size())
        throw InvalidInput("tet " + std::to_string(t) + " refers to point " + std::to_string(v) + ", but there are " +
                           std::to_string(p.size()) + " points");
    if (CGAL::orientation(point(c[0]), point(c[1]), point(c[2]), point(c[3])) != CGAL::POSITIVE)
      throw InvalidInput("tet " + std::to_string(t) + " (" + std::to_string(c[0]) + ", " + std::to_string(c[1]) +
                         ", " + std::to_string(c[2]) + ", " + std::to_string(c[3]) +
                         ") is not positively oriented (flat or inverted)");
  }
}

}  // namespace

DualAreaSigns dual_area_signs(const std::vector<Point3>& points, const std::vector<std::array<int, 4>>& tets) {
  require_positive_tets(points, tets);
  std::vector<Piece> pieces;
  pieces.reserve(6 * tets.size());
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (int f = 0; f < 6; ++f) {
      int a = tets[t][kEdgeFrames[f][0]], b = tets[t][kEdgeFrames[f][1]];
      pieces.push_back({{std::min(a, b), std::max(a, b)}, static_cast<int>(t), f});
    }
  std::sort(pieces.begin(), pieces.end(), [](const Piece& x, const Piece& y) {
    return x.edge != y.edge ? x.edge < y.edge : (x.tet != y.tet ? x.tet < y.tet : x.frame < y.frame);
  });
  // Edge groups: pieces[starts[g]] .. pieces[starts[g + 1]] share one edge.
  std::vector<std::size_t> starts;
  for (std::size_t q = 0; q < pieces.size(); ++q)
    if (q == 0 || pieces[q].edge != pieces[q - 1].edge) starts.push_back(q);
  starts.push_back(pieces.size());
  const std::size_t edges = starts.size() - 1;
  DualAreaSigns out;
  out.signs.assign(edges, 0);
  std::vector<std::size_t> undecided;
  {
    CGAL::Protect_FPU_rounding<true> upward;  // the rounding mode Interval_nt_advanced needs, for this block
    for (std::size_t g = 0; g < edges; ++g) {
      auto x = dual_area_interval(points, tets, &pieces[starts[g]], &pieces[starts[g + 1]]);
      if (x.inf() > 0) {
        out.signs[g] = 1;
      } else if (x.sup() < 0) {
        out.signs[g] = -1;
      } else {
        undecided.push_back(g);  // contains 0, or overflowed / NaN on extreme coordinates
      }
    }
  }
  for (std::size_t g : undecided)
    out.signs[g] = dual_area_exact_sign(points, tets, &pieces[starts[g]], &pieces[starts[g + 1]]);
  out.exact_evaluations = static_cast<int>(undecided.size());
  out.edges.reserve(edges);
  for (std::size_t g = 0; g < edges; ++g) out.edges.push_back(pieces[starts[g]].edge);
  return out;
}

}  // namespace nonobtuse
