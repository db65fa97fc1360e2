// 3D interior quality: Delaunay refinement of the interior of a mesh with a fixed Gabriel boundary, the
// triangulation kept between insertions (see refine_interior in quality3d.h).
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <queue>
#include <string>
#include <tuple>

#include "gabriel3d_index.h"
#include "nonobtuse/quality3d.h"

namespace nonobtuse {
namespace {

using namespace gabriel3d;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<int, K>;
using Cb = CGAL::Triangulation_cell_base_with_info_3<int, K, CGAL::Delaunay_triangulation_cell_base_3<K>>;
using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb>;
using DT = CGAL::Delaunay_triangulation_3<K, Tds>;
using Cell = DT::Cell_handle;
using Vertex = DT::Vertex_handle;

// The closed diametral spheres of the subfacets and subsegments, found from a query point: the spheres' search
// balls (which contain them, see search_ball) are grouped by radius in power-of-two classes, each a kd-tree over
// the ball centers; a query asks each class for the centers within the class's largest radius of the point, and the
// exact predicate decides.
class SphereIndex {
 public:
  SphereIndex(const std::vector<P3>& pts, const std::vector<Triangle>& faces, const std::vector<Segment>& segments)
      : pts_(pts), faces_(faces), segments_(segments) {
    std::map<int, std::size_t> class_of;
    auto add = [&](const SearchBall& ball, int row) {
      if (ball.everything || !std::isfinite(ball.radius)) {
        always_.push_back(row);
        return;
      }
      int e = 0;
      std::frexp(ball.radius, &e);
      auto [it, fresh] = class_of.emplace(e, classes_.size());
      if (fresh) classes_.push_back({std::ldexp(1.0, e), {}, {}, nullptr});
      Class& c = classes_[it->second];
      c.centers.emplace_back(ball.center[0], ball.center[1], ball.center[2]);
      c.rows.push_back(row);
    };
    for (std::size_t f = 0; f < faces.size(); ++f)
      add(search_ball(pts[faces[f][0]], pts[faces[f][1]], pts[faces[f][2]]), static_cast<int>(f));
    for (std::size_t s = 0; s < segments.size(); ++s)
      add(search_ball(pts[segments[s][0]], pts[segments[s][1]]), -1 - static_cast<int>(s));
    for (Class& c : classes_) c.index = std::make_unique<PointIndex>(c.centers);
  }

  static constexpr int kNone = std::numeric_limits<int>::min();

  // The first subfacet (its row) or subsegment (-1 - its row) whose closed diametral sphere holds q, or kNone
  // (exact).
  int find(const P3& q) const {
    for (int row : always_)
      if (holds(row, q)) return row;
    for (const Class& c : classes_) {
      int found = kNone;
      SearchBall around{{q.x(), q.y(), q.z()}, c.radius, false};
      c.index->for_each_in(around, [&](int i) {
        if (found == kNone && holds(c.rows[i], q)) found = c.rows[i];
      });
      if (found != kNone) return found;
    }
    return kNone;
  }

  bool hits(const P3& q) const { return find(q) != kNone; }

  // The center and radius of the diametral sphere of row (floating point), and the unit direction from the center
  // towards `side` across the subfacet's plane (for a subsegment, perpendicular to it).
  std::tuple<P3, double, K::Vector_3> sphere_towards(int row, const P3& side) const {
    P3 center;
    K::Vector_3 up;
    if (row >= 0) {
      const Triangle& f = faces_[row];
      const P3 &a = pts_[f[0]], &b = pts_[f[1]], &c = pts_[f[2]];
      center = CGAL::circumcenter(a, b, c);
      up = CGAL::cross_product(b - a, c - a);
      if ((side - center) * up < 0) up = -up;
    } else {
      const Segment& g = segments_[-1 - row];
      const P3 &a = pts_[g[0]], &b = pts_[g[1]];
      center = CGAL::midpoint(a, b);
      const K::Vector_3 along = b - a, away = side - center;
      up = away - along * ((away * along) / (along * along));
    }
    const P3& corner = pts_[row >= 0 ? faces_[row][0] : segments_[-1 - row][0]];
    const double length = std::sqrt(up * up);
    return {center, std::sqrt(CGAL::squared_distance(center, corner)), length > 0 ? up / length : up};
  }

