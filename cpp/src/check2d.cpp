// Exact edge classification of a 2D mesh: kind, apex angle class on each side, local Delaunay property.
#include "nonobtuse/check2d.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <map>
#include <set>
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

// Collects each edge's sides. Invariant: at most one triangle per side of an edge; the triangle traversing the
// edge as (a, b), a < b, lies on the left.
std::map<Segment, EdgeReport> collect_sides(const Mesh2& mesh) {
  std::map<Segment, EdgeReport> edges;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      int u = tri[(k + 1) % 3], v = tri[(k + 2) % 3], apex = tri[k];
      Segment key{std::min(u, v), std::max(u, v)};
      auto [it, fresh] = edges.try_emplace(key, EdgeReport{key, EdgeKind::Interior, {}, {}, true});
      EdgeSide& side = u < v ? it->second.left : it->second.right;
      if (side.triangle >= 0)
        throw InvalidInput("edge (" + std::to_string(key[0]) + ", " + std::to_string(key[1]) + ") has " +
                           describe_triangle(mesh, side.triangle) + " and " + describe_triangle(mesh, t) +
                           " on the same side: the mesh is not a consistently oriented manifold");
      side.triangle = static_cast<int>(t);
      side.apex = apex;
      side.angle = classify_angle(at(mesh, u), at(mesh, apex), at(mesh, v));
    }
  }
  return edges;
}

EdgeKind kind_of(const Mesh2& mesh, const EdgeReport& e, bool constrained) {
  if (e.left.triangle < 0 || e.right.triangle < 0) return EdgeKind::Boundary;
  if (constrained) return EdgeKind::Interface;
  const auto& region = mesh.triangle_region;
  if (!region.empty() && region[e.left.triangle] != region[e.right.triangle]) return EdgeKind::Interface;
  return EdgeKind::Interior;
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
  if (!mesh.triangle_region.empty() && mesh.triangle_region.size() != mesh.triangles.size())
    throw InvalidInput("triangle_region has " + std::to_string(mesh.triangle_region.size()) + " entries for " +
                       std::to_string(mesh.triangles.size()) + " triangles");
  require_counter_clockwise(mesh);
  std::map<Segment, EdgeReport> edges = collect_sides(mesh);
  std::set<Segment> constrained;
  for (std::size_t s = 0; s < mesh.segments.size(); ++s) {
    auto [a, b] = mesh.segments[s];
    Segment key{std::min(a, b), std::max(a, b)};
    if (edges.find(key) == edges.end())
      throw InvalidInput("segment " + std::to_string(s) + " (" + std::to_string(a) + ", " + std::to_string(b) +
                         ") is not an edge of any triangle");
    constrained.insert(key);
  }
  std::vector<EdgeReport> out;
  out.reserve(edges.size());
  for (auto& [key, e] : edges) {
    e.kind = kind_of(mesh, e, constrained.count(key) > 0);
    e.locally_delaunay = locally_delaunay(mesh, e);
    out.push_back(e);
  }
  return out;
}

}  // namespace nonobtuse
