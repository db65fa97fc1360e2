// The Delaunay tetrahedralization of all points, restricted to the PLC's interior.
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <array>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <limits>
#include <memory>
#include <mutex>
#include <numeric>
#include <system_error>
#include <thread>
#include <tuple>
#include <utility>

#include "gabriel3d_plc.h"
#include "points_delaunay.h"
#include "quality3d_rows.h"

namespace nonobtuse::gabriel3d {
namespace {

// Per cell: its component (or -2 - facet for a flat cell) and, per face, the facet it covers (-1: none; kUnknown:
// not yet known). Vectors on the cells instead of hash maps keyed by corners: the lookups for every face of every
// cell were about a quarter of restrict_delaunay on fandisk (perf), most of it hashing and node allocation.
constexpr int kUnknown = -3;
struct CellInfo {
  int component = -1;
  std::array<int, 4> facet{kUnknown, kUnknown, kUnknown, kUnknown};
};

using Vb3 = CGAL::Triangulation_vertex_base_with_info_3<int, K>;
using Cb3 = CGAL::Triangulation_cell_base_with_info_3<CellInfo, K, CGAL::Delaunay_triangulation_cell_base_3<K>>;
using Tds3 = CGAL::Triangulation_data_structure_3<Vb3, Cb3>;
using DT3 = CGAL::Delaunay_triangulation_3<K, Tds3>;

using Corners = std::array<int, 3>;  // sorted point indices

Corners corners(int a, int b, int c) {
  Corners k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

// Records facet f on face i of cell c and on the same face seen from its neighbor, unless already known.
void set_face_facet(DT3::Cell_handle c, int i, int f) {
  if (c->info().facet[i] == kUnknown) c->info().facet[i] = f;
  auto n = c->neighbor(i);
  int j = n->index(c);
  if (n->info().facet[j] == kUnknown) n->info().facet[j] = f;
}

// Where the faces covering the facets come from: every subfacet of a facet that is a Delaunay face (the usual case:
// a subfacet with an empty open diametral sphere is Delaunay unless points lie on that sphere) is marked on its two
// cells (the first facet listing it wins); a facet with a subfacet missing from the Delaunay tetrahedralization
// (cospherical points, e.g. a cube's square faces) is covered by centroid: every Delaunay face with its corners on
// the facet and its centroid inside the facet's domain. Returns that flag per facet. One pass over the faces of the
// cells, each looked up among the subfacets filed under its smallest corner (a handful), instead of collecting the
// cells around every point (CGAL's incident_cells was most of this function's time).
std::vector<bool> mark_subfacets(const PlcState& s, const DT3& dt) {
  struct Subfacet {
    int b, c, facet;  // the two larger corners
    bool found;
  };
  // The subfacets by smallest corner, in facet order within a corner (compressed rows: first[a] .. first[a + 1]).
  std::vector<int> first(s.points.size() + 1, 0);
  std::vector<Corners> keys;
  std::vector<int> facet_of_key;
  for (std::size_t f = 0; f < s.facets.size(); ++f) {
    const FacetCDT& cdt = s.facets[f]->cdt;
    for (auto fh = cdt.finite_faces_begin(); fh != cdt.finite_faces_end(); ++fh) {
      if (!fh->info().in_domain) continue;
      keys.push_back(corners(fh->vertex(0)->info(), fh->vertex(1)->info(), fh->vertex(2)->info()));
      facet_of_key.push_back(static_cast<int>(f));
      ++first[keys.back()[0] + 1];
    }
  }
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<Subfacet> by_corner(keys.size());
  std::vector<int> next(first.begin(), first.end() - 1);
  for (std::size_t k = 0; k < keys.size(); ++k)
    by_corner[next[keys[k][0]]++] = {keys[k][1], keys[k][2], facet_of_key[k], false};
  // Each face once, from the cell of smaller address of its two (infinite cells included, for the hull's faces);
  // the neighbor is not dereferenced, and each cell's corners are read once.
  const auto infinite = dt.infinite_vertex();
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) {
    int v[4];
    for (int i = 0; i < 4; ++i) v[i] = c->vertex(i) == infinite ? -1 : c->vertex(i)->info();
    for (int i = 0; i < 4; ++i) {
      if (&*c->neighbor(i) < &*c) continue;
      const int a = v[(i + 1) % 4], b = v[(i + 2) % 4], d = v[(i + 3) % 4];
      if (a < 0 || b < 0 || d < 0) continue;
      const Corners k = corners(a, b, d);
      for (int e = first[k[0]]; e < first[k[0] + 1]; ++e) {
        Subfacet& sub = by_corner[e];
        if (sub.b != k[1] || sub.c != k[2]) continue;
        if (c->info().facet[i] == kUnknown) set_face_facet(c, i, sub.facet);
        sub.found = true;
      }
    }
  }
  std::vector<bool> by_centroid(s.facets.size(), false);
  for (const Subfacet& sub : by_corner)
    if (!sub.found) by_centroid[sub.facet] = true;
  return by_centroid;
}

// The facet covered by centroid a Delaunay face (not a subfacet) lies on, or -1.
int facet_by_centroid(const PlcState& s, const std::vector<bool>& by_centroid, const Corners& k) {
  for (int f : s.point_facets[k[0]])
    if (by_centroid[f] && triangle_on_facet(s, f, k[0], k[1], k[2])) return f;
  return -1;
}

// Per point: does it lie on a facet covered by centroid? A face or cell with a corner that does not lies on no such
// facet, which the flags tell without the facet lookups (on part.off, most of the faces the flood fill crosses).
std::vector<char> on_by_centroid_facet(const PlcState& s, const std::vector<bool>& by_centroid) {
  std::vector<char> on(s.points.size(), 0);
  for (std::size_t p = 0; p < s.points.size(); ++p)
    for (int f : s.point_facets[p]) on[p] = on[p] || by_centroid[f];
  return on;
}

// The facet covered by centroid all four corners of a finite cell lie on, if none of its faces is a subfacet; else -1.
int flat_on_facet(const PlcState& s, const std::vector<bool>& by_centroid, const std::vector<char>& on,
                  DT3::Cell_handle c) {
  int v[4];
  for (int i = 0; i < 4; ++i) v[i] = c->vertex(i)->info();
  if (!on[v[0]] || !on[v[1]] || !on[v[2]] || !on[v[3]]) return -1;
  for (int f : s.point_facets[v[0]]) {
    bool all = by_centroid[f];
    for (int i = 1; i < 4 && all; ++i) {
      const auto& on = s.point_facets[v[i]];
      all = std::find(on.begin(), on.end(), f) != on.end();
    }
    if (!all) continue;
    for (int i = 0; i < 4; ++i)
      if (c->info().facet[i] >= 0) return -1;
    return f;
  }
  return -1;
}

// Sorts rows by corners(row), an array of point indices below `points`: a counting sort by the first corner, then
// each first corner's handful of rows by the rest (one comparison sort of all rows cost three times as much).
template <class Row, class Corners>
void sort_by_corners(std::vector<Row>& rows, std::size_t points, const Corners& corners) {
  std::vector<std::size_t> start(points + 1, 0);
  for (const Row& row : rows) ++start[corners(row)[0] + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<Row> sorted(rows.size());
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for (Row& row : rows) sorted[next[corners(row)[0]]++] = std::move(row);
  for (std::size_t v = 0; v < points; ++v)
    std::sort(sorted.begin() + static_cast<std::ptrdiff_t>(start[v]),
              sorted.begin() + static_cast<std::ptrdiff_t>(start[v + 1]),
              [&](const Row& x, const Row& y) { return corners(x) < corners(y); });
  rows = std::move(sorted);
}

// Sorts tets and boundary faces by their corners: the cell order of a Delaunay tetrahedralization depends on the
// insertion history, and the output must not. The rows are canonical (a tet's least even permutation, a face from
// its smallest corner: the corner order within a cell depends on the history too) and no two are equal, so any sort
// gives this order; rows with their attributes are sorted in place (sorting indices and gathering was a sixth of
// this function's own time on fandisk).
void canonical_order(Restricted& out, std::size_t points) {
  std::vector<std::pair<Tetrahedron, double>> tets(out.tets.size());
  for (std::size_t i = 0; i < tets.size(); ++i) tets[i] = {out.tets[i], out.tet_regions[i]};
  sort_by_corners(tets, points, [](const auto& row) -> const Tetrahedron& { return row.first; });
  for (std::size_t i = 0; i < tets.size(); ++i) std::tie(out.tets[i], out.tet_regions[i]) = tets[i];
  struct Face {
    Triangle corners;
    int marker, facet;
  };
  std::vector<Face> faces(out.boundary_faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i)
    faces[i] = {out.boundary_faces[i], out.face_markers[i], out.face_facets[i]};
  sort_by_corners(faces, points, [](const Face& row) -> const Triangle& { return row.corners; });
  for (std::size_t i = 0; i < faces.size(); ++i) {
    out.boundary_faces[i] = faces[i].corners;
    out.face_markers[i] = faces[i].marker;
    out.face_facets[i] = faces[i].facet;
  }
}

// Without region seeds every inside component is a region of its own: attribute 1, 2, ... in the order of the
// components' smallest cells (sorted corners), so that the numbers do not depend on the cell order. From the
// inside cells as output (tets[i] of component[i]): a pass over those rows, not over the triangulation's cells.
void number_regions(const std::vector<Tetrahedron>& tets, const std::vector<int>& component,
                    std::vector<double>& attribute) {
  std::vector<std::pair<std::array<int, 4>, int>> smallest;  // (smallest cell, component)
  // Per component (numbered 0 .. attribute.size() - 1): its smallest inside cell so far; unset: none.
  constexpr int kUnset = std::numeric_limits<int>::max();
  std::vector<std::array<int, 4>> first(attribute.size(), {kUnset, kUnset, kUnset, kUnset});
  for (std::size_t t = 0; t < tets.size(); ++t) {
    std::array<int, 4> k = tets[t];
    std::sort(k.begin(), k.end());
    std::array<int, 4>& best = first[component[t]];
    best = std::min(best, k);
  }
  for (std::size_t component = 0; component < first.size(); ++component)
    if (first[component][0] != kUnset) smallest.emplace_back(first[component], static_cast<int>(component));
  std::sort(smallest.begin(), smallest.end());
  for (std::size_t rank = 0; rank < smallest.size(); ++rank) attribute[smallest[rank].second] = rank + 1.0;
}

}  // namespace

// restrict_delaunay on the Delaunay tetrahedralization dt of s.points, whose cells carry CellInfo{}.
Restricted restrict_triangulation(const PlcState& s, const PLC3& plc, DT3& dt) {
  Restricted out;
  if (dt.dimension() < 3) return out;  // (every cell was constructed with CellInfo{})
  const std::vector<bool> by_centroid = mark_subfacets(s, dt);
  // Cells with all four corners on one facet covered by centroid are flat up to the rounding of Steiner points
  // (or non-planar input): they belong to the facet, not to the volume. Their component is -2 - facet; they are
  // never entered nor output, and their faces towards ordinary cells cover the facet. Exception: a cell with a
  // subfacet as a face is ordinary, so that the certified subfacets seal the facet from that side.
  const bool any_by_centroid = std::find(by_centroid.begin(), by_centroid.end(), true) != by_centroid.end();
  const std::vector<char> on = any_by_centroid ? on_by_centroid_facet(s, by_centroid) : std::vector<char>{};
  if (any_by_centroid)
    for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
      if (int f = flat_on_facet(s, by_centroid, on, c); f >= 0) c->info().component = -2 - f;
  auto flat = [](DT3::Cell_handle c) { return c->info().component <= -2; };
  // Components of cells connected across faces that lie on no facet. Outside: the component of the infinite
  // cells and those of hole seeds; every other component is inside (TetGen's convention for enclosed regions).
  // A face's facet is found once (marked subfacet, else by centroid) and recorded on both of its cells.
  // A face's recorded facet comes first: a face next to a flat cell has none (the flat cell's faces carry no
  // subfacet, and the faces of flat cells are never recorded).
  auto facet_of = [&](DT3::Cell_handle c, int i) {
    if (int f = c->info().facet[i]; f != kUnknown) return f;
    if (flat(c->neighbor(i))) return -2 - c->neighbor(i)->info().component;
    if (dt.is_infinite(c, i)) return -1;
    int f = -1;
    if (any_by_centroid) {
      int v[3];
      for (int j = 0, m = 0; j < 4; ++j)
        if (j != i) v[m++] = c->vertex(j)->info();
      if (on[v[0]] && on[v[1]] && on[v[2]]) f = facet_by_centroid(s, by_centroid, corners(v[0], v[1], v[2]));
    }
    set_face_facet(c, i, f);
    return f;
  };
  int components = 0;
  std::vector<DT3::Cell_handle> stack;
  auto fill = [&](DT3::Cell_handle seed) {
    if (seed->info().component != -1) return;
    int id = components++;
    seed->info().component = id;
    stack.assign(1, seed);
    while (!stack.empty()) {
      auto c = stack.back();
      stack.pop_back();
      for (int i = 0; i < 4; ++i) {
        auto n = c->neighbor(i);
        if (n->info().component == -1 && facet_of(c, i) < 0) {  // -1: neither visited nor flat
          n->info().component = id;
          stack.push_back(n);
        }
      }
    }
  };
  fill(dt.infinite_vertex()->cell());
  std::vector<bool> outside(1, true);
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) {
    if (c->info().component != -1) continue;
    fill(c);
    outside.push_back(dt.is_infinite(c));
  }
  for (const auto& h : plc.holes)
    if (auto c = dt.locate(to_cgal(h)); !flat(c)) outside[c->info().component] = true;
  auto inside = [&](DT3::Cell_handle c) { return !flat(c) && !outside[c->info().component]; };
  std::vector<double> attribute(components, 0.0);
  for (const auto& r : plc.regions)
    if (auto c = dt.locate(P3(r[0], r[1], r[2])); !flat(c)) attribute[c->info().component] = r[3];
  std::vector<int> tet_component;  // per output tet; its attribute once every component is numbered
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
    if (!inside(c)) continue;
    out.tets.push_back(quality3d::canonical_tet(
        {c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()}));
    tet_component.push_back(c->info().component);
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
      Triangle row{a, b, d};
      std::rotate(row.begin(), std::min_element(row.begin(), row.end()), row.end());  // one row, whatever the history
      out.boundary_faces.push_back(row);
      out.face_markers.push_back(s.facets[f]->id);
      out.face_facets.push_back(f);
    }
  }
  if (plc.regions.empty()) number_regions(out.tets, tet_component, attribute);
  out.tet_regions.reserve(out.tets.size());
  for (int component : tet_component) out.tet_regions.push_back(attribute[component]);
  canonical_order(out, s.points.size());
  return out;
}