  // Is q strictly inside the diametral sphere of row? (exact)
  bool strictly_inside(int row, const P3& q) const {
    if (row >= 0) {
      const Triangle& f = faces_[row];
      return CGAL::side_of_bounded_sphere(pts_[f[0]], pts_[f[1]], pts_[f[2]], q) == CGAL::ON_BOUNDED_SIDE;
    }
    const Segment& g = segments_[-1 - row];
    return CGAL::side_of_bounded_sphere(pts_[g[0]], pts_[g[1]], q) == CGAL::ON_BOUNDED_SIDE;
  }

 private:
  struct Class {
    double radius;  // every search ball of the class has a smaller radius
    std::vector<P3> centers;
    std::vector<int> rows;  // face row, or -1 - segment row
    std::unique_ptr<PointIndex> index;
  };
  bool holds(int row, const P3& q) const {
    if (row >= 0) {
      const Triangle& f = faces_[row];
      return CGAL::side_of_bounded_sphere(pts_[f[0]], pts_[f[1]], pts_[f[2]], q) != CGAL::ON_UNBOUNDED_SIDE;
    }
    const Segment& s = segments_[-1 - row];
    return CGAL::side_of_bounded_sphere(pts_[s[0]], pts_[s[1]], q) != CGAL::ON_UNBOUNDED_SIDE;
  }
  const std::vector<P3>& pts_;
  const std::vector<Triangle>& faces_;
  const std::vector<Segment>& segments_;
  std::vector<Class> classes_;
  std::vector<int> always_;
};

std::array<int, 4> sorted_corners(std::array<int, 4> k) {
  std::sort(k.begin(), k.end());
  return k;
}

void check_input(const InteriorMesh& mesh, const InteriorBounds& bounds) {
  const auto n = static_cast<int>(mesh.points.size());
  auto in_range = [&](int v, const char* what, std::size_t row) {
    if (v < 0 || v >= n)
      throw InvalidInput(std::string(what) + " " + std::to_string(row) + " refers to point " + std::to_string(v) +
                         ", but there are " + std::to_string(n) + " points");
  };
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    for (int v : mesh.tets[t]) in_range(v, "tet", t);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    for (int v : mesh.faces[f]) in_range(v, "face", f);
  for (std::size_t s = 0; s < mesh.segments.size(); ++s)
    for (int v : mesh.segments[s]) in_range(v, "segment", s);
  std::vector<bool> on_boundary(mesh.points.size(), false);
  for (const Triangle& f : mesh.faces)
    for (int v : f) on_boundary[v] = true;
  for (const Segment& s : mesh.segments)
    for (int v : s) on_boundary[v] = true;
  for (std::size_t r = 0; r < mesh.remove.size(); ++r) {
    in_range(mesh.remove[r], "removed point", r);
    if (on_boundary[mesh.remove[r]])
      throw InvalidInput("removed point " + std::to_string(mesh.remove[r]) + " is a corner of a face or segment");
  }
  if (mesh.tet_labels.size() != mesh.tets.size())
    throw InvalidInput("tet_labels has " + std::to_string(mesh.tet_labels.size()) + " entries for " +
                       std::to_string(mesh.tets.size()) + " tets");
  for (std::size_t t = 0; t < mesh.tet_labels.size(); ++t)
    if (mesh.tet_labels[t] < 0 || static_cast<std::size_t>(mesh.tet_labels[t]) >= bounds.volume_bounds.size())
      throw InvalidInput("tet " + std::to_string(t) + " has label " + std::to_string(mesh.tet_labels[t]) +
                         ", but there are " + std::to_string(bounds.volume_bounds.size()) + " volume bounds");
}

class InteriorRefiner {
 public:
  InteriorRefiner(const InteriorMesh& mesh, const InteriorBounds& bounds) : mesh_(mesh), bounds_(bounds) {
    pts_.reserve(mesh.points.size());
    for (const auto& p : mesh.points) pts_.push_back(to_cgal(p));
    for (const Triangle& f : mesh.faces)
      if (CGAL::collinear(pts_[f[0]], pts_[f[1]], pts_[f[2]]))
        throw InvalidInput("a face has collinear corners " + std::to_string(f[0]) + ", " + std::to_string(f[1]) +
                           ", " + std::to_string(f[2]) + ": no diametral sphere");
    for (const Segment& s : mesh.segments)
      if (pts_[s[0]] == pts_[s[1]]) throw InvalidInput("a segment has coincident ends " + std::to_string(s[0]));
    spheres_ = std::make_unique<SphereIndex>(pts_, mesh.faces, mesh.segments);
  }

