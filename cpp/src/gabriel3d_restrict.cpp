// The Delaunay tetrahedralization of all points, restricted to the PLC's interior.
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <array>

#include "gabriel3d_plc.h"

namespace nonobtuse::gabriel3d {
namespace {

using Vb3 = CGAL::Triangulation_vertex_base_with_info_3<int, K>;
using Cb3 = CGAL::Triangulation_cell_base_with_info_3<int, K, CGAL::Delaunay_triangulation_cell_base_3<K>>;
using Tds3 = CGAL::Triangulation_data_structure_3<Vb3, Cb3>;
using DT3 = CGAL::Delaunay_triangulation_3<K, Tds3>;

// The input facet a Delaunay face lies on (its corners on the facet and its centroid in the facet's domain), or -1.
int facet_under(const PlcState& s, const DT3::Facet& face) {
  int v[3], k = 0;
  for (int i = 0; i < 4; ++i)
    if (i != face.second) v[k++] = face.first->vertex(i)->info();
  for (int f : s.point_facets[v[0]])
    if (triangle_on_facet(s, f, v[0], v[1], v[2])) return f;
  return -1;
}

}  // namespace

Restricted restrict_delaunay(const PlcState& s, const PLC3& plc) {
  std::vector<std::pair<P3, int>> input;
  input.reserve(s.points.size());
  for (std::size_t i = 0; i < s.points.size(); ++i) input.emplace_back(s.points[i], static_cast<int>(i));
  DT3 dt(input.begin(), input.end());
  Restricted out;
  if (dt.dimension() < 3) return out;
  // Components of cells connected across faces that lie on no facet. Outside: the component of the infinite
  // cells and those of hole seeds; every other component is inside (TetGen's convention for enclosed regions).
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) c->info() = -1;
  std::map<std::array<int, 3>, int> on_facet;  // sorted corners -> facet index or -1
  auto facet_of = [&](DT3::Cell_handle c, int i) {
    if (dt.is_infinite(c, i)) return -1;
    std::array<int, 3> k;
    for (int j = 0, m = 0; j < 4; ++j)
      if (j != i) k[m++] = c->vertex(j)->info();
    std::sort(k.begin(), k.end());
    auto it = on_facet.find(k);
    if (it == on_facet.end()) it = on_facet.emplace(k, facet_under(s, {c, i})).first;
    return it->second;
  };
  int components = 0;
  std::vector<DT3::Cell_handle> stack;
  auto fill = [&](DT3::Cell_handle seed) {
    if (seed->info() != -1) return;
    int id = components++;
    seed->info() = id;
    stack.assign(1, seed);
    while (!stack.empty()) {
      auto c = stack.back();
      stack.pop_back();
      for (int i = 0; i < 4; ++i) {
        auto n = c->neighbor(i);
        if (n->info() == -1 && facet_of(c, i) < 0) {
          n->info() = id;
          stack.push_back(n);
        }
      }
    }
  };
  fill(dt.infinite_vertex()->cell());
  std::vector<bool> outside(1, true);
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) {
    if (c->info() != -1) continue;
    fill(c);
    outside.push_back(dt.is_infinite(c));
  }
  for (const auto& h : plc.holes) outside[dt.locate(to_cgal(h))->info()] = true;
  std::vector<double> attribute(components, 0.0);
  for (const auto& r : plc.regions) attribute[dt.locate(P3(r[0], r[1], r[2]))->info()] = r[3];
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
    if (outside[c->info()]) continue;
    out.tets.push_back({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
    out.tet_regions.push_back(attribute[c->info()]);
    // Boundary faces, each once: seen from the inside cell (or the first of two inside cells), oriented outward.
    for (int i = 0; i < 4; ++i) {
      auto n = c->neighbor(i);
      int f = facet_of(c, i);
      if (f < 0) continue;
      if (!outside[n->info()] && n->vertex(n->index(c))->info() < c->vertex(i)->info()) continue;
      int a = c->vertex(DT3::vertex_triple_index(i, 0))->info();
      int b = c->vertex(DT3::vertex_triple_index(i, 1))->info();
      int d = c->vertex(DT3::vertex_triple_index(i, 2))->info();
      if (CGAL::orientation(s.points[a], s.points[b], s.points[d], c->vertex(i)->point()) == CGAL::POSITIVE)
        std::swap(b, d);
      out.boundary_faces.push_back({a, b, d});
      out.face_markers.push_back(s.facets[f]->id);
    }
  }
  return out;
}

}  // namespace nonobtuse::gabriel3d