Restricted restrict_delaunay(const PlcState& s, const PLC3& plc) { return DelaunayRounds().restrict(s, plc); }

// insert_while's inserting thread takes batches of at least this many points (CGAL sorts each spatially), and what
// is left once work() ended.
constexpr std::size_t kInsertBatch = 1024;

struct DelaunayRounds::Kept {
  DT3 dt;
  // Between feed() and the inserting thread of insert_while: the points handed over and not yet taken, whether the
  // thread runs, and how many points of the list were handed (a prefix, like the tetrahedralization's vertices).
  std::mutex mutex;
  std::condition_variable ready;
  std::vector<std::pair<P3, int>> queue;
  bool open = false;
  std::size_t fed = 0;
};

DelaunayRounds::DelaunayRounds() : kept_(std::make_unique<Kept>()) {}
DelaunayRounds::~DelaunayRounds() = default;

void DelaunayRounds::insert_while(bool parallel, const std::function<void()>& work) {
  Kept& k = *kept_;
  k.fed = k.dt.number_of_vertices();
  k.open = parallel;
  std::exception_ptr inserting;
  std::thread inserter;
  if (parallel) try {
      inserter = std::thread([&k, &inserting] {
        try {
          std::vector<std::pair<P3, int>> batch;
          for (bool open = true; open;) {
            {
              std::unique_lock<std::mutex> lock(k.mutex);
              k.ready.wait(lock, [&k] { return k.queue.size() >= kInsertBatch || !k.open; });
              batch.swap(k.queue);
              open = k.open;
            }
            k.dt.insert(batch.begin(), batch.end());
            batch.clear();
          }
        } catch (...) {
          inserting = std::current_exception();
        }
      });
    } catch (const std::system_error&) {
      k.open = false;
    }
  std::exception_ptr working;
  try {
    work();
  } catch (...) {
    working = std::current_exception();
  }
  if (inserter.joinable()) {
    {
      std::lock_guard<std::mutex> lock(k.mutex);
      k.open = false;
    }
    k.ready.notify_one();
    inserter.join();
  }
  if (working) std::rethrow_exception(working);
  if (inserting) std::rethrow_exception(inserting);
}

