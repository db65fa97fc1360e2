// Exact edge classification of a 2D mesh: kind, apex angle class on each side, local Delaunay property; the
// nonobtuse-boundary certificate.
#include "nonobtuse/check2d.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <sstream>
#include <string>
#include <utility>

#include "fork_join.h"

namespace nonobtuse {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;

Point at(const Mesh2& mesh, int i) { return Point(mesh.points[i].x, mesh.points[i].y); }

std::string describe_triangle(const Mesh2& mesh, std::size_t t) {
  std::ostringstream s;
  s.precision(17);
  s << "triangle " << t << " (";
  for (int k = 0; k < 3; ++k) {
    const Point2& p = mesh.points[mesh.triangles[t][k]];
    s << (k ? ", " : "") << mesh.triangles[t][k] << ": (" << p.x << ", " << p.y << ")";
  }
  s << ")";
  return s.str();
}

AngleClass classify_angle(const Point& a, const Point& apex, const Point& b) {
  switch (CGAL::angle(a, apex, b)) {
    case CGAL::ACUTE: return AngleClass::Acute;
    case CGAL::RIGHT: return AngleClass::Right;
    default: return AngleClass::Obtuse;
  }
}

// Every triangle index is a valid point index.
void require_valid_indices(const Mesh2& mesh) {
  const int n = static_cast<int>(mesh.points.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int v : mesh.triangles[t])
      if (v < 0 || v >= n)
        throw InvalidInput("triangle " + std::to_string(t) + " refers to point " + std::to_string(v) +
                           ", but there are " + std::to_string(n) + " points");
}

// Of a point p seen from a vertex v: 0 when its direction has angle in [0, pi) (p above v, or level with it and to
// its right), else 1. Exact: it compares coordinates (lexicographically by (y, x)).
int half_plane(const Point2& v, const Point2& p) { return p.y > v.y || (p.y == v.y && p.x > v.x) ? 0 : 1; }

// Whether the direction of p from v comes strictly before that of q, by angle in [0, 2 pi) from the +x axis
// (exact: half planes, then the orientation of (v, p, q) within one).
bool angle_before(const Mesh2& mesh, int v, int p, int q) {
  const int hp = half_plane(mesh.points[v], mesh.points[p]), hq = half_plane(mesh.points[v], mesh.points[q]);
  if (hp != hq) return hp < hq;
  return CGAL::orientation(at(mesh, v), at(mesh, p), at(mesh, q)) == CGAL::LEFT_TURN;
}

// Per vertex, its corners in triangles (low 32 bits) and how many of its triangles' angular wedges cross the
// ray from it in the +x direction (high 32 bits): the wedge of triangle (v, a, b) runs counter-clockwise from
// a to b through less than pi and crosses the ray (counted when it ends on it, not when it starts there) iff a
// lies in half plane 1 and b in half plane 0. The crossings of a closed fan are its winding number.
using CornerCounts = std::vector<std::uint64_t>;
constexpr std::uint64_t kCrossing = std::uint64_t{1} << 32;

// Every triangle in [t_begin, t_end) is strictly counter-clockwise (exact orientation; indices checked valid): the
// side assignment below and the cotangent signs in control_volumes2d rely on it. Adds each triangle's corners and
// ray crossings to `counts`.
void require_counter_clockwise(const Mesh2& mesh, std::size_t t_begin, std::size_t t_end, CornerCounts& counts) {
  for (std::size_t t = t_begin; t < t_end; ++t) {
    const auto& tri = mesh.triangles[t];
    if (CGAL::orientation(at(mesh, tri[0]), at(mesh, tri[1]), at(mesh, tri[2])) != CGAL::LEFT_TURN)
      throw InvalidInput(describe_triangle(mesh, t) + " is degenerate or clockwise; triangles must be "
                         "counter-clockwise");
    for (int k = 0; k < 3; ++k) {
      const Point2& v = mesh.points[tri[k]];
      const bool crossing = half_plane(v, mesh.points[tri[(k + 1) % 3]]) == 1 &&
                            half_plane(v, mesh.points[tri[(k + 2) % 3]]) == 0;
      counts[tri[k]] += 1 + (crossing ? kCrossing : 0);
    }
  }
}

// The half-edges of the mesh's triangles (indices checked valid), bucketed by their smaller vertex a with a
// counting sort (linear), so that both sides of an edge (a, b) share a bucket. A half-edge is one 64-bit word: b,
// a bit set when its triangle lies on the edge's left (runs counter-clockwise through a then b), and 3 triangle
// + the corner opposite the edge: the arrays stay small, as the certificate is a pass over memory. Buckets hold
// about six half-edges and are paired by a short scan, unsorted (sorting a million small buckets was most of the
// certificate's time); a bucket of a high-degree vertex is sorted first, so that pairing stays O(d log d).
class HalfEdges {
 public:
  // When `parallel`, the triangles are bucketed on two threads, each for half of them, into the sequential layout.
  HalfEdges(const Mesh2& mesh, bool parallel)
      : mesh_(mesh), start_(mesh.points.size() + 1, 0), half_(3 * mesh.triangles.size()) {
    if (mesh.triangles.size() > kMaxTriangles)
      throw InvalidInput("the mesh has " + std::to_string(mesh.triangles.size()) + " triangles; at most " +
                         std::to_string(kMaxTriangles) + " are supported");
    const std::size_t middle = mesh.triangles.size() / 2;
    std::vector<Index> upper(parallel ? start_.size() : 0, 0);  // bucket sizes from the upper half
    auto count = [&](std::size_t t_begin, std::size_t t_end, std::vector<Index>& size) {
      for (std::size_t t = t_begin; t < t_end; ++t)
        for (int k = 0; k < 3; ++k)
          ++size[std::min(mesh.triangles[t][(k + 1) % 3], mesh.triangles[t][(k + 2) % 3]) + 1];
    };
    fork_join(parallel, [&] { count(0, parallel ? middle : mesh.triangles.size(), start_); },
              [&] { if (parallel) count(middle, mesh.triangles.size(), upper); });
    std::vector<Index> next(start_.size() - 1);  // where the lower half's next half-edge of bucket a goes
    for (std::size_t a = 0; a + 1 < start_.size(); ++a) {
      if (parallel) start_[a + 1] += upper[a + 1];
      start_[a + 1] += start_[a];
      next[a] = start_[a];
      if (parallel) upper[a] = start_[a + 1] - upper[a + 1];  // the upper half's first slot in bucket a
    }
    auto fill = [&](std::size_t t_begin, std::size_t t_end, std::vector<Index>& slot) {
      for (std::size_t t = t_begin; t < t_end; ++t)
        for (int k = 0; k < 3; ++k) {
          int u = mesh.triangles[t][(k + 1) % 3], v = mesh.triangles[t][(k + 2) % 3];
          half_[slot[std::min(u, v)]++] =
              static_cast<std::uint64_t>(std::max(u, v)) << 32 | (u < v ? kLeft : 0) | (3 * t + k);
        }
    };
    fork_join(parallel, [&] { fill(0, parallel ? middle : mesh.triangles.size(), next); },
              [&] { if (parallel) fill(middle, mesh.triangles.size(), upper); });
    for (std::size_t a = 0; a + 1 < start_.size(); ++a)
      if (start_[a + 1] - start_[a] > kShort) std::sort(half_.begin() + start_[a], half_.begin() + start_[a + 1]);
  }

