// 3D interior quality: Delaunay refinement of the interior of a mesh with a Gabriel boundary, the triangulation kept
// between insertions, the boundary split where circumcenters encroach it (see refine_interior in quality3d.h).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <queue>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>

#include "nonobtuse/quality3d.h"
#include "quality3d_boundary.h"
#include "quality3d_cells.h"
#include "quality3d_rows.h"
#include "quality3d_shape.h"
#include "quality3d_spheres.h"

namespace nonobtuse {
namespace {

using gabriel3d::from_cgal;
using gabriel3d::P3;
using gabriel3d::to_cgal;
using quality3d::BoundarySplitter;
using quality3d::canonical_tet;
using quality3d::check_input;
using quality3d::tet_shape;
using quality3d::tet_quality;
using quality3d::TetQuality;
using quality3d::TetShape;
using quality3d::SphereIndex;
using quality3d::Cell;
using quality3d::corners;
using quality3d::DT;
using quality3d::flood_labels;
using quality3d::label_cells;
using quality3d::Vertex;

class InteriorRefiner {
 public:
  InteriorRefiner(const InteriorMesh& mesh, const InteriorBounds& bounds)
      : mesh_(mesh), bounds_(bounds), faces_(mesh.faces), segments_(mesh.segments) {
    pts_.reserve(mesh.points.size());
    for (const auto& p : mesh.points) pts_.push_back(to_cgal(p));
    for (const Triangle& f : mesh.faces)
      if (CGAL::collinear(pts_[f[0]], pts_[f[1]], pts_[f[2]]))
        throw InvalidInput("a face has collinear corners " + std::to_string(f[0]) + ", " + std::to_string(f[1]) +
                           ", " + std::to_string(f[2]) + ": no diametral sphere");
    for (const Segment& s : mesh.segments)
      if (pts_[s[0]] == pts_[s[1]]) throw InvalidInput("a segment has coincident ends " + std::to_string(s[0]));
    if (!mesh.face_facets.empty())
      splitter_ = std::make_unique<BoundarySplitter>(mesh.points, mesh.faces, mesh.face_facets, mesh.segments,
                                                     bounds.min_length, bounds.max_boundary_points,
                                                     bounds.sharp_dihedral_degrees, bounds.small_apex_degrees,
                                                     bounds.volume_sharp_degrees);
    spheres_ = std::make_unique<SphereIndex>(pts_, faces_, segments_);
    for (const auto& e : mesh.left_alone) left_alone_.insert(quality3d::element(e));
  }

  // Builds the Delaunay tetrahedralization and labels its cells; false when a subfacet or subsegment is not in it.
  bool build() {
    std::vector<std::pair<P3, int>> input;
    for (std::size_t i = 0; i < pts_.size(); ++i) input.emplace_back(pts_[i], static_cast<int>(i));
    dt_.insert(input.begin(), input.end());
    vertex_.assign(pts_.size(), Vertex());
    for (auto v = dt_.finite_vertices_begin(); v != dt_.finite_vertices_end(); ++v) vertex_[v->info()] = v;
    if (std::count(vertex_.begin(), vertex_.end(), Vertex()))
      throw InvalidInput("two points are equal: the tetrahedralization has fewer vertices");
    if (!conforming()) return false;
    label_cells(dt_, mesh_.tets, mesh_.tet_labels, faces_);
    return true;
  }

  InteriorRefinement run() {
    InteriorRefinement out;
    for (const Point3& p : mesh_.insert) out.placed += place(to_cgal(p), Cell());
    started_ = std::chrono::steady_clock::now();
    out.status = "converged";
    for (;;) {
      if (!refine_cells()) {
        out.status = "budget_exhausted";
        break;
      }
      if (!splitter_) break;
      const std::size_t mark = pts_.size();
      InteriorRefinement certified;  // the state before this step: returned if the step fails
      std::vector<Blocked> blocked;
      collect(certified, &blocked);
      const bool gabriel = split_boundary(std::move(blocked));
      if (splitter_->points().size() == mark) {  // nothing split: the cells left stay blocked
        if (out_of_time()) out.status = "budget_exhausted";
        break;
      }
      ++out.boundary_rounds;
      const Regions before = regions();
      insert_boundary_points(mark);
      if (!gabriel || !extract_boundary() || !relabel(before)) {
        conforming_ = false;
        InteriorRefinement split;
        collect(split);
        certified.status = gabriel ? "not_conforming" : "boundary_stopped";
        certified.step_centers = step_centers_;
        certified.step_elements.assign(step_.begin(), step_.end());
        certified.certified_points = static_cast<long long>(mark);
        certified.points.swap(split.points);  // the step's boundary points after the certified ones
        std::tie(certified.split_faces, certified.split_face_facets, certified.split_segments) =
            std::tie(split.faces, split.face_facets, split.segments);
        std::tie(certified.boundary_rounds, certified.boundary_points, certified.refused_splits) =
            std::make_tuple(out.boundary_rounds, split.boundary_points, split.refused_splits);
        return certified;
      }
      spheres_ = std::make_unique<SphereIndex>(pts_, faces_, segments_);
    }
    collect(out);
    if (out.status == "converged" && out.blocked_rows.size() > out.small_angle_rows.size()) out.status = "blocked";
    return out;
  }