  // Builds the Delaunay tetrahedralization and labels its cells; false when a subfacet or subsegment is not in it.
  bool build() {
    kept_.assign(pts_.size(), true);
    for (int r : mesh_.remove) kept_[r] = false;
    std::vector<std::pair<P3, int>> input;
    for (std::size_t i = 0; i < pts_.size(); ++i)
      if (kept_[i]) input.emplace_back(pts_[i], static_cast<int>(i));
    dt_.insert(input.begin(), input.end());
    vertex_.assign(pts_.size(), Vertex());
    for (auto v = dt_.finite_vertices_begin(); v != dt_.finite_vertices_end(); ++v) vertex_[v->info()] = v;
    for (std::size_t i = 0; i < pts_.size(); ++i)
      if (kept_[i] && vertex_[i] == Vertex())
        throw InvalidInput("two points are equal: the tetrahedralization has fewer vertices");
    if (!conforming()) return false;
    label_cells();
    return true;
  }

  InteriorRefinement run() {
    InteriorRefinement out;
    for (const Point3& p : mesh_.insert) out.placed += place(to_cgal(p), Cell());
    queue_ = {};  // every cell is queued next, once
    for (auto c = dt_.finite_cells_begin(); c != dt_.finite_cells_end(); ++c) push_if_bad(c);
    const auto started = std::chrono::steady_clock::now();
    out.status = "converged";
    while (!queue_.empty()) {
      if (inserted_ >= bounds_.max_points ||
          (inserted_ % 64 == 0 && std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() >
                                      bounds_.time_limit)) {
        out.status = "budget_exhausted";
        break;
      }
      Entry e = queue_.top();
      queue_.pop();
      Cell c;
      if (!dt_.is_cell(e.v[0], e.v[1], e.v[2], e.v[3], c)) continue;  // destroyed by an insertion since
      try_insert(c);
    }
    collect(out);
    if (out.status == "converged" && !out.blocked_rows.empty()) out.status = "blocked";
    return out;
  }

 private:
  struct Entry {
    double ratio;                     // radius-edge ratio (the queue's order: worst first)
    std::array<int, 4> key;           // sorted point indices: ties broken deterministically
    std::array<Vertex, 4> v;
    bool operator<(const Entry& o) const { return std::tie(ratio, key) < std::tie(o.ratio, o.key); }
  };

  // Is every subfacet a face and every subsegment an edge of dt_?
  bool conforming() const {
    Cell c;
    int i = 0, j = 0, k = 0;
    for (const Triangle& f : mesh_.faces)
      if (!dt_.is_facet(vertex_[f[0]], vertex_[f[1]], vertex_[f[2]], c, i, j, k)) return false;
    for (const Segment& s : mesh_.segments)
      if (!dt_.is_edge(vertex_[s[0]], vertex_[s[1]], c, i, j)) return false;
    return true;
  }