  // Calls f(a, b, left, right) once for every edge (a, b), a < b, that some triangle has, with its half-edges
  // whose triangle lies on the left and on the right (npos where there is none), in increasing a. Throws
  // InvalidInput when two triangles lie on the same side of an edge.
  // Only edges (a, b) with a in [a_begin, a_end): calls on disjoint ranges may run concurrently.
  template <class F>
  void for_each_edge(std::size_t a_begin, std::size_t a_end, F&& f) {
    for (std::size_t a = a_begin; a < a_end; ++a) {
      const std::size_t first = start_[a], last = start_[a + 1];
      for (std::size_t i = first; i < last; ++i) {
        if (half_[i] & kPaired) continue;
        std::size_t side[2] = {npos, npos};  // [left, right]
        side[left(i) ? 0 : 1] = i;
        for (std::size_t j = i + 1; j < last; ++j) {
          if (head(j) != head(i)) {
            if (last - first > kShort) break;  // sorted: the edge's half-edges are adjacent
            continue;
          }
          std::size_t& s = side[left(j) ? 0 : 1];
          if (s != npos) throw same_side(static_cast<int>(a), head(i), s, j);
          s = j;
          half_[j] |= kPaired;
        }
        f(static_cast<int>(a), head(i), side[0], side[1]);
      }
    }
  }