 private:
  struct Entry {
    double ratio;                     // radius-edge ratio (the queue's order: worst first)
    std::array<int, 4> key;           // sorted point indices: ties broken deterministically
    std::array<Vertex, 4> v;
    bool operator<(const Entry& o) const { return std::tie(ratio, key) < std::tie(o.ratio, o.key); }
  };

  // A cell over a bound whose circumcenter lies in the closed diametral sphere of a subfacet or subsegment and is
  // not left alone: split_boundary splits that boundary for it.
  struct Blocked {
    double ratio;
    std::array<int, 4> key;
    P3 center;
  };

  bool out_of_time() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count() > bounds_.time_limit;
  }

  // Is every subfacet a face and every subsegment an edge of dt_?
  bool conforming() const {
    Cell c;
    int i = 0, j = 0, k = 0;
    for (const Triangle& f : faces_)
      if (!dt_.is_facet(vertex_[f[0]], vertex_[f[1]], vertex_[f[2]], c, i, j, k)) return false;
    for (const Segment& s : segments_)
      if (!dt_.is_edge(vertex_[s[0]], vertex_[s[1]], c, i, j)) return false;
    return true;
  }

  // The circumsphere of c from its corners in index order: the rounding does not depend on the cell's history
  // (exact for a cell flat in floating point, see tet_shape).
  TetShape shape(Cell c) const {
    const std::array<int, 4> k = corners(c);
    return tet_shape(pts_[k[0]], pts_[k[1]], pts_[k[2]], pts_[k[3]]);
  }
  P3 circumcenter(Cell c) const { return shape(c).center; }

  // The corners in index order: the rounding does not depend on the cell's history (the order of a cell's
  // vertices follows the insertions, and the spatial sort of a bulk insertion is randomized).
  TetQuality measure(Cell c) const {
    const std::array<int, 4> k = corners(c);
    return tet_quality(pts_[k[0]], pts_[k[1]], pts_[k[2]], pts_[k[3]], bounds_.radius_edge,
                       bounds_.volume_bounds[c->info()]);
  }

  // The small-angle rule (BoundarySplitter::leaves_alone; as Triangle and TetGen leave what no insertion can fix
  // near small input angles). Also left alone: a cell whose four corners lie on one facet, flat but for the
  // rounding of the boundary points (joint.off: volumes near 1e-22 at edges near 1e-2); no interior point splits it.
  bool flat_on_facet(Cell c) const { return splitter_ && splitter_->on_one_facet(corners(c)); }
  bool left_alone(const TetQuality& q, int row) const {
    return splitter_ && std::isfinite(q.ratio) && row != SphereIndex::kNone &&
           splitter_->leaves_alone(row, faces_, segments_, q.over_volume ? 0.0 : q.shortest,  // 0: none shorter
                                   q.over_volume);
  }

  void push_if_bad(Cell c) {
    if (dt_.is_infinite(c) || c->info() < 0) return;
    const TetQuality q = measure(c);
    if (!q.over) return;
    queue_.push({std::isfinite(q.ratio) ? q.ratio : std::numeric_limits<double>::max(), corners(c),
                 {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}});
  }