  // Domain cells: those of the input tets, then by flood fill across faces that are not subfacets (a Delaunay
  // tetrahedralization with every subfacet as a face holds the same domain split differently where points are
  // cospherical).
  void label_cells() {
    std::map<std::array<int, 4>, int> label_of;
    std::map<int, int> removed_label;  // a removed point's star lies in one region (it is on no subfacet)
    for (std::size_t t = 0; t < mesh_.tets.size(); ++t) {
      label_of.emplace(sorted_corners(mesh_.tets[t]), mesh_.tet_labels[t]);
      for (int v : mesh_.tets[t])
        if (!kept_[v]) removed_label[v] = mesh_.tet_labels[t];
    }
    std::map<std::array<int, 3>, bool> subfacet;
    for (const Triangle& f : mesh_.faces) {
      std::array<int, 3> k = f;
      std::sort(k.begin(), k.end());
      subfacet[k] = true;
    }
    std::vector<Cell> stack;
    for (auto c = dt_.all_cells_begin(); c != dt_.all_cells_end(); ++c) {
      c->info() = -1;
      if (dt_.is_infinite(c)) continue;
      auto it = label_of.find(corners(c));
      if (it != label_of.end()) {
        c->info() = it->second;
        stack.push_back(c);
      }
    }
    for (auto [v, label] : removed_label) {  // the cell now holding a removed point is in its region
      Cell c = dt_.locate(pts_[v]);
      if (!dt_.is_infinite(c) && c->info() < 0) {
        c->info() = label;
        stack.push_back(c);
      }
    }
    while (!stack.empty()) {
      Cell c = stack.back();
      stack.pop_back();
      for (int i = 0; i < 4; ++i) {
        Cell n = c->neighbor(i);
        if (n->info() >= 0 || dt_.is_infinite(n)) continue;
        std::array<int, 3> k;
        for (int j = 0, m = 0; j < 4; ++j)
          if (j != i) k[m++] = c->vertex(j)->info();
        std::sort(k.begin(), k.end());
        if (subfacet.count(k)) continue;
        n->info() = c->info();
        stack.push_back(n);
      }
    }
  }

  static std::array<int, 4> corners(Cell c) {
    return sorted_corners({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
  }

  // Radius-edge ratio and whether the domain cell c is over a bound (floating point).
  std::pair<double, bool> measure(Cell c) const {
    const P3 &a = c->vertex(0)->point(), &b = c->vertex(1)->point(), &d = c->vertex(2)->point(),
             &e = c->vertex(3)->point();
    double shortest = std::numeric_limits<double>::infinity();
    const P3* v[4] = {&a, &b, &d, &e};
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) shortest = std::min(shortest, CGAL::squared_distance(*v[i], *v[j]));
    const double radius2 = CGAL::squared_radius(a, b, d, e);
    const double ratio = std::sqrt(radius2 / shortest);
    const double volume = CGAL::volume(a, b, d, e);
    const bool over = (bounds_.radius_edge > 0 && ratio > bounds_.radius_edge) ||
                      volume > bounds_.volume_bounds[c->info()] || !std::isfinite(ratio);
    return {ratio, over};
  }

  void push_if_bad(Cell c) {
    if (dt_.is_infinite(c) || c->info() < 0) return;
    auto [ratio, over] = measure(c);
    if (!over) return;
    queue_.push({std::isfinite(ratio) ? ratio : std::numeric_limits<double>::max(), corners(c),
                 {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}});
  }

  // Split rule. Termination (Shewchuk, Si's TetGen): a circumcenter is inserted only strictly outside every closed
  // diametral sphere, so the boundary is never changed here, and it is at distance r (the tet's circumradius) from
  // every vertex (the circumsphere is empty). A tet over the radius-edge bound R has r > R * (its shortest edge), so
  // with R >= 2 (Shewchuk's bound for tets whose circumcenters are inserted and whose encroaching centers go to the
  // boundary instead) the new point's nearest neighbour is farther than twice the shortest edge it was made for:
  // insertion radii grow along every chain of tets that trigger one another and cannot shrink below the boundary's
  // own spacing; a tet over the volume bound V has r >= (3V / 4 pi)^(1/3) (a tet lies in its circumsphere). So the
  // points inserted here are well spaced in a bounded domain, and finitely many; max_points and time_limit bound the
  // loop anyway. Near small input angles (a center in a closed diametral sphere, outside the domain or on a vertex)
  // nothing is inserted: the tet is blocked and handed back, as TetGen leaves such tets and counts them.
  void try_insert(Cell c) {
    if (place(dt_.dual(c), c)) ++inserted_;
  }

  // Inserts p when it is finite, strictly outside every closed diametral sphere, in a domain cell and on no vertex
  // (exact), labelling its cavity and queueing the bad cells in it; false otherwise.
  bool place(const P3& p, Cell hint) {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) return false;
    DT::Locate_type lt;
    int li = 0, lj = 0;
    Cell at = dt_.locate(p, lt, li, lj, hint);
    if (lt == DT::VERTEX || lt == DT::OUTSIDE_AFFINE_HULL || dt_.is_infinite(at) || at->info() < 0) return false;
    if (spheres_->hits(p)) return false;
    const int label = at->info();
    const int index = static_cast<int>(pts_.size());
    Vertex v = dt_.insert(p, lt, at, li, lj);
    v->info() = index;
    pts_.push_back(p);
    std::vector<Cell> incident;
    dt_.finite_incident_cells(v, std::back_inserter(incident));
    for (Cell n : incident) n->info() = label;  // the cavity is in one region: it crosses no subfacet
    for (Cell n : incident) push_if_bad(n);
    return true;
  }

