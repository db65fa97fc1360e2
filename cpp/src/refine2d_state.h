// Internal: the state every 2D boundary-refinement strategy works on: the constrained Delaunay triangulation of the
// domain with its domain marks, the work queue of subsegment sides, the Steiner budget and the per-edge
// bookkeeping. Its data is private: strategies read the triangulation and change it only through split
// (split_point.cpp), the one operation that inserts a Steiner point.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <deque>
#include <unordered_map>
#include <vector>

#include "diametral_disk.h"
#include "refine2d_diagnosis.h"
#include "nonobtuse/refine2d.h"

namespace nonobtuse::refine2d {

// Scratch of the walks over faces on one lane (visibility.h): a walk has reached a face iff its info().visit[lane]
// equals the walk's stamp (cheaper than a set of face handles), and listed a vertex iff vertex_stamp[index] equals
// the list's stamp. Walks on one lane must not nest; walks on two lanes may run on two threads (the lower bound).
struct WalkLane {
  unsigned face_walks = 0;
  unsigned vertex_lists = 0;
  std::vector<unsigned> vertex_stamp;
};

class State {
 public:
  // Triangulates the domain (cdt::build), or takes over `prebuilt`'s triangulation when it holds one of this very
  // domain (cdt::same_domain; `prebuilt` is empty afterwards either way). Throws InvalidInput when the domain holds
  // no triangle.
  State(const Domain2& domain, long long budget, Triangulation2* prebuilt = nullptr);

  const CDT& cdt() const { return cdt_; }
  const Domain2& domain() const { return domain_; }
  int n_input() const { return n_input_; }
  long long budget() const { return budget_; }
  long long placed() const { return placed_; }  // Steiner points inserted on constraints so far
  bool budget_left() const { return placed_ < budget_; }
  // Every vertex inserted after the input's, in insertion order (its index is n_input() + its position): the
  // Steiner points on constraints (split) and the interior points (insert_interior, quality2d.cpp); a null handle
  // for a point removed since (remove_boundary_point) until compact_added.
  const std::vector<Vertex_handle>& added() const { return added_; }
  long long interior_points() const { return static_cast<long long>(added_.size()) - placed_; }
  // One row per input constraint edge, in the order of the input CDT's boundary sides (an interface once).
  const std::vector<BoundaryEdgeStats>& edges() const { return edges_; }
  void set_lower_bound(int edge, int count) { edges_[edge].lower_bound = count; }
  // The input domain is a convex polygon without holes, inner points or constraints (Theorem 3's setting).
  bool convex_polygon() const { return convex_polygon_; }
  // A step had to break another subsegment's empty disk (Theorem 3's optimality no longer follows).
  bool fallback_used() const { return fallback_used_; }
  void note_fallback() { fallback_used_ = true; }

  // The work queue: sides to (re)examine, first in first out. split queues the sides of every face it changes.
  void enqueue(const Side& side) { queue_.push_back(side); }
  void enqueue_all();  // every boundary side
  bool has_work() const { return !queue_.empty(); }
  Side next_side() {
    Side side = queue_.front();
    queue_.pop_front();
    return side;
  }
  std::size_t queued() const { return queue_.size(); }
  const Side& queued_at(std::size_t i) const { return queue_[i]; }
  // Provenance of the work queue (the diagnosis, refine2d_diagnosis.cpp).
  Propagation& propagation() { return propagation_; }
  const Propagation& propagation() const { return propagation_; }

  // The face on the left of s -> e, or nullptr when (s, e) is not a constrained edge of the CDT (anymore).
  Face_handle left_face(const Side& side) const;
  // A constrained subsegment with a domain triangle on its left (both sides of an interface or of a dangling
  // segment are boundary sides, each refined on its own; an outer boundary edge has one).
  bool is_boundary_side(const Side& side) const;
  // The domain triangles next to the subsegment of `side`: its left face first when that is in the domain, then
  // the right one when that is (two for an interface or dangling segment). Visibility walks start from these.
  std::vector<Face_handle> domain_faces(const Side& side) const;
  // A boundary side whose triangle is obtuse at the apex (exact: CGAL::angle(s, apex, e) == OBTUSE).
  bool is_violated(const Side& side) const;
  // The apex of the side's triangle (call only on a boundary side).
  Vertex_handle apex(const Side& side) const;
  // Every boundary side of the current CDT, sorted by vertex indices. A scan of every face, repeated only after a
  // split.
  std::vector<Side> boundary_sides() const;
  // The index in edges() of the input boundary edge a subsegment lies on (either orientation).
  int edge_of(const Side& side) const;
  // The index in edges() of the input edge Steiner point `index` (>= n_input) was placed on; -1 for an interior
  // point.
  int steiner_edge(int index) const { return steiner_edge_.at(index - n_input_); }

  // The scratch of walks on `lane` (0 or 1; lane 0 is the refinement's).
  WalkLane& lane(int i) const { return lanes_[i]; }

  // CGAL's is_valid (constrained Delaunay everywhere, the exterior included), and the maintained domain marks
  // equal a recomputation (which then replaces them). O(n): after every split in debug builds or when
  // check_every_split is set.
  void check_invariants();
#ifdef NONOBTUSE_CHECK_INVARIANTS
  static constexpr bool kCheckEverySplit = true;  // debug builds: check_invariants after every split
#else
  static constexpr bool kCheckEverySplit = false;
#endif
  // check_invariants after every split (tests ask for it in any build).
  void set_check_every_split(bool on) { check_every_split_ = on; }

 private:
  // Inserts a Steiner point into a constrained edge; the only mutation of the triangulation (split_point.cpp).
  friend Vertex_handle split(State& st, const Side& side, const Point& p);
  // Inserts a point strictly inside the domain, off every constraint (quality2d.cpp), the other mutation.
  friend Vertex_handle insert_interior(State& st, const Point& p, Face_handle located);
  // Removes a boundary Steiner point and renumbers the vertices after the removed ones (quality2d_prune.cpp).
  friend std::vector<Face_handle> remove_boundary_point(State& st, Vertex_handle v);
  friend std::vector<int> compact_added(State& st);

  // Every side of `sides` (the boundary sides) on the hull, no interface, every vertex on a constraint.
  bool is_convex_polygon(const std::vector<Side>& sides) const;
  static std::uint64_t edge_key(int a, int b) {
    return static_cast<std::uint64_t>(std::min(a, b)) << 32 | static_cast<std::uint32_t>(std::max(a, b));
  }

  CDT cdt_;
  const Domain2& domain_;
  const int n_input_;
  const long long budget_;
  long long placed_ = 0;
  bool fallback_used_ = false;
  bool convex_polygon_ = false;
  bool check_every_split_ = kCheckEverySplit;
  std::deque<Side> queue_;
  std::vector<BoundaryEdgeStats> edges_;
  Propagation propagation_;
  mutable std::array<WalkLane, 2> lanes_;
  // Input boundary edge (min, max) -> index in edges_; keyed min << 32 | max (a hash map: a polygon of a million
  // vertices has a million edges).
  std::unordered_map<std::uint64_t, int> edge_index_;
  std::vector<int> steiner_edge_;    // added vertex (index - n_input) -> index in edges_, -1 for interior points
  std::vector<Vertex_handle> added_;
  long long splits_ = 0;             // calls to split: the CDT changes only there
  mutable std::vector<Side> sides_;  // boundary_sides() as of split number sides_of_
  mutable long long sides_of_ = -1;
};

}  // namespace nonobtuse::refine2d
