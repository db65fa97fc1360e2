// Exact edge classification of a 2D mesh: kind, apex angle class on each side, local Delaunay property; the
// nonobtuse-boundary certificate.
#include "nonobtuse/check2d.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <utility>

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

// Every triangle index is a valid point index and every triangle is strictly counter-clockwise (exact
// orientation): the side assignment below and the cotangent signs in control_volumes2d rely on it.
void require_counter_clockwise(const Mesh2& mesh) {
  const int n = static_cast<int>(mesh.points.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int v : mesh.triangles[t])
      if (v < 0 || v >= n)
        throw InvalidInput("triangle " + std::to_string(t) + " refers to point " + std::to_string(v) +
                           ", but there are " + std::to_string(n) + " points");
    const auto& tri = mesh.triangles[t];
    if (CGAL::orientation(at(mesh, tri[0]), at(mesh, tri[1]), at(mesh, tri[2])) != CGAL::LEFT_TURN)
      throw InvalidInput(describe_triangle(mesh, t) + " is degenerate or clockwise; triangles must be "
                         "counter-clockwise");
  }
}

// The half-edges of the mesh's triangles (indices checked valid), bucketed by their smaller vertex a with a
// counting sort (linear; comparison-sorting 3m keys dominated refine's certificate at 1e6 triangles), each
// bucket, a handful of half-edges, sorted by (b, triangle): the sides of edge (a, b) are adjacent.
class HalfEdges {
 public:
  struct HalfEdge {
    int b, triangle, apex;  // the edge (a, b), a < b, of `triangle`, whose vertex opposite it is `apex`
    bool left;              // the triangle traverses the edge as (a, b): it lies on the edge's left
  };

  explicit HalfEdges(const Mesh2& mesh) : start_(mesh.points.size() + 1, 0), half_(3 * mesh.triangles.size()) {
    auto ends = [&mesh](std::size_t t, int k) {
      int u = mesh.triangles[t][(k + 1) % 3], v = mesh.triangles[t][(k + 2) % 3];
      return std::make_pair(std::min(u, v), std::max(u, v));
    };
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      for (int k = 0; k < 3; ++k) ++start_[ends(t, k).first + 1];
    for (std::size_t a = 0; a + 1 < start_.size(); ++a) start_[a + 1] += start_[a];
    std::vector<std::size_t> next(start_.begin(), start_.end() - 1);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const auto& tri = mesh.triangles[t];
        auto [a, b] = ends(t, k);
        half_[next[a]++] = {b, static_cast<int>(t), tri[k], tri[(k + 1) % 3] == a};
      }
    for (std::size_t a = 0; a + 1 < start_.size(); ++a)
      std::sort(half_.begin() + start_[a], half_.begin() + start_[a + 1], [](const HalfEdge& x, const HalfEdge& y) {
        return std::make_pair(x.b, x.triangle) < std::make_pair(y.b, y.triangle);
      });
  }

  // Calls f(a, first, last) for every edge (a, half(first).b), in increasing (a, b) order; [first, last) are its
  // half-edges.
  template <class F>
  void for_each_edge(F&& f) const {
    for (std::size_t a = 0; a + 1 < start_.size(); ++a)
      for (std::size_t first = start_[a], last; first < start_[a + 1]; first = last) {
        for (last = first + 1; last < start_[a + 1] && half_[last].b == half_[first].b;) ++last;
        f(static_cast<int>(a), first, last);
      }
  }

  // The first half-edge of edge (a, b), a < b, or npos when no triangle has it.
  std::size_t find(int a, int b) const {
    for (std::size_t i = start_[a]; i < start_[a + 1]; ++i)
      if (half_[i].b == b) return i;
    return npos;
  }

  const HalfEdge& half(std::size_t i) const { return half_[i]; }
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

 private:
  std::vector<std::size_t> start_;  // bucket a: half_[start_[a], start_[a + 1])
  std::vector<HalfEdge> half_;
};

// constrained[i] for the first half-edge i of every edge listed in mesh.segments.
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