  // Inserts the circumcenters of the cells over a bound, worst first, until none can be; false at max_points or
  // time_limit.
  bool refine_cells() {
    queue_ = {};  // every cell is queued next, once
    for (auto c = dt_.finite_cells_begin(); c != dt_.finite_cells_end(); ++c) push_if_bad(c);
    while (!queue_.empty()) {
      if (inserted_ >= bounds_.max_points || (inserted_ % 64 == 0 && out_of_time())) return false;
      Entry e = queue_.top();
      queue_.pop();
      Cell c;
      if (!dt_.is_cell(e.v[0], e.v[1], e.v[2], e.v[3], c)) continue;  // destroyed by an insertion since
      try_insert(c);
    }
    return true;
  }

  // Split rule. Termination (Shewchuk, Si's TetGen): a circumcenter is inserted only strictly outside every closed
  // diametral sphere, so the boundary is never changed here, and it is at distance r (the tet's circumradius) from
  // every vertex (the circumsphere is empty). A tet over the radius-edge bound R has r > R * (its shortest edge), so
  // with R >= 2 (Shewchuk's bound for tets whose circumcenters are inserted and whose encroaching centers go to the
  // boundary instead) the new point's nearest neighbour is farther than twice the shortest edge it was made for:
  // insertion radii grow along every chain of tets that trigger one another and cannot shrink below the boundary's
  // own spacing; a tet over the volume bound V has r >= (3V / 4 pi)^(1/3) (a tet lies in its circumsphere). So the
  // points inserted here are well spaced in a bounded domain, and finitely many; max_points and time_limit bound the
  // loop anyway. A center in a closed diametral sphere goes to split_boundary; outside the domain or on a vertex
  // (near small input angles, or rounding) nothing is inserted: the tet is blocked and handed back, as TetGen leaves
  // such tets and counts them.
  void try_insert(Cell c) {
    if (place(circumcenter(c), c)) ++inserted_;
  }

  // Inserts p when it is finite, strictly outside every closed diametral sphere, in a domain cell and on no vertex
  // (exact), labelling its cavity and queueing the bad cells in it; false otherwise.
  bool place(const P3& p, Cell hint) {
    if (!finite(p)) return false;
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
    vertex_.push_back(v);
    if (splitter_) splitter_->add_interior_point(p);
    std::vector<Cell> incident;
    dt_.incident_cells(v, std::back_inserter(incident));
    // the cavity is in one region (it crosses no subfacet); an infinite cell (p on the hull) is outside it
    for (Cell n : incident) n->info() = dt_.is_infinite(n) ? -1 : label;
    for (Cell n : incident) push_if_bad(n);
    return true;
  }

