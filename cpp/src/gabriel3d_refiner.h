// Internal: the Refiner of one Gabriel pass (gabriel3d_refine.cpp), driven by refine_once
// (gabriel3d_refine_once.cpp).
#pragma once
#include <chrono>
#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "gabriel3d_collar.h"
#include "gabriel3d_encroached.h"
#include "gabriel3d_mirror.h"
#include "gabriel3d_needle_pairs.h"
#include "gabriel3d_protect.h"
#include "gabriel3d_refine.h"
#include "gabriel3d_stations.h"

namespace nonobtuse::gabriel3d {

// Why the refinement stopped early, if it did.
struct Stop {
  RefineStatus status;
  std::string reason;
};

struct SubfacetRef {
  int facet, a, b, c;  // a < b < c (canonical) so that the rounded circumcenter does not depend on the order
  bool operator<(const SubfacetRef& o) const {
    return std::tie(facet, a, b, c) < std::tie(o.facet, o.a, o.b, o.c);
  }
};

inline SubfacetRef canonical(SubfacetRef r) {
  int v[3] = {r.a, r.b, r.c};
  std::sort(v, v + 3);
  return {r.facet, v[0], v[1], v[2]};
}

// The order in which repair() splits encroached faces: a permutation of `faces` (rows of point indices) that
// depends on the set of faces alone, neither on the rows' order nor on the order of the corners within a row
// (both follow the cell order of the Delaunay tetrahedralization): ascending by a 64-bit mix of the sorted corners,
// ties by the corners. Scattered over the mesh rather than sorted by a corner, which kept neighbouring faces
// together (experiments/README.md, "repair order").
std::vector<std::size_t> scattered_order(const std::vector<Triangle>& faces);

class Refiner {
 public:
  // cascade_floor: stop (min_length_reached) once a split leaves a subsegment shorter (refine_once).
  Refiner(PlcState& s, const Refine3DOptions& o, bool ignore_frame_artifacts, const Protection* protection,
          bool mirror, const Stations* stations = nullptr, CascadeFloor cascade_floor = {})
      : s_(s), o_(o), ignore_frame_artifacts_(ignore_frame_artifacts), protection_(protection), stations_(stations),
        cascade_floor_(std::move(cascade_floor)),
        index_(s.points),
        encroached_subsegments_(s, index_), start_(std::chrono::steady_clock::now()), acute_(s.n_input, false),
        collared_(protection ? collared_segments(s) : std::vector<bool>{}),
        mirror_pairs_(mirror ? mirror_pairs(s, 90.0) : std::vector<MirrorPair>{}), needle_(needle_corners(s)) {
    if (stations)  // the feet of the stations (place_station) stand in for the mirror along grouped segments
      mirror_pairs_.erase(std::remove_if(mirror_pairs_.begin(), mirror_pairs_.end(),
                                         [&](const MirrorPair& p) { return stations->grouped(p.segment); }),
                          mirror_pairs_.end());
    std::vector<std::vector<int>> ends(s.n_input);
    for (const auto& seg : s.segments) ends[seg.a].push_back(seg.b), ends[seg.b].push_back(seg.a);
    for (int v = 0; v < s.n_input; ++v)
      for (std::size_t i = 0; i < ends[v].size() && !acute_[v]; ++i)
        for (std::size_t j = i + 1; j < ends[v].size() && !acute_[v]; ++j)
          acute_[v] = CGAL::angle(s.points[ends[v][i]], s.points[v], s.points[ends[v][j]]) == CGAL::ACUTE;
  }

