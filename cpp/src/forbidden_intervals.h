// Internal: forbidden intervals (paper 4.2, Figure 5). A Steiner point on one subsegment that lands inside the open
// half-disk of another boundary subsegment f, whose triangle would get it as apex, breaks f: those points form
// f's forbidden interval on the subsegment.
#pragma once
#include <optional>
#include <utility>
#include <vector>

#include "refine2d_state.h"

namespace nonobtuse::refine2d {

// The boundary sides (other than `side`) that a vertex at p, on `side`, would make violated: exactly those
// among the edges of p's conflict zone (the triangles whose circumcircle strictly contains p, reachable from
// `side`'s domain_faces across unconstrained edges; their triangles get p as apex) whose open half-disk contains p.
// These are the forbidden intervals of `side` that contain p, visibility included. Exact. Walks on lane 0.
// Cost: the conflict zone.
std::vector<Side> sides_broken_by(const State& st, const Side& side, const Point& p);

// A boundary side (other than `cur`) that a Steiner point at p on `cur` would break, if any: p in its forbidden
// interval (the first of sides_broken_by).
std::optional<Side> forbidder(const State& st, const Side& cur, const Point& p);

// The forbidden interval of [s, e] with respect to f: the parameters t1 <= t2 where s + t (e - s) crosses f's
// diametral circle (a float construction; every decision made with it is re-checked exactly).
std::pair<double, double> forbidden_interval(const Point& s, const Point& e, const Side& f);

// True when s lies in the closed diametral disk of f (f's forbidden interval then starts at s: no progress).
bool in_closed_disk(const Point& s, const Side& f);

}  // namespace nonobtuse::refine2d
