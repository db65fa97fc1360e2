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
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "exact_circumsphere.h"
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
[[gnu::always_inline]] inline Vec<NT> operator-(const Vec<NT>& a, const Vec<NT>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class NT>
[[gnu::always_inline]] inline Vec<NT> operator+(const Vec<NT>& a, const Vec<NT>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
// The scalar's type is not deduced, so GMP expression templates (a / b) convert to NT.
template <class NT>
[[gnu::always_inline]] inline Vec<NT> scaled(const typename Vec<NT>::Scalar& s, const Vec<NT>& a) {
  return {s * a.x, s * a.y, s * a.z};
}
template <class NT>
[[gnu::always_inline]] inline NT dot(const Vec<NT>& a, const Vec<NT>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class NT>
[[gnu::always_inline]] inline Vec<NT> cross(const Vec<NT>& a, const Vec<NT>& b) {
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

// The edges of the tets numbered in (a, b) order, and per piece (6 t + f: tet t, frame f) the number of its edge.
struct EdgeNumbering {
  std::vector<Segment> edges;  // a < b, sorted
  std::vector<int> edge_of;    // per piece
};

// f(q, a, b) for every piece q = 6 t + f in order, (a, b) its edge with a < b (no division per piece: this runs
// twice over the 38M pieces of the 1e6-face torus).
template <class F>
void for_each_piece_edge(const std::vector<std::array<int, 4>>& tets, const F& f) {
  std::size_t q = 0;
  for (const auto& t : tets)
    for (const auto& frame : kEdgeFrames) {
      int a = t[frame[0]], b = t[frame[1]];
      f(q++, std::min(a, b), std::max(a, b));
    }
}

// A counting sort of the pieces by their edge's smaller end, then each end's pieces (about 75) sorted by their
// other end: O(t) plus those small sorts, where a comparison sort of the 6 t pieces took most of the pass. A piece
// is one 64-bit key, other end above piece, so the sort compares integers and the edges and the pieces' numbers
// come out of one walk over the sorted keys.
EdgeNumbering number_edges(std::size_t points, const std::vector<std::array<int, 4>>& tets) {
  const std::size_t n = 6 * tets.size();
  if (n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw InvalidInput("too many tets for the control volumes: " + std::to_string(tets.size()));
  std::vector<std::size_t> start(points + 1, 0);
  for_each_piece_edge(tets, [&](std::size_t, int a, int) { ++start[a + 1]; });
  for (std::size_t v = 0; v < points; ++v) start[v + 1] += start[v];
  std::vector<std::uint64_t> by_end(n);  // other end << 32 | piece, grouped by smaller end
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for_each_piece_edge(tets, [&](std::size_t q, int a, int b) {
      by_end[fill[a]++] = static_cast<std::uint64_t>(b) << 32 | q;
    });
  }
  EdgeNumbering out;
  out.edge_of.resize(n);
  for (std::size_t a = 0; a < points; ++a) {
    std::sort(by_end.begin() + static_cast<std::ptrdiff_t>(start[a]),
              by_end.begin() + static_cast<std::ptrdiff_t>(start[a + 1]));
    for (std::size_t k = start[a]; k < start[a + 1]; ++k) {
      const int b = static_cast<int>(by_end[k] >> 32);
      if (k == start[a] || b != out.edges.back()[1]) out.edges.push_back({static_cast<int>(a), b});
      out.edge_of[by_end[k] & 0xffffffffu] = static_cast<int>(out.edges.size()) - 1;
    }
  }
  return out;
}

template <class NT>
Fraction<NT> piece_fraction(const std::vector<Point3>& p, const std::vector<std::array<int, 4>>& tets,
                            std::size_t q) {
  const auto& t = tets[q / 6];
  const int* f = kEdgeFrames[q % 6];
  return dual_piece<NT>(p[t[f[0]]], p[t[f[1]]], p[t[f[2]]], p[t[f[3]]]);
}

// The interval filter works per tet, in a frame with the origin at the tet's first corner: the circumcenters of
// its four faces and of the tet once, then each of its six pieces as ((C1 - C2) x (C_T - M)) . e, which is
// 2 |e| times the piece's signed area (C1 - C2 is orthogonal to e, so the terms with M of the area vector
// collapse; the positive factor does not change the sign of the sum), where computing each piece from scratch
// in its own frame repeated the circumcenters three times and took most of the control volumes' time.
template <class NT>
Vec<NT> triangle_circumcenter(const Vec<NT>& a, const Vec<NT>& b, const Vec<NT>& c) {
  Vec<NT> u = b - a, v = c - a, w = cross(u, v);
  Vec<NT> num = scaled(dot(u, u), cross(v, w)) + scaled(dot(v, v), cross(w, u));
  NT den = NT(2) * dot(w, w);
  return a + Vec<NT>{num.x / den, num.y / den, num.z / den};
}

// The interval pieces (as above) of tets [from, to) into piece[6 (t - from) + f], f the frame. A denominator
// containing 0 (or an overflow) only widens a piece.
void interval_pieces(const std::vector<Point3>& p, const std::vector<std::array<int, 4>>& tets, std::size_t from,
                     std::size_t to, CGAL::Interval_nt_advanced* piece) {
  using I = CGAL::Interval_nt_advanced;
  CGAL::Protect_FPU_rounding<true> upward;  // the rounding mode Interval_nt_advanced needs (per thread)
  for (std::size_t t = from; t < to; ++t) {
    const auto& c = tets[t];
    const Vec<I> origin = lift<I>(p[c[0]]);
    Vec<I> x[4] = {{I(0), I(0), I(0)}, lift<I>(p[c[1]]) - origin, lift<I>(p[c[2]]) - origin,
                   lift<I>(p[c[3]]) - origin};
    Vec<I> opposite[4];  // circumcenter of the face opposite each corner
    for (int m = 0; m < 4; ++m)
      opposite[m] = triangle_circumcenter(x[(m + 1) % 4], x[(m + 2) % 4], x[(m + 3) % 4]);
    const Vec<I>&u = x[1], &v = x[2], &w = x[3];
    Vec<I> num = scaled(dot(u, u), cross(v, w)) + scaled(dot(v, v), cross(w, u)) + scaled(dot(w, w), cross(u, v));
    I den = I(2) * dot(u, cross(v, w));
    const Vec<I> ct{num.x / den, num.y / den, num.z / den};
    for (int f = 0; f < 6; ++f) {
      const int* q = kEdgeFrames[f];  // (i, j, k, l): C1 = C(ijk), opposite l; C2 = C(ijl), opposite k
      Vec<I> m = scaled(I(0.5), x[q[0]] + x[q[1]]);
      *piece++ = dot(cross(opposite[q[3]] - opposite[q[2]], ct - m), x[q[1]] - x[q[0]]);
    }
  }
}

// Per edge, the interval sum of its pieces in (tet, frame) order, into sum[e]. Blocks of tets, each block's pieces
// on two threads (halves of its tets; most of the work is a tet's five circumcenters, which splitting by edges
// computed on both threads for most tets), then added in order on this one.
void dual_area_intervals(const std::vector<Point3>& p, const std::vector<std::array<int, 4>>& tets,
                         const std::vector<int>& edge_of, std::vector<CGAL::Interval_nt_advanced>& sum) {
  constexpr std::size_t kBlock = 1 << 15, kForkFrom = 1 << 12;
  std::vector<CGAL::Interval_nt_advanced> piece(6 * std::min(kBlock, tets.size()));
  for (std::size_t begin = 0; begin < tets.size(); begin += kBlock) {
    const std::size_t end = std::min(tets.size(), begin + kBlock), middle = begin + (end - begin) / 2;
    fork_join(end - begin >= kForkFrom, [&] { interval_pieces(p, tets, begin, middle, piece.data()); },
              [&] { interval_pieces(p, tets, middle, end, piece.data() + 6 * (middle - begin)); });
    CGAL::Protect_FPU_rounding<true> upward;
    for (std::size_t q = 6 * begin; q < 6 * end; ++q) sum[edge_of[q]] += piece[q - 6 * begin];
  }
}

// The sum of fractions num / den (den > 0) exactly: its sign. A first sum in intervals around the fractions (as
// tight as doubles go) decides most sums that are not 0; otherwise one fraction over the product of the dens (no
// division), whose sign is the numerator's. Putting the fractions over one denominator multiplies numbers that
// grow with every fraction, the most of the exact arithmetic.
int sign_of_sum(const std::vector<Fraction<Exact>>& terms) {
  CGAL::Interval_nt<> tight(0);  // protected: sets and restores the rounding mode per operation
  for (const auto& x : terms)
    tight += CGAL::Interval_nt<>(CGAL::to_interval(x.num)) / CGAL::Interval_nt<>(CGAL::to_interval(x.den));
  if (tight.inf() > 0) return 1;
  if (tight.sup() < 0) return -1;
  Exact num(0), den(1);
  for (const auto& x : terms) {
    num = num * x.den + x.num * den;
    den = den * x.den;
  }
  return CGAL::sign(num);
}

// Exact, from the pieces of an edge (`pieces` in (tet, frame) order) as fractions num / den.
int dual_area_exact_sign(const std::vector<Point3>& p, const std::vector<std::array<int, 4>>& tets,
                         const std::vector<int>& pieces) {
  std::vector<Fraction<Exact>> exact;
  exact.reserve(pieces.size());
  for (int q : pieces) exact.push_back(piece_fraction<Exact>(p, tets, q));
  return sign_of_sum(exact);
}

// One tet around edge (a, b), as (a, b, k, l) (positive), and its circumcenter nt / (2 dt) with the origin at a.
struct TetAroundEdge {
  int k, l;
  Vec<Exact> nt;
  Exact dt;
};

// The exact sign of the dual area of edge (a, b) from the circumcenters of its tets. Each piece is
// ((C(abk) - C(abl)) x C_T) . e / 2 up to a positive factor common to all (see dual_piece; the origin anywhere on
// the edge's line). Chained around the edge (the tet after (a, b, k, l) is (a, b, l, k'), across face abl), the
// face circumcenter C(abl) lies on the line through the circumcenters T and T' of the two tets (all three are
// equidistant from a, b, l and lie in the bisector plane of ab), so C(abl) x (T' - T) = T x T' and the sum is
// sum (T x T') . e over consecutive tets, plus, where a chain ends (an edge on the mesh boundary),
// (C(abk) x T) . e for its first tet and -(C(abl) x T) . e for its last: the polygon of the tets' circumcenters
// (Voronoi's), closed by the face circumcenters on the boundary. Exact fractions of degree 9 over 6 in the
// coordinates where the pieces are 14 over 11, and no face circumcenter inside a chain. Nothing (the caller sums
// the pieces) when a face around the edge is in more than two of its tets (not a tet mesh there).
std::optional<int> dual_area_sign_by_circumcenters(const std::vector<Point3>& p,
                                                   const std::vector<std::array<int, 4>>& tets,
                                                   const std::vector<int>& pieces, int a) {
  std::vector<TetAroundEdge> around;
  around.reserve(pieces.size());
  const Vec<Exact> origin = lift<Exact>(p[a]);
  Vec<Exact> e;
  for (int q : pieces) {
    const auto& t = tets[q / 6];
    const int* f = kEdgeFrames[q % 6];
    const bool from_a = t[f[0]] == a;  // else (b, a, k, l) is positive, so (a, b, l, k) is
    const int k = t[f[from_a ? 2 : 3]], l = t[f[from_a ? 3 : 2]];
    e = lift<Exact>(p[t[f[from_a ? 1 : 0]]]) - origin;
    const Vec<Exact> u = lift<Exact>(p[k]) - origin, v = lift<Exact>(p[l]) - origin;
    const Exact ee = dot(e, e), uu = dot(u, u), vv = dot(v, v);
    const Vec<Exact> uv = cross(u, v);
    around.push_back({k, l, scaled(ee, uv) + scaled(uu, cross(v, e)) + scaled(vv, cross(e, u)), dot(e, uv)});
  }
  auto find = [&](int TetAroundEdge::*end, int v) {
    int found = -1;
    for (std::size_t m = 0; m < around.size(); ++m)
      if (around[m].*end == v) found = found < 0 ? static_cast<int>(m) : -2;
    return found;  // -1: none, -2: several
  };
  // The face circumcenter C(abv) = n / (2 d) (origin a) times T_m, dotted with e: a fraction.
  auto face_term = [&](int v, const TetAroundEdge& m) {
    const Vec<Exact> u = lift<Exact>(p[v]) - origin, w = cross(e, u);
    const Vec<Exact> n = scaled(dot(e, e), cross(u, w)) + scaled(dot(u, u), cross(w, e));
    return Fraction<Exact>{dot(cross(n, m.nt), e), dot(w, w) * m.dt};
  };
  std::vector<Fraction<Exact>> terms;
  for (const auto& m : around) {
    const int next = find(&TetAroundEdge::k, m.l), previous = find(&TetAroundEdge::l, m.k);
    if (next == -2 || previous == -2) return std::nullopt;
    if (next >= 0) {
      terms.push_back({dot(cross(m.nt, around[next].nt), e), m.dt * around[next].dt});
    } else {
      Fraction<Exact> x = face_term(m.l, m);
      terms.push_back({-x.num, x.den});
    }
    if (previous < 0) terms.push_back(face_term(m.k, m));
  }
  return sign_of_sum(terms);
}

// The pieces of each of `edges` (ascending), each list in (tet, frame) order.
std::vector<std::vector<int>> pieces_of(const std::vector<std::size_t>& edges, const std::vector<int>& edge_of,
                                        std::size_t edge_count) {
  std::vector<int> slot(edge_count, -1);
  for (std::size_t k = 0; k < edges.size(); ++k) slot[edges[k]] = static_cast<int>(k);
  std::vector<std::vector<int>> out(edges.size());
  for (std::size_t q = 0; q < edge_of.size(); ++q)
    if (slot[edge_of[q]] >= 0) out[slot[edge_of[q]]].push_back(static_cast<int>(q));
  return out;
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

// The circumcenter of a positive tet in doubles or, where the tet is flat in doubles (den == 0: the doubles
// would give NaN; *flat says so), computed exactly and rounded. Only these tets take the exact path, so every
// other tet's center, hence every other output, is the one of the doubles bit for bit. Rare (34 of the 3,666
// tets of check3d's UV sphere 30 x 40; none on tests/data/3d, ../shared/data/3d and the 6.3M tets of the
// 1e6-face torus), so the exact kernel stays off the loop's common path.
D3 tet_circumcenter(const Point3& pa, const Point3& pb, const Point3& pc, const Point3& pd, bool* flat) {
  const D3 a = d3(pa), u = d3(pb) - a, v = d3(pc) - a, w = d3(pd) - a;
  const double den = dot(u, cross(v, w));
  *flat = den == 0;
  if (*flat) return d3(exact_circumsphere(pa, pb, pc, pd).center);
  D3 num = times(dot(u, u), cross(v, w)) + times(dot(v, v), cross(w, u)) + times(dot(w, w), cross(u, v));
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

// The floating-point magnitudes: per edge the sum of its pieces in (tet, frame) order, as numpy's bincount adds
// (into `sum`), the per-point volumes, and the count of tets flat in doubles.
void float_magnitudes(const std::vector<Point3>& p, const std::vector<std::array<int, 4>>& tets,
                      const EdgeNumbering& numbering, std::vector<double>& sum, ControlVolumes3D& out) {
  sum.assign(numbering.edges.size(), 0.0);
  out.volumes.assign(p.size(), 0.0);
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const auto& c = tets[t];
    bool flat = false;
    D3 ct = tet_circumcenter(p[c[0]], p[c[1]], p[c[2]], p[c[3]], &flat);
    out.flat_in_floating_point += flat;
    double share[4] = {0, 0, 0, 0};
    for (int f = 0; f < 6; ++f) {
      const int* q = kEdgeFrames[f];
      auto [area, length] = float_piece(d3(p[c[q[0]]]), d3(p[c[q[1]]]), d3(p[c[q[2]]]), d3(p[c[q[3]]]), ct);
      sum[numbering.edge_of[6 * t + f]] += area;
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

// The exact signs of the dual areas of `numbering`'s edges into out.signs (and out.exact_evaluations).
void exact_signs(const std::vector<Point3>& points, const std::vector<std::array<int, 4>>& tets,
                 const EdgeNumbering& numbering, ControlVolumes3D& out) {
  const std::size_t edges = numbering.edges.size();
  // The interval filter, the bulk of the work, on two threads.
  std::vector<CGAL::Interval_nt_advanced> interval(edges, CGAL::Interval_nt_advanced(0));
  dual_area_intervals(points, tets, numbering.edge_of, interval);
  out.signs.assign(edges, 0);
  std::vector<std::size_t> undecided;
  for (std::size_t g = 0; g < edges; ++g) {
    if (interval[g].inf() > 0) {
      out.signs[g] = 1;
    } else if (interval[g].sup() < 0) {
      out.signs[g] = -1;
    } else {
      undecided.push_back(g);  // contains 0, or overflowed / NaN on extreme coordinates
    }
  }
  std::vector<std::vector<int>> undecided_pieces = pieces_of(undecided, numbering.edge_of, edges);
  // Exact arithmetic on two threads as well (halves of the undecided edges): a torus of 1e6 faces, whose
  // cross-sections are nearly cocircular, leaves 262k of its 7.3M edges undecided.
  auto exact = [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to; ++k) {
      const auto& pieces = undecided_pieces[k];
      const auto by_circumcenters =
          dual_area_sign_by_circumcenters(points, tets, pieces, numbering.edges[undecided[k]][0]);
      out.signs[undecided[k]] = by_circumcenters ? *by_circumcenters : dual_area_exact_sign(points, tets, pieces);
    }
  };
  const std::size_t middle = undecided.size() / 2;
  fork_join(undecided.size() >= 256, [&] { exact(0, middle); }, [&] { exact(middle, undecided.size()); });
  out.exact_evaluations = static_cast<int>(undecided.size());
}

}  // namespace

ControlVolumes3D control_volumes3d(const std::vector<Point3>& points, const std::vector<std::array<int, 4>>& tets) {
  require_positive_tets(points, tets);
  ControlVolumes3D out;
  EdgeNumbering numbering = number_edges(points.size(), tets);
  const std::size_t edges = numbering.edges.size();
  std::vector<double> sum;
  float_magnitudes(points, tets, numbering, sum, out);
  exact_signs(points, tets, numbering, out);
  out.dual_areas.reserve(edges);
  out.lengths.reserve(edges);
  for (std::size_t g = 0; g < edges; ++g) {
    const Segment& e = numbering.edges[g];
    out.dual_areas.push_back(out.signs[g] * std::abs(sum[g]));
    D3 d = d3(points[e[1]]) - d3(points[e[0]]);
    out.lengths.push_back(std::sqrt(dot(d, d)));
  }
  out.edges = std::move(numbering.edges);
  return out;
}

ControlVolumes3D dual_area_signs(const std::vector<Point3>& points, const std::vector<std::array<int, 4>>& tets) {
  require_positive_tets(points, tets);
  ControlVolumes3D out;
  EdgeNumbering numbering = number_edges(points.size(), tets);
  exact_signs(points, tets, numbering, out);
  out.edges = std::move(numbering.edges);
  return out;
}

}  // namespace nonobtuse
