// The 3D dual (Voronoi face) areas and cell volumes of a tet mesh: exact signs (interval filter, exact arithmetic
// when it cannot decide), floating-point magnitudes.
#include "nonobtuse/control_volumes3d.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Interval_nt.h>
#ifdef CGAL_HAS_MPZF
#include <CGAL/Mpzf.h>
#else
#include <CGAL/Gmpzf.h>
#endif

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "fork_join.h"

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

// Doubles with numpy's operation order, so that the magnitudes are those of the module's numpy formulas bit for
// bit (a three-term sum over an axis is (x + y) + z; the compiler contracts nothing into fused multiply-adds on
// the default x86-64 target).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("fp-contract=off")  // no fused multiply-adds (aarch64 would contract by default)
#endif
struct D3 {
  double x, y, z;
};
D3 operator-(const D3& a, const D3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 operator+(const D3& a, const D3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
D3 times(double s, const D3& a) { return {s * a.x, s * a.y, s * a.z}; }
D3 over(const D3& a, double s) { return {a.x / s, a.y / s, a.z / s}; }
double sum3(double x, double y, double z) { return (x + y) + z; }
double dot(const D3& a, const D3& b) { return sum3(a.x * b.x, a.y * b.y, a.z * b.z); }
D3 cross(const D3& a, const D3& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
D3 d3(const Point3& p) { return {p.x, p.y, p.z}; }

D3 triangle_circumcenter(const D3& a, const D3& b, const D3& c) {
  D3 u = b - a, v = c - a, w = cross(u, v);
  D3 num = times(dot(u, u), cross(v, w)) + times(dot(v, v), cross(w, u));
  return a + over(num, 2.0 * dot(w, w));
}

// The circumcenter, or NaN where the tet is flat in doubles (den == 0); *flat says which.
D3 tet_circumcenter(const D3& a, const D3& b, const D3& c, const D3& d, bool* flat) {
  D3 u = b - a, v = c - a, w = d - a;
  D3 num = times(dot(u, u), cross(v, w)) + times(dot(v, v), cross(w, u)) + times(dot(w, w), cross(u, v));
  double den = dot(u, cross(v, w));
  *flat = den == 0;
  return a + over(num, 2.0 * den);
}

// One tet's piece of the dual area of edge (i, j) (frame (i, j, k, l), positive) and |j - i|, in doubles.
std::pair<double, double> float_piece(const D3& xi, const D3& xj, const D3& xk, const D3& xl, const D3& ct) {
  D3 m = times(0.5, xi + xj);
  D3 c1 = triangle_circumcenter(xi, xj, xk), c2 = triangle_circumcenter(xi, xj, xl);
  D3 area = times(0.5, cross(c1 - m, ct - m) + cross(ct - m, c2 - m));
  D3 e = xj - xi;
  double length = std::sqrt(dot(e, e));
  return {dot(area, e) / length, length};
}

// The floating-point magnitudes: per piece (in pieces' tet-and-frame order within each tet), the per-point
// volumes, and the count of tets flat in doubles.
void float_magnitudes(const std::vector<Point3>& p, const std::vector<std::array<int, 4>>& tets,
                      std::vector<double>& piece, ControlVolumes3D& out) {
  piece.assign(6 * tets.size(), 0.0);
  out.volumes.assign(p.size(), 0.0);
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const auto& c = tets[t];
    bool flat = false;
    D3 ct = tet_circumcenter(d3(p[c[0]]), d3(p[c[1]]), d3(p[c[2]]), d3(p[c[3]]), &flat);
    out.flat_in_floating_point += flat;
    double share[4] = {0, 0, 0, 0};
    for (int f = 0; f < 6; ++f) {
      const int* q = kEdgeFrames[f];
      auto [area, length] = float_piece(d3(p[c[q[0]]]), d3(p[c[q[1]]]), d3(p[c[q[2]]]), d3(p[c[q[3]]]), ct);
      piece[6 * t + f] = area;
      double pyramid = area * length / 6.0;
      share[q[0]] += pyramid;
      share[q[1]] += pyramid;
    }
    for (int v = 0; v < 4; ++v) out.volumes[c[v]] += share[v];
  }
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

ControlVolumes3D control_volumes3d(const std::vector<Point3>& points, const std::vector<std::array<int, 4>>& tets) {
  require_positive_tets(points, tets);
  ControlVolumes3D out;
  std::vector<double> piece;
  float_magnitudes(points, tets, piece, out);
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
  out.signs.assign(edges, 0);
  // The interval filter, the bulk of the work, on two threads (halves of the edges); the undecided edges of the
  // first half come first, so the order (and everything after) does not depend on the split.
  std::vector<std::size_t> undecided, undecided_after;
  auto filter = [&](std::size_t from, std::size_t to, std::vector<std::size_t>& left) {
    CGAL::Protect_FPU_rounding<true> upward;  // the rounding mode Interval_nt_advanced needs (per thread)
    for (std::size_t g = from; g < to; ++g) {
      auto x = dual_area_interval(points, tets, &pieces[starts[g]], &pieces[starts[g + 1]]);
      if (x.inf() > 0) {
        out.signs[g] = 1;
      } else if (x.sup() < 0) {
        out.signs[g] = -1;
      } else {
        left.push_back(g);  // contains 0, or overflowed / NaN on extreme coordinates
      }
    }
  };
  fork_join(worth_forking(edges, 2), [&] { filter(0, edges / 2, undecided); },
            [&] { filter(edges / 2, edges, undecided_after); });
  undecided.insert(undecided.end(), undecided_after.begin(), undecided_after.end());
  for (std::size_t g : undecided)
    out.signs[g] = dual_area_exact_sign(points, tets, &pieces[starts[g]], &pieces[starts[g + 1]]);
  out.exact_evaluations = static_cast<int>(undecided.size());
  out.edges.reserve(edges);
  out.dual_areas.reserve(edges);
  out.lengths.reserve(edges);
  for (std::size_t g = 0; g < edges; ++g) {
    const Segment& e = pieces[starts[g]].edge;
    double sum = 0.0;  // in tet order, as numpy's bincount adds
    for (std::size_t q = starts[g]; q < starts[g + 1]; ++q) sum += piece[6 * pieces[q].tet + pieces[q].frame];
    out.edges.push_back(e);
    out.dual_areas.push_back(out.signs[g] * std::abs(sum));
    D3 d = d3(points[e[1]]) - d3(points[e[0]]);
    out.lengths.push_back(std::sqrt(dot(d, d)));
  }
  return out;
}

}  // namespace nonobtuse