  // Split rule at the boundary (Ruppert; Shewchuk, "Tetrahedral mesh generation by Delaunay refinement", 1998; Si's
  // TetGen). A circumcenter of a tet over a bound that lies in the closed diametral sphere of a subsegment splits that
  // subsegment at its midpoint; in that of a subfacet, the subfacet at its circumcenter z, unless z encroaches
  // subsegments of its facet, which are split instead. Then every subsegment and subfacet that any vertex encroaches
  // is split by the same rule, subsegments first, until the boundary is Gabriel again, and the next refine_cells
  // inserts the circumcenters that are now free. Termination (Shewchuk's insertion radii, for R >= 2 and input angles
  // of at least 90 degrees): a vertex's insertion radius (its distance to the nearest vertex when inserted) is at
  // least r > R l >= 2 l for a circumcenter made for a tet with shortest edge l, at least r / sqrt 2 for a subfacet
  // circumcenter that such a circumcenter encroached, and at least 1 / sqrt 2 of that for a subsegment midpoint that
  // the subfacet circumcenter encroached; around the chain circumcenter -> subfacet -> subsegment -> circumcenter the
  // factor is R / 2 >= 1, so radii never shrink below the local feature size and finitely many points fit.
  // Small input angles (the small-angle rule, left_alone): a tet is not split for when its split would lie at a
  // sharp feature and near it (a dihedral angle below 85 degrees or an apex below 60, where the chain's factor drops
  // below 1; near: the split point in the feature's protecting region, SharpFeatures), or, over the radius-edge bound
  // alone, would be shorter than the tet's shortest edge l. The second clause never fires where the argument above
  // holds (the split's radius is at least r / sqrt 2 > sqrt 2 l, or r / 2 > l for the subsegments a subfacet
  // circumcenter encroaches), so it only stops chains that would shrink. The distance clause (a sketch): the region
  // holds the balls around the sharp subsegments and apexes as large as the boundary's spacing rho there and the
  // diametral spheres of the subsegments and subfacets at the features, fixed for the pass; a split made outside it
  // encroaches nothing at a feature and lies at least about rho from it, where the facets meeting at the angle theta
  // are at least about rho sin theta apart: that distance bounds the split's insertion radius from below as the
  // local feature size does above, so the chains of splits made for tets stay above min(rho sin theta, lfs) / 2 and
  // finitely many points fit; a tet over the volume bound V makes splits of radius >= (3V / 4 pi)^(1/3) / 2 (its
  // circumcenter lies in the closed diametral sphere, of radius s, of what is split, whose corners are vertices
  // outside its empty circumsphere, so its circumradius r <= 2 s). So for such a tet only the features where the
  // cascade its split starts need not end count as sharp: below 60 degrees, dihedral or apex (volume_sharp_degrees;
  // from the boundary as input, the volume bound is met at the 63-degree dihedrals of example.poly). What stays
  // unbounded are the cascades restore_gabriel runs between features at small angles that such a split reaches; they
  // stop at min_length and max_boundary_points (refused, counted, the step handed back), and time_limit bounds every
  // step. The tets left alone are counted (small_angle_rows), as Triangle's terminator and
  // TetGen's -q leave them.
  // `blocked`: the cells over a bound whose circumcenters lie in a closed diametral sphere and are not left alone
  // (collect finds them).
  bool split_boundary(std::vector<Blocked> blocked) {
    std::sort(blocked.begin(), blocked.end(), [](const Blocked& x, const Blocked& y) {
      return std::tie(y.ratio, x.key) < std::tie(x.ratio, y.key);  // worst first
    });
    if (bounds_.max_step_centers > 0 && blocked.size() > static_cast<std::size_t>(bounds_.max_step_centers))
      blocked.resize(static_cast<std::size_t>(bounds_.max_step_centers));
    step_.clear();
    step_centers_ = static_cast<long long>(blocked.size());
    // Bounded steps (after a cascade nothing finished: refine_quality3d's retries) get 64 points per center: the
    // steps that succeed there add one or two (cad_ramp_5deg.off, schonhardt.off), a cascade thousands.
    splitter_->limit_step(bounds_.max_step_centers > 0 ? 64 * static_cast<long long>(blocked.size()) : -1);
    for (const Blocked& b : blocked) {
      if (out_of_time()) return false;
      const int row = spheres_->find(b.center);  // the spheres as the step began
      step_.insert(element_of(row));
      if (row < 0) {
        const Segment& s = segments_[-1 - row];
        if (splitter_->is_subsegment(s[0], s[1])) splitter_->split_subsegment(s[0], s[1]);
        continue;
      }
      const auto [a, p, q] = faces_[row];
      const int f = splitter_->common_facet(a, p, q);
      // still a Delaunay face of its facet when no point (of an earlier split of this step) encroaches it
      if (f >= 0 && !splitter_->encroached(a, p, q)) splitter_->split_subfacet(f, a, p, q);
    }
    return splitter_->restore_gabriel([&] { return out_of_time(); });
  }

