// The diagnosis of a 2D refinement: which junctions and input angles drew the Steiner points, and how
// far one initial violation propagated.
#include "refine2d_diagnosis.h"

#include <cmath>
#include <set>
#include <tuple>

#include "refine2d_state.h"

namespace nonobtuse::refine2d {

void Propagation::begin(int s, int e, long long placed) {
  auto it = cause_.find(key(s, e));
  current_ = it != cause_.end() ? it->second : (cause_[key(s, e)] = causes_++);
  cause_of_point_.resize(placed, -1);
}

void Propagation::queued(int s, int e) { cause_.emplace(key(s, e), current_); }

void Propagation::end(long long placed) {
  cause_of_point_.resize(placed, current_);
  current_ = -1;
}

void Propagation::renumber(const std::vector<int>& to) {
  std::vector<int> kept;
  for (std::size_t k = 0; k < to.size(); ++k)
    if (to[k] >= 0) kept.push_back(steiner_cause(static_cast<long long>(k)));
  cause_of_point_ = std::move(kept);
}

namespace {

constexpr std::size_t kTop = 10;

// Angle at v between v -> a and v -> b in degrees (float, for reporting).
double degrees(const Point2& v, const Point2& a, const Point2& b) {
  double ax = a.x - v.x, ay = a.y - v.y, bx = b.x - v.x, by = b.y - v.y;
  return std::atan2(std::abs(ax * by - ay * bx), ax * bx + ay * by) * 180.0 / M_PI;
}

template <class T>
void keep_top(std::vector<T>& rows) {
  rows.erase(std::remove_if(rows.begin(), rows.end(), [](const T& r) { return r.steiner_points == 0; }),
             rows.end());
  std::stable_sort(rows.begin(), rows.end(),
                   [](const T& a, const T& b) { return a.steiner_points > b.steiner_points; });
  if (rows.size() > kTop) rows.resize(kTop);
}

}  // namespace

Refine2DDiagnosis diagnose(const State& st) {
  const auto& pts = st.domain().points;
  const int n = st.n_input();
  // Input constraints per input vertex (the refined edges, plus hull edges when the hull is the boundary): the
  // other ends of v's constraints are around[start[v], start[v + 1]).
  std::vector<int> start(n + 1, 0), around(2 * st.edges().size());
  for (const auto& e : st.edges()) ++start[e.edge[0] + 1], ++start[e.edge[1] + 1];
  for (int v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<int> next(start.begin(), start.end() - 1);
  for (const auto& e : st.edges()) around[next[e.edge[0]]++] = e.edge[1], around[next[e.edge[1]]++] = e.edge[0];
  // The constraint at v closest in angle to v -> a, and that angle.
  auto neighbour = [&](int v, int a) {
    std::pair<double, int> best{360.0, -1};
    for (int i = start[v]; i < start[v + 1]; ++i)
      if (around[i] != a) best = std::min(best, {degrees(pts[v], pts[a], pts[around[i]]), around[i]});
    return best;
  };
  // A row for every vertex on a constraint, in vertex order; row[v] its index (inner points have none).
  std::vector<JunctionStats> junctions;
  std::vector<int> row(n, -1);
  for (int v = 0; v < n; ++v) {
    if (start[v] == start[v + 1]) continue;
    row[v] = static_cast<int>(junctions.size());
    junctions.push_back({v, start[v + 1] - start[v], 360.0, 0});
    for (int i = start[v]; i < start[v + 1]; ++i)
      junctions.back().min_angle_degrees = std::min(junctions.back().min_angle_degrees, neighbour(v, around[i]).first);
  }
  std::map<std::pair<int, int>, InputAngleStats> angles;  // (vertex, a) -> stats
  std::map<int, std::set<int>> edges_of_cause;
  std::map<int, long long> splits_of_cause;
  const CDT& t = st.cdt();
  for (auto v = t.finite_vertices_begin(); v != t.finite_vertices_end(); ++v) {
    int idx = v->info();
    if (idx < n) continue;
    int k = st.steiner_edge(idx);
    if (k < 0) continue;  // an interior point
    auto [a, b] = st.edges()[k].edge;
    const Point2 p = cdt::from_cgal(v->point());
    auto d2 = [&](int i) { return std::hypot(pts[i].x - p.x, pts[i].y - p.y); };
    int near = d2(a) <= d2(b) ? a : b, far = near == a ? b : a;
    if (junctions[row[near]].constraints >= 2) {
      ++junctions[row[near]].steiner_points;
      auto [deg, other] = neighbour(near, far);
      auto& row = angles[{near, far}];
      row = {near, far, other, deg, row.steiner_points + 1};
    }
    int cause = st.propagation().steiner_cause(idx - n);
    if (cause >= 0) {
      edges_of_cause[cause].insert(k);
      ++splits_of_cause[cause];
    }
  }
  Refine2DDiagnosis d;
  d.junctions = std::move(junctions);
  keep_top(d.junctions);
  for (auto& [key, row] : angles) d.angles.push_back(row);
  keep_top(d.angles);
  d.initial_violations = st.propagation().causes();
  for (auto& [c, e] : edges_of_cause) d.propagation_depth = std::max(d.propagation_depth, static_cast<int>(e.size()));
  for (auto& [c, k] : splits_of_cause) d.propagation_splits = std::max(d.propagation_splits, k);
  return d;
}

}  // namespace nonobtuse::refine2d
