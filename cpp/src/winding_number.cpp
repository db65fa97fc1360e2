// The exact integer winding number of a closed oriented triangle surface around points, by vertical ray casting
// with a symbolic perturbation of the query point, and the Delaunay cells a closed surface encloses.
//
// The ray goes up (+z) from q' = q + (e, e^2, e^3) for an infinitesimal e > 0 (simulation of simplicity). q' lies
// on no triangle and its ray meets no edge, so every decision has a sign: a predicate that is 0 at q is decided by
// its first non-zero derivative in e. A triangle whose xy projection is flat (a vertical triangle) is never hit
// by the perturbed ray. Every other triangle t = (a, b, c), with s = orient2d(a, b, c) of the xy projection, is hit
// when q' projects inside it (three orient2d signs equal to s) and q' lies below its plane; it adds s (an outward
// triangle facing up is where the ray leaves an outward oriented volume). The sum over the triangles is the
// winding number of q', an integer when every edge is traversed as often in one direction as in the other (a
// closed oriented surface, a 2-cycle): then it does not depend on the ray, and it is the generalized winding
// number of q' (libigl's, exactly). Every sign is a CGAL exact predicate on the input doubles.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "fork_join.h"
#include "nonobtuse/plc_predicates.h"

namespace nonobtuse {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P2 = K::Point_2;
using P3 = K::Point_3;

int sign_of(CGAL::Orientation o) { return o == CGAL::POSITIVE ? 1 : o == CGAL::NEGATIVE ? -1 : 0; }
int compare(double x, double y) { return x < y ? -1 : x > y ? 1 : 0; }

// The sign of orient2d(u, v, q') for the xy projections, q' = q + (e, e^2): orient2d(u, v, q) =
// (vx - ux)(qy - uy) - (vy - uy)(qx - ux), whose derivatives in qx and qy are uy - vy and vx - ux. Never 0 when
// u and v project to distinct points.
int orient2d_perturbed(const P2& u, const P2& v, const P2& q) {
  int o = sign_of(CGAL::orientation(u, v, q));
  if (o != 0) return o;
  int dx = compare(u.y(), v.y());
  return dx != 0 ? dx : compare(v.x(), u.x());
}

// The sign of orient3d(a, b, c, q'), q' = q + (e, e^2, e^3): orient3d is (q - a) . n with n = (b - a) x (c - a),
// so the derivatives in qx, qy, qz are the components of n, the orient2d of the yz, zx and xy projections.
// `s_xy` (!= 0) is the last.
int orient3d_perturbed(const P3& a, const P3& b, const P3& c, const P3& q, int s_xy) {
  int o = sign_of(CGAL::orientation(a, b, c, q));
  if (o != 0) return o;
  int nx = sign_of(CGAL::orientation(P2(a.y(), a.z()), P2(b.y(), b.z()), P2(c.y(), c.z())));
  if (nx != 0) return nx;
  int ny = sign_of(CGAL::orientation(P2(a.z(), a.x()), P2(b.z(), b.x()), P2(c.z(), c.x())));
  return ny != 0 ? ny : s_xy;
}

// A uniform grid over the xy bounding box of the surface; each bucket lists the non-vertical triangles whose xy
// bounding box meets it (CSR). The bucket of a coordinate is a monotone function of it, so a triangle whose box
// contains q's projection is in q's bucket.
class ColumnGrid {
 public:
  ColumnGrid(const std::vector<P3>& p, const std::vector<PlcTriangle>& triangles) : p_(p), tri_(triangles) {
    for (std::size_t t = 0; t < tri_.size(); ++t) {
      const auto& k = tri_[t];
      int s = sign_of(CGAL::orientation(xy(k[0]), xy(k[1]), xy(k[2])));
      if (s == 0) continue;  // vertical: never hit by the perturbed ray
      kept_.push_back(static_cast<int>(t));
      sign_.push_back(static_cast<std::int8_t>(s));
      box_.push_back(p[k[0]].bbox() + p[k[1]].bbox() + p[k[2]].bbox());
    }
    if (kept_.empty()) return;
    CGAL::Bbox_3 all = box_[0];
    for (const auto& b : box_) all += b;
    x0_ = all.xmin();
    y0_ = all.ymin();
    x1_ = all.xmax();
    y1_ = all.ymax();
    // About one bucket per triangle, square buckets.
    double w = std::max(x1_ - x0_, 1e-300), h = std::max(y1_ - y0_, 1e-300);
    double cells = static_cast<double>(kept_.size());
    nx_ = static_cast<int>(std::clamp(std::sqrt(cells * w / h), 1.0, 4096.0));
    ny_ = static_cast<int>(std::clamp(cells / nx_, 1.0, 4096.0));
    sx_ = nx_ / w;
    sy_ = ny_ / h;
    start_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
    for (std::size_t i = 0; i < kept_.size(); ++i) for_each_bucket(box_[i], [&](std::size_t b) { ++start_[b + 1]; });
    for (std::size_t b = 1; b < start_.size(); ++b) start_[b] += start_[b - 1];
    entries_.resize(start_.back());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < kept_.size(); ++i)
      for_each_bucket(box_[i], [&](std::size_t b) { entries_[fill[b]++] = static_cast<int>(i); });
  }