  // A half-edge of edge (a, b), a < b, or npos when no triangle has the edge.
  std::size_t find(int a, int b) const {
    for (std::size_t i = start_[a]; i < start_[a + 1]; ++i)
      if (head(i) == b) return i;
    return npos;
  }

  // Of half-edge i: its triangle and the triangle's vertex opposite it.
  int triangle(std::size_t i) const { return static_cast<int>(code(i) / 3); }
  int apex(std::size_t i) const { return mesh_.triangles[triangle(i)][code(i) % 3]; }

  std::size_t vertices() const { return start_.size() - 1; }
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

 private:
  static constexpr std::uint64_t kLeft = std::uint64_t{1} << 31, kPaired = std::uint64_t{1} << 30;
  static constexpr std::size_t kShort = 16;  // buckets up to this long are paired by a scan, longer ones sorted
  static constexpr std::size_t kMaxTriangles = (std::size_t{1} << 30) / 3;  // 3 t + k below both flag bits

  int head(std::size_t i) const { return static_cast<int>(half_[i] >> 32); }
  bool left(std::size_t i) const { return (half_[i] & kLeft) != 0; }
  std::uint32_t code(std::size_t i) const { return static_cast<std::uint32_t>(half_[i] & (kPaired - 1)); }

  InvalidInput same_side(int a, int b, std::size_t i, std::size_t j) const {
    return InvalidInput("edge (" + std::to_string(a) + ", " + std::to_string(b) + ") has " +
                        describe_triangle(mesh_, triangle(i)) + " and " + describe_triangle(mesh_, triangle(j)) +
                        " on the same side: the mesh is not a consistently oriented manifold");
  }

