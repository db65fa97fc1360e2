#include "cdt.h"

#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <numeric>
#include <sstream>
#include <string>

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

}  // namespace

std::vector<Vertex_handle> build(CDT& cdt, const Domain2& domain) {
  const auto& pts = domain.points;
  std::vector<Point> cpts;
  cpts.reserve(pts.size());
  for (const auto& p : pts) cpts.push_back(to_cgal(p));
  std::vector<std::size_t> order(pts.size());
  std::iota(order.begin(), order.end(), 0);
  using Pmap = CGAL::Pointer_property_map<Point>::type;
  using Traits = CGAL::Spatial_sort_traits_adapter_2<K, Pmap>;
  CGAL::spatial_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(cpts)));

  std::vector<Vertex_handle> vh(pts.size());
  Face_handle hint;
  for (std::size_t i : order) {
    std::size_t before = cdt.number_of_vertices();
    vh[i] = cdt.insert(cpts[i], hint);
    if (cdt.number_of_vertices() == before)
      throw InvalidInput("duplicate points: point " + std::to_string(i) + " equals point " +
                         std::to_string(vh[i]->info()) + " at " + describe(cpts[i]));
    vh[i]->info() = static_cast<int>(i);
    hint = vh[i]->face();
  }
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
  // Exterior: component -2; holes: component -3; domain components: 0, 1, ...
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
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->info().in_domain) continue;
    mesh.triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
    mesh.triangle_region.push_back(f->info().region);
  }
  for (auto e = cdt.constrained_edges_begin(); e != cdt.constrained_edges_end(); ++e) {
    Face_handle f = e->first, g = f->neighbor(e->second);
    if (!f->info().in_domain && !g->info().in_domain) continue;
    int a = f->vertex(CDT::cw(e->second))->info(), b = f->vertex(CDT::ccw(e->second))->info();
    mesh.segments.push_back({std::min(a, b), std::max(a, b)});
  }
  std::sort(mesh.segments.begin(), mesh.segments.end());
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