  int winding_number(const P3& q) const {
    if (kept_.empty() || q.x() < x0_ || q.x() > x1_ || q.y() < y0_ || q.y() > y1_) return 0;
    const P2 q2 = xy(q);
    std::size_t bucket = static_cast<std::size_t>(row(q.y())) * nx_ + column(q.x());
    int w = 0;
    for (std::size_t e = start_[bucket]; e < start_[bucket + 1]; ++e) {
      int i = entries_[e];
      const auto& b = box_[i];
      if (q.x() < b.xmin() || q.x() > b.xmax() || q.y() < b.ymin() || q.y() > b.ymax() || q.z() > b.zmax()) continue;
      const auto& k = tri_[kept_[i]];
      int s = sign_[i];
      const P2 a = xy(k[0]), bb = xy(k[1]), c = xy(k[2]);
      if (orient2d_perturbed(a, bb, q2) != s || orient2d_perturbed(bb, c, q2) != s ||
          orient2d_perturbed(c, a, q2) != s)
        continue;
      if (orient3d_perturbed(p_[k[0]], p_[k[1]], p_[k[2]], q, s) == -s) w += s;  // q' below the plane: hit
    }
    return w;
  }

 private:
  P2 xy(int v) const { return xy(p_[v]); }
  static P2 xy(const P3& p) { return P2(p.x(), p.y()); }
  int column(double x) const { return std::clamp(static_cast<int>((x - x0_) * sx_), 0, nx_ - 1); }
  int row(double y) const { return std::clamp(static_cast<int>((y - y0_) * sy_), 0, ny_ - 1); }
  template <class F>
  void for_each_bucket(const CGAL::Bbox_3& b, const F& f) const {
    for (int gy = row(b.ymin()); gy <= row(b.ymax()); ++gy)
      for (int gx = column(b.xmin()); gx <= column(b.xmax()); ++gx) f(static_cast<std::size_t>(gy) * nx_ + gx);
  }

  const std::vector<P3>& p_;
  const std::vector<PlcTriangle>& tri_;
  std::vector<int> kept_;  // triangle index of each non-vertical triangle
  std::vector<std::int8_t> sign_;
  std::vector<CGAL::Bbox_3> box_;
  double x0_ = 0, y0_ = 0, x1_ = 0, y1_ = 0, sx_ = 1, sy_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<std::size_t> start_;
  std::vector<int> entries_;
};

std::vector<P3> to_cgal(const std::vector<PlcPoint>& points) {
  std::vector<P3> p;
  p.reserve(points.size());
  for (const auto& q : points) p.emplace_back(q.x, q.y, q.z);
  return p;
}

// Winding numbers of `queries` (indices into out) split over two threads for large inputs.
template <class Query>
void wind_all(const ColumnGrid& grid, std::size_t n, const Query& query, std::vector<int>& out) {
  out.assign(n, 0);
  auto range = [&](std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to; ++i) out[i] = grid.winding_number(query(i));
  };
  fork_join(worth_forking(n, 2), [&] { range(0, n / 2); }, [&] { range(n / 2, n); });
}

}  // namespace

std::array<int, 2> unbalanced_edge(const std::vector<PlcTriangle>& triangles) {
  // +1 per traversal a -> b with a < b, -1 per b -> a: every sum is 0 iff the surface is a 2-cycle.
  std::vector<std::pair<std::array<int, 2>, int>> uses;
  uses.reserve(3 * triangles.size());
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) {
      int a = t[k], b = t[(k + 1) % 3];
      uses.push_back(a < b ? std::make_pair(std::array<int, 2>{a, b}, 1) : std::make_pair(std::array<int, 2>{b, a}, -1));
    }
  std::sort(uses.begin(), uses.end());
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    int sum = 0;
    for (; j < uses.size() && uses[j].first == uses[i].first; ++j) sum += uses[j].second;
    if (sum != 0) return uses[i].first;
    i = j;
  }
  return {-1, -1};
}

std::vector<int> surface_winding_numbers(const std::vector<PlcPoint>& points,
                                         const std::vector<PlcTriangle>& triangles,
                                         const std::vector<PlcPoint>& queries) {
  const std::vector<P3> p = to_cgal(points);
  const ColumnGrid grid(p, triangles);
  std::vector<int> out;
  wind_all(grid, queries.size(), [&](std::size_t i) { return P3(queries[i].x, queries[i].y, queries[i].z); },
           out);
  return out;
}

std::vector<std::array<int, 4>> delaunay_cells_inside_surface(const std::vector<PlcPoint>& points,
                                                              const std::vector<PlcTriangle>& triangles) {
  return cells_inside_surface(points, triangles, delaunay_tetrahedra(points));
}

std::vector<std::array<int, 4>> cells_inside_surface(const std::vector<PlcPoint>& points,
                                                     const std::vector<PlcTriangle>& triangles,
                                                     const std::vector<std::array<int, 4>>& cells) {
  const std::vector<P3> p = to_cgal(points);
  const ColumnGrid grid(p, triangles);
  std::vector<int> winding;
  wind_all(grid, cells.size(), [&](std::size_t i) {
    const auto& c = cells[i];
    auto centroid = [&](auto coordinate) {
      return (((coordinate(p[c[0]]) + coordinate(p[c[1]])) + coordinate(p[c[2]])) + coordinate(p[c[3]])) * 0.25;
    };
    return P3(centroid([](const P3& q) { return q.x(); }), centroid([](const P3& q) { return q.y(); }),
              centroid([](const P3& q) { return q.z(); }));
  }, winding);
  std::vector<std::array<int, 4>> inside;
  for (std::size_t i = 0; i < cells.size(); ++i)
    if (winding[i] != 0) inside.push_back(cells[i]);
  return inside;
}

}  // namespace nonobtuse
