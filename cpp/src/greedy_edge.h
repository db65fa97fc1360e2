// Internal: Greedy-Refine of a single edge (Theorem 2 of the paper): from one end, the longest subsegment whose
// open half-disk holds no vertex it sees; its closed form, the emptiness test and the greedy count.
#pragma once
#include <vector>

#include "visibility.h"

namespace nonobtuse::refine2d {

// The encroachers of an edge with their points stored alongside, sorted by the coordinate along which the edge
// extends most: the sweeps re-test the remaining encroachers at every step, and a point set's hull edge has a
// large part of the input in its disk. Contiguous points spare a vertex handle dereference each, and the order
// lets a short subsegment's test skip, by binary search, the points whose coordinate lies outside its disk's
// (every consumer's answer is independent of the order).
struct Encroacher {
  Point p;
  Vertex_handle v;
};
struct Encroachers {
  std::vector<Encroacher> items;  // sorted by p[axis] (ties: as given)
  int axis = 0;                   // 0: x, 1: y
};
// `vertices` with their points, the axis chosen by the edge [s, e].
Encroachers with_points(const std::vector<Vertex_handle>& vertices, const Point& s, const Point& e);

// The greedy end from s toward e (s on the side `start`, whose left face touches [s, e]): the smallest
// t = |q - s|^2 / ((q - s) . d), d = e - s, over the vertices q of `q` that [s, s + t d] would see (`sight`;
// paper 4.4: only visible vertices encroach). At that t, q reaches the circle of [s, s + t d] (paper-notes:
// (s - q).(x - q) >= 0 iff t (q - s).d <= |q - s|^2). 1 when nothing blocks; `blocker` receives the vertex.
// Cost: one walk per candidate tried, in increasing t (usually one).
double greedy_parameter(const State& st, const Side& start, const Point& s, const Point& e,
                        const Encroachers& q, Sight sight, Vertex_handle* blocker = nullptr);

// True when no vertex of q that [s, p] would see (`sight`) encroaches it (exact encroachment, on either side: q
// only holds vertices of domain sides).
bool subsegment_is_empty(const State& st, const Side& start, const Point& s, const Point& p, const Encroachers& q,
                         Sight sight);

// Single-edge Greedy-Refine (Theorem 2) of `side` against the encroachers of its disk walk only, without
// inserting anything: the number of Steiner points it places, each rounded as the refinement rounds them; a
// vertex counts against a subsegment only when the subsegment sees it (Sight with the walk's obstacles).
int greedy_count(const State& st, const Side& side, const DiskWalk& walk);

// Keeps the vertices of q still encroaching [s, e] (disks of subsegments that share e shrink as s advances).
void keep_encroaching(const Point& s, const Point& e, Encroachers& q);

}  // namespace nonobtuse::refine2d