EdgeKind kind_of(const Mesh2& mesh, const EdgeReport& e, bool constrained) {
  if (e.left.triangle < 0 || e.right.triangle < 0) return EdgeKind::Boundary;
  if (constrained) return EdgeKind::Interface;
  const auto& region = mesh.triangle_region;
  if (!region.empty() && region[e.left.triangle] != region[e.right.triangle]) return EdgeKind::Interface;
  return EdgeKind::Interior;
}

// The report of edge (a, b) from its half-edges [first, last): sides (triangle, apex) and kind; angles stay
// Acute and locally_delaunay true (classify_angles, locally_delaunay). Invariant: at most one triangle per side;
// the triangle traversing the edge as (a, b), a < b, lies on the left.
EdgeReport edge_report(const Mesh2& mesh, const HalfEdges& h, int a, std::size_t first, std::size_t last,
                       bool constrained) {
  EdgeReport r{Segment{a, h.half(first).b}, EdgeKind::Interior, {}, {}, true};
  for (std::size_t i = first; i < last; ++i) {
    EdgeSide& side = h.half(i).left ? r.left : r.right;
    if (side.triangle >= 0)
      throw InvalidInput("edge (" + std::to_string(r.edge[0]) + ", " + std::to_string(r.edge[1]) + ") has " +
                         describe_triangle(mesh, side.triangle) + " and " +
                         describe_triangle(mesh, h.half(i).triangle) +
                         " on the same side: the mesh is not a consistently oriented manifold");
    side.triangle = h.half(i).triangle;
    side.apex = h.half(i).apex;
  }
  r.kind = kind_of(mesh, r, constrained);
  return r;
}

// The exact class of the angle opposite the edge on each side that has a triangle.
void classify_angles(const Mesh2& mesh, EdgeReport& r) {
  for (EdgeSide* side : {&r.left, &r.right})
    if (side->triangle >= 0)
      side->angle = classify_angle(at(mesh, r.edge[0]), at(mesh, side->apex), at(mesh, r.edge[1]));
}

// Every edge's report, with f(report) called in increasing (a, b) order, after checking the triangles
// (require_counter_clockwise), the region list's length and the segments.
template <class F>
void for_each_edge_report(const Mesh2& mesh, F&& f) {
  if (!mesh.triangle_region.empty() && mesh.triangle_region.size() != mesh.triangles.size())
    throw InvalidInput("triangle_region has " + std::to_string(mesh.triangle_region.size()) + " entries for " +
                       std::to_string(mesh.triangles.size()) + " triangles");
  require_counter_clockwise(mesh);
  const HalfEdges h(mesh);
  const std::vector<char> constrained = constrained_edges(mesh, h, 3 * mesh.triangles.size());
  h.for_each_edge([&](int a, std::size_t first, std::size_t last) {
    f(edge_report(mesh, h, a, first, last, constrained[first] != 0));
  });
}

// Exact local Delaunay test: the right apex is not strictly inside the circumcircle of the left triangle.
bool locally_delaunay(const Mesh2& mesh, const EdgeReport& e) {
  if (e.left.triangle < 0 || e.right.triangle < 0) return true;
  auto side = CGAL::side_of_oriented_circle(at(mesh, e.edge[0]), at(mesh, e.edge[1]), at(mesh, e.left.apex),
                                            at(mesh, e.right.apex));
  return side != CGAL::ON_POSITIVE_SIDE;
}

}  // namespace

std::vector<EdgeReport> classify_edges(const Mesh2& mesh) {
  std::vector<EdgeReport> edges;
  edges.reserve(3 * mesh.triangles.size() / 2 + mesh.segments.size());  // E = (3 m + boundary edges) / 2
  for_each_edge_report(mesh, [&](EdgeReport r) {
    classify_angles(mesh, r);
    r.locally_delaunay = locally_delaunay(mesh, r);
    edges.push_back(r);
  });
  return edges;
}

long long count_obtuse_boundary_sides(const Mesh2& mesh) {
  long long obtuse = 0;
  for_each_edge_report(mesh, [&](EdgeReport r) {
    if (r.kind == EdgeKind::Interior) return;
    classify_angles(mesh, r);
    for (const EdgeSide* side : {&r.left, &r.right}) obtuse += side->triangle >= 0 && side->angle == AngleClass::Obtuse;
  });
  return obtuse;
}

}  // namespace nonobtuse