  void collect(InteriorRefinement& out) const {
    std::vector<int> index(pts_.size(), -1);  // compacted past the removed points
    out.points.reserve(pts_.size());
    for (std::size_t i = 0; i < pts_.size(); ++i)
      if (i >= kept_.size() || kept_[i]) {  // inserted points come after the input's
        index[i] = static_cast<int>(out.points.size());
        out.points.push_back(from_cgal(pts_[i]));
      }
    for (auto c = dt_.finite_cells_begin(); c != dt_.finite_cells_end(); ++c) {
      if (c->info() < 0) continue;
      const int row = static_cast<int>(out.tets.size());
      out.tets.push_back({index[c->vertex(0)->info()], index[c->vertex(1)->info()], index[c->vertex(2)->info()],
                          index[c->vertex(3)->info()]});
      out.tet_labels.push_back(c->info());
      if (measure(c).second) {
        const P3 center = dt_.dual(c);
        out.blocked_rows.push_back(row);
        out.blocked_centers.push_back(from_cgal(center));
        out.stand_ins.push_back(stand_in(c, center));
      }
    }
    out.inserted = inserted_;
  }

  // Ruppert's and Shewchuk's rule for a circumcenter in a closed diametral sphere: split that subfacet or
  // subsegment, once. The caller's boundary repair splits what its points encroach until none does, so the point
  // that stands for the center is put high in the sphere, on the side of the tet: at height (1 - 2^-k) r above the
  // sphere's center for k = 4 down to 1, the first strictly inside the sphere and strictly inside a domain cell
  // (both exact). Once the subfacet is split at its circumcenter, the children's spheres have that point as a
  // corner's center distance away in the plane, so a point that high leaves them: one split, not a cascade down to
  // the center's distance from the plane. NaN when no such point is found (or the center is in no sphere).
  Point3 stand_in(Cell c, const P3& center) const {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (!std::isfinite(center.x()) || !std::isfinite(center.y()) || !std::isfinite(center.z())) return {nan, nan, nan};
    const int row = spheres_->find(center);
    if (row == SphereIndex::kNone) return {nan, nan, nan};
    const P3 side = CGAL::centroid(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(),
                                   c->vertex(3)->point());
    auto [sphere_center, radius, up] = spheres_->sphere_towards(row, side);
    for (int k = 4; k >= 1; --k) {
      const P3 q = sphere_center + up * (radius * (1.0 - std::ldexp(1.0, -k)));
      if (!spheres_->strictly_inside(row, q)) continue;
      DT::Locate_type lt;
      int li = 0, lj = 0;
      Cell at = dt_.locate(q, lt, li, lj, c);
      if (lt == DT::CELL && !dt_.is_infinite(at) && at->info() >= 0) return from_cgal(q);
    }
    return {nan, nan, nan};
  }

  const InteriorMesh& mesh_;
  const InteriorBounds& bounds_;
  std::vector<P3> pts_;
  std::unique_ptr<SphereIndex> spheres_;
  DT dt_;
  std::vector<Vertex> vertex_;
  std::vector<bool> kept_;  // per input point: false for those in InteriorMesh::remove
  std::priority_queue<Entry> queue_;
  long long inserted_ = 0;
};

}  // namespace

InteriorRefinement refine_interior(const InteriorMesh& mesh, const InteriorBounds& bounds) {
  check_input(mesh, bounds);
  InteriorRefiner refiner(mesh, bounds);
  if (!refiner.build()) {
    InteriorRefinement out;
    out.points = mesh.points;
    out.tets = mesh.tets;
    out.tet_labels = mesh.tet_labels;
    out.status = "not_conforming";
    return out;
  }
  return refiner.run();
}

}  // namespace nonobtuse
