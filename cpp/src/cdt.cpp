#include "cdt.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>

#include "nonobtuse/triangulate.h"

namespace nonobtuse::cdt {
namespace {

std::string describe(const Point& p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x() << ", " << p.y() << ")";
  return s.str();
}

void insert_hull_constraints(CDT& cdt) {
  std::vector<std::pair<Vertex_handle, Vertex_handle>> hull;
  auto inf = cdt.infinite_vertex();
  auto fc = cdt.incident_faces(inf), done = fc;
  if (fc == nullptr) return;
  do {
    int i = fc->index(inf);
    hull.emplace_back(fc->vertex(CDT::ccw(i)), fc->vertex(CDT::cw(i)));
  } while (++fc != done);
  for (auto& [a, b] : hull) cdt.insert_constraint(a, b);
}

// The domain's points, each with its input index, in insertion order: CGAL's spatial sort (a Hilbert curve over
// median cuts, in randomized rounds) of each of k near-square slabs cut across the bounding box's long side,
// slabs in order. The Hilbert sort alternates x and y cuts, so on a long thin box (a layer, 1000:1) its cells
// keep that aspect, consecutive points lie far apart along the layer and every point location walks across many
// triangles. Sorting (point, index) pairs rather than indices into the points keeps the sort cache-friendly.
// The order only affects speed: the Delaunay flips break cocircular ties by CGAL's symbolic perturbation.
std::vector<std::pair<Point, int>> insertion_order(const std::vector<Point2>& pts) {
  std::vector<std::pair<Point, int>> out(pts.size());
  if (pts.empty()) return out;
  auto [xlo, xhi] = std::minmax_element(pts.begin(), pts.end(), [](const Point2& a, const Point2& b) { return a.x < b.x; });
  auto [ylo, yhi] = std::minmax_element(pts.begin(), pts.end(), [](const Point2& a, const Point2& b) { return a.y < b.y; });
  const bool along_x = xhi->x - xlo->x >= yhi->y - ylo->y;
  const double lo = along_x ? xlo->x : ylo->y, length = along_x ? xhi->x - xlo->x : yhi->y - ylo->y;
  const double width = along_x ? yhi->y - ylo->y : xhi->x - xlo->x;
  const std::size_t k = width > 0 ? std::clamp<double>(std::floor(length / width), 1.0, pts.size()) : 1;
  auto slab = [&](const Point2& p) {
    return k == 1 ? 0 : std::min(k - 1, static_cast<std::size_t>(((along_x ? p.x : p.y) - lo) / length * k));
  };
  std::vector<std::size_t> start(k + 1, 0);  // slab j: out[start[j], start[j + 1])
  for (const Point2& p : pts) ++start[slab(p) + 1];
  for (std::size_t j = 0; j < k; ++j) start[j + 1] += start[j];
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < pts.size(); ++i) out[next[slab(pts[i])]++] = {to_cgal(pts[i]), static_cast<int>(i)};
  using Traits = CGAL::Spatial_sort_traits_adapter_2<K, CGAL::First_of_pair_property_map<std::pair<Point, int>>>;
  for (std::size_t j = 0; j < k; ++j) CGAL::spatial_sort(out.begin() + start[j], out.begin() + start[j + 1], Traits());
  return out;
}

// Backstops for a domain that skipped nonobtuse.validate (which names problems with more context): predicates on
// non-finite coordinates are undefined, and a constraint from a vertex to itself corrupts the triangulation.
void require_finite_and_proper(const Domain2& domain) {
  auto finite = [](double x, double y) { return std::isfinite(x) && std::isfinite(y); };
  for (std::size_t i = 0; i < domain.points.size(); ++i)
    if (!finite(domain.points[i].x, domain.points[i].y))
      throw InvalidInput("point " + std::to_string(i) + " has a coordinate that is not finite");
  for (std::size_t i = 0; i < domain.holes.size(); ++i)
    if (!finite(domain.holes[i].x, domain.holes[i].y))
      throw InvalidInput("hole " + std::to_string(i) + " has a coordinate that is not finite");
  for (std::size_t i = 0; i < domain.regions.size(); ++i)
    if (!finite(domain.regions[i].at.x, domain.regions[i].at.y) || !std::isfinite(domain.regions[i].attribute))
      throw InvalidInput("region " + std::to_string(i) + " has a coordinate or attribute that is not finite");
  for (std::size_t s = 0; s < domain.segments.size(); ++s)
    if (domain.segments[s][0] == domain.segments[s][1])
      throw InvalidInput("segment " + std::to_string(s) + " (" + std::to_string(domain.segments[s][0]) + ", " +
                         std::to_string(domain.segments[s][1]) + ") has zero length");
}

}  // namespace

