// The Delaunay tetrahedralization of all points, restricted to the PLC's interior.
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <numeric>
#include <unordered_map>

#include "gabriel3d_plc.h"

namespace nonobtuse::gabriel3d {
namespace {

using Vb3 = CGAL::Triangulation_vertex_base_with_info_3<int, K>;
using Cb3 = CGAL::Triangulation_cell_base_with_info_3<int, K, CGAL::Delaunay_triangulation_cell_base_3<K>>;
using Tds3 = CGAL::Triangulation_data_structure_3<Vb3, Cb3>;
using DT3 = CGAL::Delaunay_triangulation_3<K, Tds3>;

using Corners = std::array<int, 3>;  // sorted point indices

// Hash maps keyed by corners: looked up for every face of every cell, where std::map's tree walks were about a
// tenth of refine_gabriel on fandisk (perf). Only find/emplace: iteration order is never used.
struct CornersHash {
  std::size_t operator()(const Corners& k) const {
    std::uint64_t h = static_cast<std::uint32_t>(k[0]);
    h = h * 0x9E3779B97F4A7C15ull + static_cast<std::uint32_t>(k[1]);
    h = h * 0x9E3779B97F4A7C15ull + static_cast<std::uint32_t>(k[2]);
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};
template <class V>
using CornersMap = std::unordered_map<Corners, V, CornersHash>;

Corners corners(int a, int b, int c) {
  Corners k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

// Where the faces covering the facets come from: every subfacet of a facet that is a Delaunay face (the usual case:
// a subfacet with an empty open diametral sphere is Delaunay unless points lie on that sphere), or, for a facet with
// a subfacet missing from the Delaunay tetrahedralization (cospherical points, e.g. a cube's square faces), every
// Delaunay face with its corners on the facet and its centroid inside the facet's domain.
struct FacetCover {
  CornersMap<int> subfacets;  // subfacet -> facet index
  std::vector<bool> by_centroid;     // per facet
};

FacetCover facet_cover(const PlcState& s, const DT3& dt, const std::vector<DT3::Vertex_handle>& vertex) {
  FacetCover cover;
  cover.by_centroid.assign(s.facets.size(), false);
  for (std::size_t f = 0; f < s.facets.size(); ++f) {
    const FacetCDT& cdt = s.facets[f]->cdt;
    for (auto fh = cdt.finite_faces_begin(); fh != cdt.finite_faces_end(); ++fh) {
      if (!fh->info().in_domain) continue;
      int a = fh->vertex(0)->info(), b = fh->vertex(1)->info(), c = fh->vertex(2)->info();
      cover.subfacets.emplace(corners(a, b, c), static_cast<int>(f));
      DT3::Cell_handle cell;
      int i = 0, j = 0, k = 0;
      if (!dt.is_facet(vertex[a], vertex[b], vertex[c], cell, i, j, k)) cover.by_centroid[f] = true;
    }
  }
  return cover;
}

// The facet (index) a Delaunay face covers, or -1.
int facet_under(const PlcState& s, const FacetCover& cover, const Corners& k) {
  auto it = cover.subfacets.find(k);
  if (it != cover.subfacets.end()) return it->second;
  for (int f : s.point_facets[k[0]])
    if (cover.by_centroid[f] && triangle_on_facet(s, f, k[0], k[1], k[2])) return f;
  return -1;
}

// The facet covered by centroid all four corners of a finite cell lie on, if none of its faces is a subfacet; else -1.
int flat_on_facet(const PlcState& s, const FacetCover& cover, DT3::Cell_handle c) {
  int v[4];
  for (int i = 0; i < 4; ++i) v[i] = c->vertex(i)->info();
  for (int f : s.point_facets[v[0]]) {
    bool all = cover.by_centroid[f];
    for (int i = 1; i < 4 && all; ++i) {
      const auto& on = s.point_facets[v[i]];
      all = std::find(on.begin(), on.end(), f) != on.end();
    }
    if (!all) continue;
    for (int i = 0; i < 4; ++i)
      if (cover.subfacets.count(corners(v[(i + 1) % 4], v[(i + 2) % 4], v[(i + 3) % 4]))) return -1;
    return f;
  }
  return -1;
}

// Sorts tets and boundary faces by their corners: the cell order of a Delaunay tetrahedralization depends on the
// (randomized) insertion order, and the output and the repair order must not.
void canonical_order(Restricted& out) {
  std::vector<std::size_t> t(out.tets.size()), f(out.boundary_faces.size());
  std::iota(t.begin(), t.end(), 0);
  std::iota(f.begin(), f.end(), 0);
  std::sort(t.begin(), t.end(), [&](auto i, auto j) { return out.tets[i] < out.tets[j]; });
  std::sort(f.begin(), f.end(), [&](auto i, auto j) { return out.boundary_faces[i] < out.boundary_faces[j]; });
  Restricted sorted;
  for (auto i : t) {
    sorted.tets.push_back(out.tets[i]);
    sorted.tet_regions.push_back(out.tet_regions[i]);
  }
  for (auto i : f) {
    sorted.boundary_faces.push_back(out.boundary_faces[i]);
    sorted.face_markers.push_back(out.face_markers[i]);
    sorted.face_facets.push_back(out.face_facets[i]);
  }
  out = std::move(sorted);
}

// Without region seeds every inside component is a region of its own: attribute 1, 2, ... in the order of the
// components' smallest cells (sorted corners), so that the numbers do not depend on the cell order.
template <class Inside>
void number_regions(const DT3& dt, const Inside& inside, std::vector<double>& attribute) {
  std::vector<std::pair<std::array<int, 4>, int>> smallest;  // (smallest cell, component)
  std::map<int, std::array<int, 4>> first;
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
    if (!inside(c)) continue;
    std::array<int, 4> k{c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()};
    std::sort(k.begin(), k.end());
    auto [it, fresh] = first.emplace(c->info(), k);
    if (!fresh) it->second = std::min(it->second, k);
  }
  for (const auto& [component, k] : first) smallest.emplace_back(k, component);
  std::sort(smallest.begin(), smallest.end());
  for (std::size_t rank = 0; rank < smallest.size(); ++rank) attribute[smallest[rank].second] = rank + 1.0;
}

}  // namespace

Restricted restrict_delaunay(const PlcState& s, const PLC3& plc) {
  std::vector<std::pair<P3, int>> input;
  input.reserve(s.points.size());
  for (std::size_t i = 0; i < s.points.size(); ++i) input.emplace_back(s.points[i], static_cast<int>(i));
  DT3 dt(input.begin(), input.end());
  Restricted out;
  if (dt.dimension() < 3) return out;
  std::vector<DT3::Vertex_handle> vertex(s.points.size());
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) vertex[v->info()] = v;
  const FacetCover cover = facet_cover(s, dt, vertex);
  // Cells with all four corners on one facet covered by centroid are flat up to the rounding of Steiner points
  // (or non-planar input): they belong to the facet, not to the volume. Their info is -2 - facet; they are never entered nor output, and
  // their faces towards ordinary cells cover the facet. Exception: a cell with a subfacet as a face is ordinary,
  // so that the certified subfacets seal the facet from that side.
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) c->info() = -1;
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
    int f = flat_on_facet(s, cover, c);
    if (f >= 0) c->info() = -2 - f;
  }
  auto flat = [](DT3::Cell_handle c) { return c->info() <= -2; };
  // Components of cells connected across faces that lie on no facet. Outside: the component of the infinite
  // cells and those of hole seeds; every other component is inside (TetGen's convention for enclosed regions).
  // facet_under is cached, unless no facet is covered by centroid: it is then one lookup in cover.subfacets, and
  // filling the cache (a node per face) was most of the hash-map time.
  const bool by_centroid =
      std::find(cover.by_centroid.begin(), cover.by_centroid.end(), true) != cover.by_centroid.end();
  CornersMap<int> on_facet;  // Delaunay face -> facet index or -1
  auto facet_of = [&](DT3::Cell_handle c, int i) {
    if (flat(c->neighbor(i))) return -2 - c->neighbor(i)->info();
    if (dt.is_infinite(c, i)) return -1;
    int v[3];
    for (int j = 0, m = 0; j < 4; ++j)
      if (j != i) v[m++] = c->vertex(j)->info();
    Corners k = corners(v[0], v[1], v[2]);
    if (!by_centroid) return facet_under(s, cover, k);
    auto it = on_facet.find(k);
    if (it == on_facet.end()) it = on_facet.emplace(k, facet_under(s, cover, k)).first;
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
        if (n->info() == -1 && facet_of(c, i) < 0) {  // -1: neither visited nor flat
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
  for (const auto& h : plc.holes)
    if (auto c = dt.locate(to_cgal(h)); !flat(c)) outside[c->info()] = true;
  auto inside = [&](DT3::Cell_handle c) { return !flat(c) && !outside[c->info()]; };
  std::vector<double> attribute(components, 0.0);
  for (const auto& r : plc.regions)
    if (auto c = dt.locate(P3(r[0], r[1], r[2])); !flat(c)) attribute[c->info()] = r[3];
  if (plc.regions.empty()) number_regions(dt, inside, attribute);
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
    if (!inside(c)) continue;
    out.tets.push_back({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
    out.tet_regions.push_back(attribute[c->info()]);
    // Boundary faces, each once: seen from the inside cell (or the first of two inside cells), oriented outward.
    for (int i = 0; i < 4; ++i) {
      auto n = c->neighbor(i);
      int f = facet_of(c, i);
      if (f < 0) continue;
      if (inside(n) && n->vertex(n->index(c))->info() < c->vertex(i)->info()) continue;
      int a = c->vertex(DT3::vertex_triple_index(i, 0))->info();
      int b = c->vertex(DT3::vertex_triple_index(i, 1))->info();
      int d = c->vertex(DT3::vertex_triple_index(i, 2))->info();
      if (CGAL::orientation(s.points[a], s.points[b], s.points[d], c->vertex(i)->point()) == CGAL::POSITIVE)
        std::swap(b, d);
      out.boundary_faces.push_back({a, b, d});
      out.face_markers.push_back(s.facets[f]->id);
      out.face_facets.push_back(f);
    }
  }
  canonical_order(out);
  return out;
}

}  // namespace nonobtuse::gabriel3d
