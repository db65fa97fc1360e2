// Exact signs of the 3D dual (Voronoi face) areas: interval filter, exact rationals when it cannot decide.
#include "nonobtuse/control_volumes3d.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <string>

namespace nonobtuse {
namespace {

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

// Circumcenter of triangle (a, b, c): a + (|u|^2 v x w + |v|^2 w x u) / (2 |w|^2), u = b - a, v = c - a, w = u x v.
template <class NT>
Vec<NT> triangle_circumcenter(const Vec<NT>& a, const Vec<NT>& b, const Vec<NT>& c) {
  Vec<NT> u = b - a, v = c - a, w = cross(u, v);
  Vec<NT> num = scaled(dot(u, u), cross(v, w)) + scaled(dot(v, v), cross(w, u));
  return a + scaled(NT(1) / (NT(2) * dot(w, w)), num);
}

// Circumcenter of tet (a, b, c, d): a + (|u|^2 v x w + |v|^2 w x u + |w|^2 u x v) / (2 u . (v x w)).
template <class NT>
Vec<NT> tet_circumcenter(const Vec<NT>& a, const Vec<NT>& b, const Vec<NT>& c, const Vec<NT>& d) {
  Vec<NT> u = b - a, v = c - a, w = d - a;
  Vec<NT> num = scaled(dot(u, u), cross(v, w)) + scaled(dot(v, v), cross(w, u)) + scaled(dot(w, w), cross(u, v));
  return a + scaled(NT(1) / (NT(2) * dot(u, cross(v, w))), num);
}

// Twice the signed area of the piece (M, C(ijk), C_T, C(ijl)) of the face dual to edge (i, j) inside the tet,
// times |j - i|. (i, j, k, l) is positively oriented; the piece then runs counter-clockwise seen from j when C_T
// is inside the tet, so the area vector points along i -> j.
template <class NT>
NT dual_piece(const Point3& pi, const Point3& pj, const Point3& pk, const Point3& pl) {
  Vec<NT> i = lift<NT>(pi), j = lift<NT>(pj), k = lift<NT>(pk), l = lift<NT>(pl);
  Vec<NT> m = scaled(NT(0.5), i + j);  // exact: halving a sum of doubles
  Vec<NT> c1 = triangle_circumcenter(i, j, k) - m, c2 = triangle_circumcenter(i, j, l) - m;
  Vec<NT> ct = tet_circumcenter(i, j, k, l) - m;
  return dot(cross(c1, ct) + cross(ct, c2), j - i);
}

// The six edges (i, j) of a positive tet (0, 1, 2, 3), each with the other two vertices (k, l) ordered so that
// (i, j, k, l) is an even permutation, hence positively oriented as well.
constexpr int kEdgeFrames[6][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 2, 0, 3}, {1, 3, 2, 0}, {2, 3, 0, 1}};

struct Piece {
  Segment edge;  // a < b
  int tet, frame;
};

template <class NT>
NT dual_area_sum(const std::vector<Point3>& p, const std::vector<std::array<int, 4>>& tets,
                 const Piece* first, const Piece* last) {
  NT sum(0);
  for (const Piece* q = first; q != last; ++q) {
    const auto& t = tets[q->tet];
    const int* f = kEdgeFrames[q->frame];
    sum = sum + dual_piece<NT>(p[t[f[0]]], p[t[f[1]]], p[t[f[2]]], p[t[f[3]]]);
  }
  return sum;
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
      auto x = dual_area_sum<CGAL::Interval_nt_advanced>(points, tets, &pieces[starts[g]], &pieces[starts[g + 1]]);
      if (x.inf() > 0) {
        out.signs[g] = 1;
      } else if (x.sup() < 0) {
        out.signs[g] = -1;
      } else {
        undecided.push_back(g);  // contains 0, or overflowed / NaN on extreme coordinates
      }
    }
  }
  for (std::size_t g : undecided) {
    auto exact = dual_area_sum<CGAL::Exact_rational>(points, tets, &pieces[starts[g]], &pieces[starts[g + 1]]);
    out.signs[g] = CGAL::sign(exact);
  }
  out.exact_evaluations = static_cast<int>(undecided.size());
  out.edges.reserve(edges);
  for (std::size_t g = 0; g < edges; ++g) out.edges.push_back(pieces[starts[g]].edge);
  return out;
}

}  // namespace nonobtuse