std::vector<Vertex_handle> build(CDT& cdt, const Domain2& domain) {
  if (cdt.number_of_vertices() != 0) throw InternalError("cdt::build: the triangulation is not empty");
  require_finite_and_proper(domain);
  // The points go into a Delaunay triangulation over the same data structure, which is then swapped in:
  // Delaunay_triangulation_2 inserts without the constraint bookkeeping, and both break cocircular ties by the
  // same symbolic perturbation, so this is the CDT of the points without constraints.
  CGAL::Delaunay_triangulation_2<K, Tds> dt;
  std::vector<Vertex_handle> vh(domain.points.size());
  Face_handle hint;
  for (const auto& [p, i] : insertion_order(domain.points)) {
    std::size_t before = dt.number_of_vertices();
    vh[i] = dt.insert(p, hint);
    if (dt.number_of_vertices() == before)
      throw InvalidInput("duplicate points: point " + std::to_string(std::max(i, vh[i]->info())) + " equals point " +
                         std::to_string(std::min(i, vh[i]->info())) + " at " + describe(p));
    vh[i]->info() = i;
    hint = vh[i]->face();
  }
  static_cast<CGAL::Triangulation_2<K, Tds>&>(cdt).swap(dt);
  for (std::size_t s = 0; s < domain.segments.size(); ++s) {
    auto [a, b] = domain.segments[s];
    try {
      cdt.insert_constraint(vh.at(a), vh.at(b));
    } catch (const CDT::Intersection_of_constraints_exception&) {
      throw InvalidInput("segment " + std::to_string(s) + " (" + std::to_string(a) + ", " + std::to_string(b) +
                         ") crosses another segment away from their endpoints");
    }
  }
  if (domain.convex_hull_boundary) insert_hull_constraints(cdt);
  mark_domain(cdt, domain);
  return vh;
}

void mark_domain(CDT& cdt, const Domain2& domain) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = FaceInfo{};
  if (cdt.dimension() < 2) return;  // collinear points: no face, nothing inside
  // Fill from `stack` across unconstrained edges; set(face) marks each face reached.
  auto fill = [&](std::vector<Face_handle> stack, auto&& reached, auto&& set) {
    while (!stack.empty()) {
      Face_handle f = stack.back();
      stack.pop_back();
      if (reached(f)) continue;
      set(f);
      for (int i = 0; i < 3; ++i)
        if (!cdt.is_constrained(Edge(f, i)) && !reached(f->neighbor(i))) stack.push_back(f->neighbor(i));
    }
  };
  // Exterior: component -2; holes: component -3. As in Triangle's hole carving, only these are walked and every
  // other face is in the domain, marked in container order (sequential memory; a flood fill over a million domain
  // faces was most of this function's time).
  std::vector<Face_handle> outside;
  auto inf_faces = cdt.incident_faces(cdt.infinite_vertex()), done = inf_faces;
  if (inf_faces != nullptr) do outside.push_back(inf_faces); while (++inf_faces != done);
  auto marked = [](Face_handle f) { return f->info().component != -1; };
  fill(outside, marked, [](Face_handle f) { f->info().component = -2; });
  for (const auto& h : domain.holes) {
    Face_handle f = cdt.locate(to_cgal(h));
    if (f == nullptr || cdt.is_infinite(f)) continue;
    fill({f}, marked, [](Face_handle g) { g->info().component = -3; });
  }
  if (domain.regions.empty()) {  // one class of domain faces: component 0, region attribute 0
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
      if (f->info().component == -1) f->info() = FaceInfo{true, 0};
    return;
  }
  // Regions: domain components 0, 1, ... by flood fill, each with the attribute of a region seed inside it.
  int next = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info().component != -1) continue;
    int c = next++;
    fill({f}, marked, [c](Face_handle g) {
      g->info().component = c;
      g->info().in_domain = true;
    });
  }
  std::vector<double> attribute(next, 0.0);
  for (const auto& r : domain.regions) {
    Face_handle f = cdt.locate(to_cgal(r.at));
    if (f != nullptr && f->info().in_domain) attribute[f->info().component] = r.attribute;
  }
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info().in_domain) f->info().region = attribute[f->info().component];
}

Mesh2 to_mesh(const CDT& cdt) {
  Mesh2 mesh;
  int n = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) n = std::max(n, v->info() + 1);
  mesh.points.resize(n);
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    if (v->info() < 0) throw InternalError("cdt::to_mesh: a vertex has no index");
    mesh.points[v->info()] = from_cgal(v->point());
  }
  mesh.triangles.reserve(cdt.number_of_faces());
  mesh.triangle_region.reserve(cdt.number_of_faces());
  // Constrained edges bordering the domain, from the domain faces beside them (twice for an interface).
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->info().in_domain) continue;
    mesh.triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
    mesh.triangle_region.push_back(f->info().region);
    for (int i = 0; i < 3; ++i)
      if (f->is_constrained(i)) {
        int a = f->vertex(CDT::cw(i))->info(), b = f->vertex(CDT::ccw(i))->info();
        mesh.segments.push_back({std::min(a, b), std::max(a, b)});
      }
  }
  std::sort(mesh.segments.begin(), mesh.segments.end());
  mesh.segments.erase(std::unique(mesh.segments.begin(), mesh.segments.end()), mesh.segments.end());
  return mesh;
}

}  // namespace nonobtuse::cdt

namespace nonobtuse {

Mesh2 triangulate(const Domain2& domain) {
  cdt::CDT t;
  cdt::build(t, domain);
  Mesh2 mesh = cdt::to_mesh(t);
  if (mesh.triangles.empty())
    throw InvalidInput("the domain contains no triangle (are all points collinear, or is everything a hole?)");
  return mesh;
}

}  // namespace nonobtuse