  const Mesh2& mesh_;
  using Index = std::uint32_t;  // half-edges number 3 m < 2^30
  std::vector<Index> start_;  // bucket a: half_[start_[a], start_[a + 1])
  std::vector<std::uint64_t> half_;
};

// constrained[i] for a half-edge i of every edge listed in mesh.segments (kind_of reads the first side it gets).
std::vector<char> constrained_edges(const Mesh2& mesh, const HalfEdges& h, std::size_t n_half) {
  std::vector<char> constrained(n_half, 0);
  for (std::size_t s = 0; s < mesh.segments.size(); ++s) {
    auto [a, b] = mesh.segments[s];
    std::size_t i = h.find(std::min(a, b), std::max(a, b));
    if (i == HalfEdges::npos)
      throw InvalidInput("segment " + std::to_string(s) + " (" + std::to_string(a) + ", " + std::to_string(b) +
                         ") is not an edge of any triangle");
    constrained[i] = 1;
  }
  return constrained;
}

// The kind of edge (a, b) from its half-edges with the triangle on the left and on the right (npos where none).
// regions: the triangles' region attributes, or nullptr when they are all equal (no lookups then: they are
// scattered reads, one pair per interior edge).
EdgeKind kind_of(const std::vector<double>* regions, const HalfEdges& h, std::size_t left, std::size_t right,
                 const std::vector<char>& constrained) {
  if (left == HalfEdges::npos || right == HalfEdges::npos) return EdgeKind::Boundary;
  if (constrained[left] || constrained[right]) return EdgeKind::Interface;
  if (regions && (*regions)[h.triangle(left)] != (*regions)[h.triangle(right)]) return EdgeKind::Interface;
  return EdgeKind::Interior;
}

// The report of edge (a, b) of kind `kind`: its sides (triangle, apex); angles stay Acute and locally_delaunay
// true (classify_angles, locally_delaunay).
EdgeReport edge_report(const HalfEdges& h, int a, int b, std::size_t left, std::size_t right, EdgeKind kind) {
  EdgeReport r{Segment{a, b}, kind, {}, {}, true};
  if (left != HalfEdges::npos) r.left = {h.triangle(left), h.apex(left)};
  if (right != HalfEdges::npos) r.right = {h.triangle(right), h.apex(right)};
  return r;
}

// The exact class of the angle opposite the edge on each side that has a triangle.
void classify_angles(const Mesh2& mesh, EdgeReport& r) {
  for (EdgeSide* side : {&r.left, &r.right})
    if (side->triangle >= 0)
      side->angle = classify_angle(at(mesh, r.edge[0]), at(mesh, side->apex), at(mesh, r.edge[1]));
}

// An end of a fan of triangles around `vertex`: the boundary edge to `other` where the fan starts (the first
// triangle, counter-clockwise around the vertex, has the edge vertex -> other) or ends (other -> vertex).
struct FanEnd {
  int vertex, other;
  bool start;
};

// The fan ends at both vertices of boundary edge (a, b), from its half-edge whose triangle is on the left
// (has a -> b) or on the right (has b -> a).
void add_fan_ends(std::vector<FanEnd>& ends, int a, int b, bool triangle_on_left) {
  if (!triangle_on_left) std::swap(a, b);
  ends.push_back({a, b, true});
  ends.push_back({b, a, false});
}

std::string describe_point(const Mesh2& mesh, int v) {
  std::ostringstream s;
  s.precision(17);
  s << "point " << v << " (" << mesh.points[v].x << ", " << mesh.points[v].y << ")";
  return s.str();
}

// The triangles at vertex v cover a neighbourhood of v at most once (exactly once when v is interior). The
// fans at v (its triangles, grouped between boundary edges) and the gaps between them, taken counter-clockwise,
// form closed walks around v; the walk from each fan end to the next fan start (by exact angle) is a gap. Fans
// and gaps cover every direction once iff the ends alternate start, end (no two in the same direction) and the
// ray crossings of the fans (`crossings`, see CornerCounts) plus those of the gaps add up to 1: every closed
// walk winds at least once.
void require_embedded_at(const Mesh2& mesh, int v, std::uint64_t crossings, std::vector<FanEnd> ends) {
  auto fail = [&](const std::string& why) {
    return InvalidInput("the triangles around " + describe_point(mesh, v) + " " + why +
                        ": the mesh overlaps itself (it is not embedded in the plane)");
  };
  std::sort(ends.begin(), ends.end(),
            [&](const FanEnd& x, const FanEnd& y) { return angle_before(mesh, v, x.other, y.other); });
  std::uint64_t winding = crossings;
  for (std::size_t i = 0; i < ends.size(); ++i) {
    const FanEnd& e = ends[i];
    const FanEnd& next = ends[(i + 1) % ends.size()];
    if (ends.size() > 1 && !angle_before(mesh, v, e.other, next.other) && !angle_before(mesh, v, next.other, e.other))
      throw fail("have boundary edges to points " + std::to_string(e.other) + " and " + std::to_string(next.other) +
                 " in the same direction");
    if (e.start == next.start) throw fail("overlap: two fans of triangles around it cover the same directions");
    if (!e.start) winding += angle_before(mesh, v, next.other, e.other);  // the gap from e to next crosses the ray
  }
  if (winding != 1)
    throw fail(ends.empty() ? "wind " + std::to_string(winding) + " times around it"
                            : "cover some directions from it more than once");
}

// Every vertex in a triangle passes require_embedded_at. counts: CornerCounts; ends: the FanEnd of every boundary
// edge, in any order. Linear: the fan ends are bucketed by vertex with a counting sort.
void require_embedded(const Mesh2& mesh, const CornerCounts& counts, const std::vector<FanEnd>& ends) {
  const std::size_t n = mesh.points.size();
  std::vector<std::uint32_t> start(n + 1, 0);
  for (const FanEnd& e : ends) ++start[e.vertex + 1];
  for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<FanEnd> by_vertex(ends.size());
  std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
  for (const FanEnd& e : ends) by_vertex[next[e.vertex]++] = e;
  for (std::size_t v = 0; v < n; ++v) {
    if ((counts[v] & (kCrossing - 1)) == 0) continue;  // in no triangle
    const std::uint64_t crossings = counts[v] >> 32;
    if (start[v] == start[v + 1]) {
      if (crossings != 1) require_embedded_at(mesh, static_cast<int>(v), crossings, {});
      continue;
    }
    require_embedded_at(mesh, static_cast<int>(v), crossings,
                        std::vector<FanEnd>(by_vertex.begin() + start[v], by_vertex.begin() + start[v + 1]));
  }
}

// Calls f(part, report) for every edge whose kind keep(kind) accepts, after checking the triangles' indices and
// orientation (require_counter_clockwise), the region list's length and the segments; then checks that the mesh
// does not overlap itself around any vertex (require_embedded: an error there discards what f collected). Large meshes are done in two
// halves on two threads: the triangles' orientation, then edges (a, b) with a below and above the middle vertex
// (part 0 and 1: f must keep its parts apart). Either way part 0 gets its edges in increasing a, and the error
// reported is the first in that order. Sequential when threads is 1 or the mesh is small.
template <class Keep, class F>
void for_each_edge_report(const Mesh2& mesh, int threads, Keep&& keep, F&& f) {
  if (!mesh.triangle_region.empty() && mesh.triangle_region.size() != mesh.triangles.size())
    throw InvalidInput("triangle_region has " + std::to_string(mesh.triangle_region.size()) + " entries for " +
                       std::to_string(mesh.triangles.size()) + " triangles");
  require_valid_indices(mesh);
  const bool parallel = worth_forking(mesh.triangles.size(), threads);
  const std::size_t m = mesh.triangles.size();
  CornerCounts counts(mesh.points.size(), 0), upper_counts(parallel ? mesh.points.size() : 0, 0);
  fork_join(parallel, [&] { require_counter_clockwise(mesh, 0, parallel ? m / 2 : m, counts); },
            [&] { if (parallel) require_counter_clockwise(mesh, m / 2, m, upper_counts); });
  for (std::size_t v = 0; v < upper_counts.size(); ++v) counts[v] += upper_counts[v];
  HalfEdges h(mesh, parallel);
  const std::vector<char> constrained = constrained_edges(mesh, h, 3 * mesh.triangles.size());
  const auto& region = mesh.triangle_region;
  const bool one_region = std::adjacent_find(region.begin(), region.end(), std::not_equal_to<>()) == region.end();
  const std::vector<double>* regions = one_region ? nullptr : &region;
  std::vector<FanEnd> fan_ends[2];
  auto part = [&](int p, std::size_t a_begin, std::size_t a_end) {
    h.for_each_edge(a_begin, a_end, [&](int a, int b, std::size_t left, std::size_t right) {
      if (left == HalfEdges::npos || right == HalfEdges::npos) add_fan_ends(fan_ends[p], a, b, left != HalfEdges::npos);
      EdgeKind kind = kind_of(regions, h, left, right, constrained);
      if (keep(kind)) f(p, edge_report(h, a, b, left, right, kind));
    });
  };
  const std::size_t n = h.vertices();
  fork_join(parallel, [&] { part(0, 0, n / 2); }, [&] { part(1, n / 2, n); });
  fan_ends[0].insert(fan_ends[0].end(), fan_ends[1].begin(), fan_ends[1].end());
  require_embedded(mesh, counts, fan_ends[0]);
}

// Exact local Delaunay test: the right apex is not strictly inside the circumcircle of the left triangle.
bool locally_delaunay(const Mesh2& mesh, const EdgeReport& e) {
  if (e.left.triangle < 0 || e.right.triangle < 0) return true;
  auto side = CGAL::side_of_oriented_circle(at(mesh, e.edge[0]), at(mesh, e.edge[1]), at(mesh, e.left.apex),
                                            at(mesh, e.right.apex));
  return side != CGAL::ON_POSITIVE_SIDE;
}

}  // namespace

std::vector<EdgeReport> classify_edges(const Mesh2& mesh, int threads) {
  std::vector<EdgeReport> edges[2];
  for_each_edge_report(mesh, threads, [](EdgeKind) { return true; }, [&](int part, EdgeReport r) {
    classify_angles(mesh, r);
    r.locally_delaunay = locally_delaunay(mesh, r);
    edges[part].push_back(r);
  });
  edges[0].insert(edges[0].end(), edges[1].begin(), edges[1].end());
  std::sort(edges[0].begin(), edges[0].end(), [](const EdgeReport& x, const EdgeReport& y) { return x.edge < y.edge; });
  return std::move(edges[0]);
}

long long count_obtuse_boundary_sides(const Mesh2& mesh, int threads) {
  long long obtuse[2] = {0, 0};
  auto guarded = [](EdgeKind kind) { return kind != EdgeKind::Interior; };
  for_each_edge_report(mesh, threads, guarded, [&](int part, EdgeReport r) {
    classify_angles(mesh, r);
    for (const EdgeSide* side : {&r.left, &r.right})
      obtuse[part] += side->triangle >= 0 && side->angle == AngleClass::Obtuse;
  });
  return obtuse[0] + obtuse[1];
}

}  // namespace nonobtuse