  // Splits every input segment through a protected apex where it leaves the apex's ball.
  std::optional<Stop> place_protecting_points();
  // Places the stations of the input vertices where two segments of a group meet (gabriel3d_stations.h).
  std::optional<Stop> place_apex_stations();
  // Runs to convergence of the subfacets and subsegments, or to a stop.
  std::optional<Stop> run();
  // Every point inserted from now on is fed to `delaunay` (DelaunayRounds::feed; nullptr: none is).
  void feed(DelaunayRounds* delaunay) { delaunay_ = delaunay; }
  // Splits the encroached faces and subsegments of the restricted Delaunay mesh (which can differ from the
  // subfacets where points are cospherical). Sets *progress when a point was inserted.
  std::optional<Stop> repair(const Restricted& mesh, const std::vector<Key>& segments, const GabrielReport& report,
                             bool* progress);
  // Splits subsegments (at their split rule's point) whatever their diametral spheres hold: those the Delaunay
  // tetrahedralization lacks although no point lies strictly inside their spheres (refine_once). Sets *progress
  // when a point was inserted.
  std::optional<Stop> split_missing(const std::vector<Key>& subsegments, bool* progress) {
    for (const Key& sub : subsegments)
      if (auto stop = split(sub, true, progress)) return stop;
    return std::nullopt;
  }
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  // Without a finite time_limit (the default) the clock is not read: asked per subfacet scanned and per row
  // checked, it was 1.4% of refine_gabriel on part.off (perf).
  bool out_of_time() const { return std::isfinite(o_.time_limit) && seconds() > o_.time_limit; }
  // Work units (Refine3DOptions::max_work): counted by every exact encroachment query, and by add_work.
  long work() const { return work_; }
  void add_work(std::size_t units) { work_ += static_cast<long>(units); }
  long steiner_on_segments = 0, steiner_on_facets = 0, greedy_splits = 0;

 private:
  std::optional<Stop> budget_left() const;
  // The encroached subsegments in Key order, as a scan of every subsegment would list them (kept up to date by
  // inserted()). Charged one work unit per subsegment, the full scan it replaces, so that max_work stops where it
  // did.
  std::vector<Key> encroached_subsegments();
  std::vector<SubfacetRef> encroached_subfacets() const;
  bool encroached(int a, int b, int c) const {
    ++work_;
    return deepest_encroacher(s_.points, index_, a, b, c).vertex >= 0;
  }
  // A subfacet (a, b, c) of facet f encroached in 3D, not counting points of f that the facet's triangulation
  // sees outside the subfacet's circumcircle (exact 2D test in its frame). In exact arithmetic the two tests agree
  // for points in the facet's plane; they differ only through the rounding of the frame and of Steiner points
  // (near-cocircular points, e.g. a regular 10-gon, where splitting for them wasted hundreds of points). Points
  // of f inside the 2D circumcircle lie behind a subsegment and do count. The exact check of the final mesh is
  // authoritative either way; repair() fixes what it finds. memo: the face's last scan (gabriel3d_scan_memo.h).
  bool subfacet_encroached(int f, int a, int b, int c, ScanMemo* memo = nullptr) const {
    ++work_;
    // The test captures two pointers, so that its std::function stays in place: capturing the five variables by
    // reference put every subfacet scan's std::function on the heap (an allocation per subfacet per scan).
    struct Subfacet {
      const Facet& facet;
      int a, b, c;
    } sub{*s_.facets[f], a, b, c};
    auto artifact = [this, &sub](int t) {
      const auto& vertex = sub.facet.vertex;
      auto it = vertex.find(t);
      return ignore_frame_artifacts_ && it != vertex.end() &&
             CGAL::side_of_bounded_circle(vertex.at(sub.a)->point(), vertex.at(sub.b)->point(),
                                          vertex.at(sub.c)->point(), it->second->point()) != CGAL::ON_BOUNDED_SIDE;
    };
    return memo ? encroached_since_memo(s_.points, index_, a, b, c, *memo, artifact)
                : deepest_encroacher(s_.points, index_, a, b, c, nullptr, artifact).vertex >= 0;
  }
  // Splits `sub` if it still exists and (unless `always`) is still encroached by a vertex. `pending`: a point not
  // inserted (a refused circumcenter) that the greedy rule treats as one more encroacher.
  std::optional<Stop> split(const Key& sub, bool always, bool* inserted, const P3* pending = nullptr);
  // Splits subfacet f (a face of facet f.facet's triangulation, or only a triangle on it when !require_face).
  std::optional<Stop> split_subfacet(const SubfacetRef& f, bool require_face, bool* inserted);
  // The subsegments of facet f (of input segments that are constraints of its triangulation) whose diametral spheres
  // hold p strictly inside (exact), in Key order.
  std::vector<Key> facet_subsegments_holding(int f, const P3& p) const;
  std::optional<Stop> too_short(const P3& p, const P3& q) const;
  // A stop when p is closer than min_length to a point; *near (when given) is set to that point.
  std::optional<Stop> too_close(const P3& p, int* near = nullptr) const;
  // Point m was added; `split`: the subsegment it split, if any.
  void inserted(int m, const std::optional<Key>& split = std::nullopt);
  // Places the images of new point m on the facets mirrored to one of its own (gabriel3d_mirror.h) where they
  // verify; images are not mirrored again (one hop: a base point near two mirrored segments goes to both facets,
  // and their images do not come back). Images that are existing points, within min_length of one, or strictly
  // inside a protecting ball are not placed.
  void mirror(int m);
  // Places the images of point m, on input segment `segment` between points `around`, on the other segments of
  // its group (gabriel3d_stations.h); each image's rounding is chosen among nearby doubles so that, by exact
  // predicates, it and the station's points placed before it do not encroach each other's new subsegments.
  std::optional<Stop> place_station(int segment, int m, const std::vector<int>& around);
  // Places in facet f the point base + w (1 + 1/64), w the component of p - base orthogonal to input segment
  // `along` (through base) and to f's normal, if it lies strictly inside f's domain.
  std::optional<Stop> place_foot(int f, int p, int base, int along);
  // Places the partners (gabriel3d_needle_pairs.h) of point m, just split onto subsegment (a, b), on the other
  // segments of the needle corners its segment belongs to, and theirs on the corners beyond (breadth first, one
  // point per segment reached). Refused partners are skipped.
  void partner(int m, int a, int b);
  // With mirrored meshes: the radius of the protecting ball at input vertex v whose sphere holds point m (m within
  // twice that radius of v, exact; balls are far enough apart that no other ball's sphere point is), else 0.
  double sphere_of(int v, int m) const;
  // [e, x_s]: the piece of an input segment inside e's protecting ball (x_s where the segment leaves it).
  bool protected_piece(const Key& sub) const;

