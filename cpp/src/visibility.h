// Internal: visibility from a subsegment (paper 4.4: only vertices that the subsegment sees encroach it). Walks
// over the triangles meeting a diametral disk, stopped by constraints, and exact shading by obstacles.
#pragma once
#include <vector>

#include "refine2d_state.h"
#include "shadows.h"

namespace nonobtuse::refine2d {

// What the walk over the diametral disk of a side found.
struct DiskWalk {
  std::vector<Vertex_handle> encroachers;  // vertices strictly inside the open half-disk, reachable from the side
  std::vector<Segment2> obstacles;         // the constrained edges of the faces reached that come near the disk
                                           // (DiskReach), other than the side's own
};

// How a vertex strictly inside the open diametral disk of a subsegment [a, b] of an edge counts as its encroacher.
// Reach (obstacles == nullptr): reachable from the edge's domain faces inside the closed disk without crossing a
// constraint (float pruning with slack, so it errs toward yes): implied by being seen, but a walk can wrap around a
// constraint's free end (or an end on the circle) to vertices that no point of (a, b) sees; the refinement uses
// it (its result is certified exactly anyway). Exact: seen from some point y of the open subsegment, the closed
// segment [y, v] meeting none of *obstacles (covered_from); the lower bound uses it with the obstacles of the walk
// over the whole edge's disk: the first constraint on every sight line from the edge inside that disk is an edge of
// a face the walk reached. Closed obstacles are stricter than "no constraint properly crosses [y, v]" only on
// sight lines grazing a constraint's end, so Exact never counts a vertex that is not seen.
// in_front (Exact only, optional): per vertex, its shadows on the walk's side, from the obstacles that may lie in
// front of it for any subsegment of the side (ObstaclesInFront, ShadowIntervals): the same answer as covered_from
// over all the walk's obstacles, in a binary search instead of a sort per question.
class ObstaclesInFront;
struct Sight {
  const std::vector<Segment2>* obstacles = nullptr;
  const ObstaclesInFront* in_front = nullptr;
};

// Which faces a walk over a diametral disk enters. Reach: every triangle meeting the closed disk that it reaches
// across unconstrained edges. Seen: only across an unconstrained edge that may hold a point seen from the side (see
// walk_seen in visibility.cpp): its encroachers are a subset of Reach's holding every vertex that Exact sight
// counts, and its obstacles still hold the first constraint on every sight line, so Exact sight decides the same
// on either; its cost is the faces that may be seen, where Reach's is every face in the disk (a spiky polygon's
// disk holds many spikes that the side does not see).
enum class Walked { Reach, Seen };

// Vertices strictly inside the open diametral disk of the subsegment on a domain side of it (exact: strictly
// left of s -> e when the left is a domain side, strictly right when the right is, and angle(s, q, e) ==
// OBTUSE), found by walking from its domain_faces across unconstrained edges into every triangle meeting the
// closed disk. Constraints stop the walk, which gives visibility; the float distance test only prunes the walk
// (conservatively, with slack): every decision on a vertex is exact. Encroachers are sorted by vertex index.
// Cost: the number of triangles meeting the disk (Walked::Seen: those that may be seen).
// Walks on different lanes (0 or 1) may run concurrently, each on one thread; lane 0 is the refinement's.
DiskWalk walk_diametral_disk(const State& st, const Side& side, int lane = 0, Walked walked = Walked::Reach);

// Whether v, strictly inside the open diametral disk of [a, b] on `start`'s edge, counts against it (Sight).
bool sees(const State& st, const Side& start, const Point& a, const Point& b, Vertex_handle v, Sight sight);

// Depth-first walk on `lane` from the faces `start` across the unconstrained edges (u, w) for which
// crosses(u, w) holds; visit(face) returns true to stop.
template <class Crosses, class Visit>
void walk(const State& st, const std::vector<Face_handle>& start, Crosses&& crosses, Visit&& visit, int lane) {
  const unsigned walk = ++st.lane(lane).face_walks;
  std::vector<Face_handle> stack(start);
  for (Face_handle f : start) f->info().visit[lane] = walk;
  while (!stack.empty()) {
    Face_handle f = stack.back();
    stack.pop_back();
    if (visit(f)) return;
    for (int i = 0; i < 3; ++i) {
      if (f->is_constrained(i)) continue;
      Face_handle g = f->neighbor(i);
      if (g->info().visit[lane] == walk || st.cdt().is_infinite(g)) continue;
      if (!crosses(f->vertex(CDT::ccw(i))->point(), f->vertex(CDT::cw(i))->point())) continue;
      g->info().visit[lane] = walk;
      stack.push_back(g);
    }
  }
}

// The closed diametral disk of [a, b] in doubles, for pruning: near(u, w) when the segment [u, w] comes within
// the radius (with slack: a little too far rather than too little).
struct DiskReach {
  double cx, cy, reach;
  DiskReach(const Point& a, const Point& b)
      : cx(0.5 * (a.x() + b.x())), cy(0.5 * (a.y() + b.y())),
        reach(0.25 * CGAL::to_double(CGAL::squared_distance(a, b)) * (1 + 1e-9) + 1e-300) {}
  bool near(const Point& u, const Point& w) const { return distance2_to_segment(cx, cy, u, w) <= reach; }
};

// walk into the faces meeting the closed diametral disk of [a, b] (float pruning with slack: a little too far).
template <class Visit>
void walk_disk(const State& st, const std::vector<Face_handle>& start, const Point& a, const Point& b, Visit&& visit,
               int lane = 0) {
  const DiskReach disk(a, b);
  // The union of (face ∩ disk) along the walk stays connected: consecutive faces share a piece of the crossed
  // edge inside the disk.
  walk(st, start, [&](const Point& u, const Point& w) { return disk.near(u, w); }, visit, lane);
}

}  // namespace nonobtuse::refine2d