  static bool finite(const P3& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

  // The splitter's new points (from index mark on) into dt_, their cells unlabelled.
  void insert_boundary_points(std::size_t mark) {
    Cell hint;
    for (std::size_t i = mark; i < splitter_->points().size(); ++i) {
      const P3& p = splitter_->points()[i];
      pts_.push_back(p);
      Vertex v = dt_.insert(p, hint);
      v->info() = static_cast<int>(i);
      vertex_.push_back(v);
      std::vector<Cell> incident;  // infinite ones too: a point on the hull makes infinite cells, unlabelled
      dt_.incident_cells(v, std::back_inserter(incident));
      for (Cell n : incident) n->info() = -1;
      hint = v->cell();
    }
  }

  // The subfacets as faces of dt_: the facets' triangulations, with their edges flipped where dt_ chose the other
  // diagonal of nearly cocircular points (BoundarySplitter::follow). False unless each is a face and every
  // subsegment an edge of dt_.
  bool extract_boundary() {
    Cell c;
    int i = 0, j = 0, k = 0;
    // follow asks about a face again after each flip in its facet and once more at the end; dt_ does not change
    // meanwhile, so each answer is kept (is_facet walks the cells around a vertex; measured on anchor.off's
    // refine_quality3d: is_facet 9.5% -> 7.1% of the samples).
    std::unordered_map<std::array<int, 3>, bool, gabriel3d::CheckMemo::Hash> known;
    auto is_face = [&](int a, int b, int d) {
      std::array<int, 3> key{a, b, d};
      std::sort(key.begin(), key.end());
      auto [it, fresh] = known.try_emplace(key, false);
      if (fresh) it->second = dt_.is_facet(vertex_[a], vertex_[b], vertex_[d], c, i, j, k);
      return it->second;
    };
    if (splitter_->follow(is_face) > 0) return false;
    std::vector<Triangle> faces;
    std::vector<int> facets;
    splitter_->subfacets(faces, facets);
    std::vector<std::pair<Cell, int>> sides;
    for (const Triangle& t : faces) {
      dt_.is_facet(vertex_[t[0]], vertex_[t[1]], vertex_[t[2]], c, i, j, k);
      sides.emplace_back(c, 6 - i - j - k);
    }
    std::vector<Segment> segments = splitter_->subsegments();
    for (const Segment& s : segments)
      if (!dt_.is_edge(vertex_[s[0]], vertex_[s[1]], c, i, j)) return false;
    faces_ = std::move(faces);
    face_facets_ = std::move(facets);
    face_sides_ = std::move(sides);
    segments_ = std::move(segments);
    return true;
  }

  // The labelled cells before a boundary step: each one's centroid and label, and each label's volume.
  struct Regions {
    std::vector<std::pair<P3, int>> seeds;
    std::vector<double> volumes;
  };
  Regions regions() const {
    Regions r{{}, std::vector<double>(bounds_.volume_bounds.size(), 0.0)};
    for (auto c = dt_.finite_cells_begin(); c != dt_.finite_cells_end(); ++c) {
      if (c->info() < 0) continue;
      const P3 &a = c->vertex(0)->point(), &b = c->vertex(1)->point(), &d = c->vertex(2)->point(),
               &e = c->vertex(3)->point();
      r.seeds.emplace_back(CGAL::centroid(a, b, d, e), c->info());
      r.volumes[c->info()] += CGAL::volume(a, b, d, e);
    }
    return r;
  }

  // Labels the cells the boundary points made: a flood fill from the cells kept, then, for a region left with less
  // volume than before (all cells of a part of it were remade), from the cells that hold its old cells' centroids
  // (inside the region, which the boundary points do not change). False when a region's volume still differs (by
  // more than rounding). Then orients each subfacet away from a domain cell behind it.
  bool relabel(const Regions& before) {
    std::vector<Cell> stack;
    for (auto c = dt_.finite_cells_begin(); c != dt_.finite_cells_end(); ++c)
      if (c->info() >= 0) stack.push_back(c);
    flood_labels(dt_, faces_, std::move(stack));
    auto short_of = [&](const Regions& now, int label) {
      return now.volumes[label] < before.volumes[label] * (1 - 1e-9);
    };
    Regions now = regions();
    for (const auto& [at, label] : before.seeds) {
      if (!short_of(now, label)) continue;
      Cell c = dt_.locate(at);
      if (dt_.is_infinite(c) || c->info() >= 0) continue;
      c->info() = label;
      flood_labels(dt_, faces_, {c});
      now = regions();
    }
    for (std::size_t label = 0; label < before.volumes.size(); ++label)
      if (short_of(now, static_cast<int>(label)) || now.volumes[label] > before.volumes[label] * (1 + 1e-9))
        return false;
    for (std::size_t f = 0; f < faces_.size(); ++f) {
      Cell cell = face_sides_[f].first;
      int index = face_sides_[f].second;
      if (cell->info() < 0) {  // the domain cell is the one across
        const Cell across = cell->neighbor(index);
        index = across->index(cell);
        cell = across;
      }
      Triangle& t = faces_[f];
      if (CGAL::orientation(pts_[t[0]], pts_[t[1]], pts_[t[2]], cell->vertex(index)->point()) == CGAL::POSITIVE)
        std::swap(t[1], t[2]);
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());  // one row, whatever the history
    }
    std::vector<std::size_t> order(faces_.size());  // and one order
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return faces_[x] < faces_[y]; });
    std::vector<Triangle> faces;
    std::vector<int> facets;
    for (std::size_t row : order) faces.push_back(faces_[row]), facets.push_back(face_facets_[row]);
    faces_ = std::move(faces);
    face_facets_ = std::move(facets);
    face_sides_.clear();
    return true;
  }

  // The state as a result; with `blocked`, also the cells split_boundary starts from (one pass over the cells for
  // both: they are taken from the same state, before the step).
  void collect(InteriorRefinement& out, std::vector<Blocked>* blocked = nullptr) const {
    for (const P3& p : pts_) out.points.push_back(from_cgal(p));
    std::vector<std::pair<std::array<int, 4>, Cell>> cells;  // the cells' order follows their history: sorted
    for (auto c = dt_.finite_cells_begin(); c != dt_.finite_cells_end(); ++c)
      if (c->info() >= 0)
        cells.emplace_back(canonical_tet({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(),
                                          c->vertex(3)->info()}),
                           c);
    std::sort(cells.begin(), cells.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& [t, c] : cells) {
      const TetQuality q = measure(c);
      if (q.over) {
        const P3 center = circumcenter(c);
        const bool flat = flat_on_facet(c);
        const int row = flat || !finite(center) ? SphereIndex::kNone : spheres_->find(center);
        const bool alone =
            left_alone(q, row) || (row != SphereIndex::kNone && left_alone_.count(element_of(row)) > 0);
        if (flat || alone) out.small_angle_rows.push_back(static_cast<int>(out.tets.size()));
        if (blocked && row != SphereIndex::kNone && !alone)
          blocked->push_back(
              {std::isfinite(q.ratio) ? q.ratio : std::numeric_limits<double>::max(), corners(c), center});
        out.blocked_rows.push_back(static_cast<int>(out.tets.size()));
        out.blocked_centers.push_back(from_cgal(center));
      }
      out.tets.push_back(t);
      out.tet_labels.push_back(c->info());
    }
    out.inserted = inserted_;
    out.certified_points = static_cast<long long>(pts_.size());
    out.faces = faces_;
    out.segments = segments_;
    out.face_facets = mesh_.face_facets;
    if (!splitter_) return;
    out.boundary_points = splitter_->added;
    out.refused_splits = splitter_->refused;
    if (face_facets_.empty() && conforming_) return;  // no boundary step yet: the input's faces and facet ids
    std::vector<int> facets = face_facets_;
    if (!conforming_) {  // the facets' triangulations: the boundary for a repair to make Delaunay
      splitter_->subfacets(out.faces, facets);
      out.segments = splitter_->subsegments();
    }
    out.face_facets.clear();
    for (int f : facets) out.face_facets.push_back(splitter_->facet_id(f));
  }

  const InteriorMesh& mesh_;
  const InteriorBounds& bounds_;
  std::vector<P3> pts_;
  std::vector<Triangle> faces_;     // the subfacets (the input's, then those of dt_ after each boundary step)
  std::vector<int> face_facets_;    // their facets (indices into the splitter's), after a boundary step
  std::vector<std::pair<Cell, int>> face_sides_;  // a cell of dt_ with each subfacet as its face, and its index
  std::vector<Segment> segments_;   // the subsegments
  std::unique_ptr<BoundarySplitter> splitter_;  // none without face_facets: the boundary is fixed
  std::unique_ptr<SphereIndex> spheres_;
  DT dt_;
  std::vector<Vertex> vertex_;
  std::priority_queue<Entry> queue_;
  // The subfacet or subsegment at a SphereIndex row, as a boundary element (quality3d::element).
  std::array<int, 3> element_of(int row) const {
    if (row >= 0) return quality3d::element(faces_[static_cast<std::size_t>(row)]);
    const Segment& s = segments_[static_cast<std::size_t>(-1 - row)];
    return quality3d::element({s[0], s[1], -1});
  }
  std::set<std::array<int, 3>> left_alone_;  // InteriorMesh::left_alone
  std::set<std::array<int, 3>> step_;        // what the last boundary step split for
  long long step_centers_ = 0;               // and for how many circumcenters
  long long inserted_ = 0;
  bool conforming_ = true;  // false after a boundary step whose subfacets are not all faces of dt_
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
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
    out.faces = mesh.faces;
    out.face_facets = mesh.face_facets;
    out.segments = mesh.segments;
    out.certified_points = static_cast<long long>(mesh.points.size());
    out.status = "not_conforming";
    return out;
  }
  return refiner.run();
}

}  // namespace nonobtuse