void DelaunayRounds::feed(const std::vector<P3>& points) {
  Kept& k = *kept_;
  bool full = false;
  {
    std::lock_guard<std::mutex> lock(k.mutex);
    if (!k.open) return;
    for (; k.fed < points.size(); ++k.fed) k.queue.emplace_back(points[k.fed], static_cast<int>(k.fed));
    full = k.queue.size() >= kInsertBatch;
  }
  if (full) k.ready.notify_one();
}

Restricted DelaunayRounds::restrict(const PlcState& s, const PLC3& plc) {
  DT3& dt = kept_->dt;
  if (s.points.size() < dt.number_of_vertices())
    throw InternalError("DelaunayRounds: the PLC state has fewer points than the kept triangulation");
  std::vector<std::pair<P3, int>> added;
  added.reserve(s.points.size() - dt.number_of_vertices());
  for (std::size_t i = dt.number_of_vertices(); i < s.points.size(); ++i)
    added.emplace_back(s.points[i], static_cast<int>(i));
  dt.insert(added.begin(), added.end());  // (spatially sorted by CGAL)
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) c->info() = CellInfo{};
  return restrict_triangulation(s, plc, dt);
}

std::vector<Key> DelaunayRounds::missing_edges(const std::vector<Key>& edges) const {
  const DT3& dt = kept_->dt;
  std::vector<DT3::Vertex_handle> at(dt.number_of_vertices());
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) at[v->info()] = v;
  std::vector<Key> out;
  DT3::Cell_handle c;
  int i = 0, j = 0;
  for (const Key& e : edges)
    if (!dt.is_edge(at[e.first], at[e.second], c, i, j)) out.push_back(e);
  return out;
}

Restricted restrict_delaunay(const PlcState& s, const PLC3& plc, PointsDelaunay&& built) {
  if (built.number_of_vertices() != s.points.size())
    throw InternalError("restrict_delaunay: the triangulation given is not of the PLC's points");
  struct Vertex {  // the point and its index; Vertex_base_with_info's constructor takes the point alone
    DT3::Vertex operator()(const PointsDelaunay::Vertex& v) const { return DT3::Vertex(v.point()); }
    void operator()(const PointsDelaunay::Vertex& from, DT3::Vertex& to) const { to.info() = from.info(); }
  };
  struct Cell {  // no data: restrict_triangulation sets every cell's info
    DT3::Cell operator()(const PointsDelaunay::Cell&) const { return DT3::Cell(); }
    void operator()(const PointsDelaunay::Cell&, DT3::Cell&) const {}
  };
  DT3 dt;
  dt.set_infinite_vertex(dt.tds().copy_tds(built.tds(), built.infinite_vertex(), Vertex(), Cell()));
  built.clear();  // its memory goes before the restriction's
  return restrict_triangulation(s, plc, dt);
}

}  // namespace nonobtuse::gabriel3d