  PlcState& s_;
  const Refine3DOptions& o_;
  bool ignore_frame_artifacts_;
  const Protection* protection_;  // nullptr: no protecting balls
  const Stations* stations_;      // nullptr: no stations
  // Is a subsegment from a to b below the cascade floor (evaluated on first need, then kept in floor_)?
  bool below_floor(const P3& a, const P3& b);

  CascadeFloor cascade_floor_;
  std::optional<double> floor_;  // cascade_floor_.evaluate(), once called
  bool below_floor_ = false;     // a split left a subsegment shorter than the floor
  std::set<int> segment_sphere_points_;  // placed by place_protecting_points: where a segment leaves a ball
  std::set<int> arc_points_;             // placed on a ball's sphere by arc_split_point
  PointIndex index_;
  DelaunayRounds* delaunay_ = nullptr;
  EncroachedSubsegments encroached_subsegments_;
  std::chrono::steady_clock::time_point start_;
  long last_encroached_segments_ = 0, last_encroached_facets_ = 0;
  mutable long work_ = 0;  // counted in const queries: the count is the cost, not part of the state
  std::vector<bool> acute_;  // per input vertex: two input segments meet there at an acute angle
  std::vector<bool> collared_;  // per input segment: collared (gabriel3d_collar.h); empty without protection
  std::vector<MirrorPair> mirror_pairs_;  // below 90 degrees, as the collars; empty unless the mirrored strategy runs
  std::set<int> images_;                  // points placed by mirror()
  NeedleCorners needle_;  // the facet corners whose segments' points get partners
};

}  // namespace nonobtuse::gabriel3d
