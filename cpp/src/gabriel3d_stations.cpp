// Stations on groups of near-parallel close input segments (gabriel3d_stations.h).
#include "gabriel3d_stations.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <numeric>

namespace nonobtuse::gabriel3d {

namespace {

// Partners: ends pairwise within this fraction of the segment's length (step.off: 3.1e-7). Floating point; the
// choice of groups is a strategy, the certificate stays the exact check.
constexpr double kNearEnds = 1e-5;
constexpr double kApexDegrees = 1.0;

int find(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

Stations::Stations(const PlcState& s) {
  const int n = static_cast<int>(s.segments.size());
  std::vector<std::vector<int>> at(s.n_input);
  for (int i = 0; i < n; ++i) at[s.segments[i].a].push_back(i), at[s.segments[i].b].push_back(i);
  std::vector<P3> input(s.points.begin(), s.points.begin() + s.n_input);
  PointIndex index(input);
  std::vector<StationLink> links;
  for (int i = 0; i < n; ++i) {
    const InputSegment& seg = s.segments[i];
    const double reach = kNearEnds * distance(s.points[seg.a], s.points[seg.b]);
    index.for_each_in({{s.points[seg.a].x(), s.points[seg.a].y(), s.points[seg.a].z()}, reach, false}, [&](int v) {
      if (distance(s.points[v], s.points[seg.a]) > reach) return;
      for (int j : at[v]) {
        const InputSegment& other = s.segments[j];
        const int far = other.a == v ? other.b : other.a;
        if (j == i || far == v || distance(s.points[far], s.points[seg.b]) > reach) continue;
        const int apex = v == seg.a ? v : far == seg.b ? far : -1;
        links.push_back({i, j, apex});
        links.push_back({j, i, apex});
      }
    });
  }
  // Segments through one end at an angle below kApexDegrees: their shells are centered at that end, so a group's
  // stations there must be matched by equal radii too (step.off: 3-9 leaves 5-9 at 9 at 0.82 degrees; with shells
  // from 9 its points sat in the middle of 1-6's pieces from 6, 2.3e-4 away, below radius 1).
  const std::size_t partners = links.size();
  const double cos_limit = std::cos(kApexDegrees * M_PI / 180.0);
  for (int v = 0; v < s.n_input; ++v)
    for (std::size_t x = 0; x < at[v].size(); ++x)
      for (std::size_t y = x + 1; y < at[v].size(); ++y) {
        const int i = at[v][x], j = at[v][y];
        const P3& p = s.points[s.segments[i].a == v ? s.segments[i].b : s.segments[i].a];
        const P3& q = s.points[s.segments[j].a == v ? s.segments[j].b : s.segments[j].a];
        const K::Vector_3 d = p - s.points[v], e = q - s.points[v];
        if (CGAL::to_double(d * e) > cos_limit * std::sqrt(CGAL::to_double(d * d) * CGAL::to_double(e * e)))
          links.push_back({i, j, v}), links.push_back({j, i, v});
      }
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& l : links) parent[find(parent, l.from)] = find(parent, l.to);
  std::vector<bool> kept(n, false);
  for (std::size_t k = 0; k < partners; ++k) kept[find(parent, links[k].from)] = true;
  std::vector<std::vector<StationLink>> out(n);
  for (const auto& l : links)
    if (kept[find(parent, l.from)]) out[l.from].push_back(l);
  for (int i = 0; i < n; ++i) {
    if (out[i].empty()) continue;
    // 0-1 breadth-first search: links through a shared end cost 0, by the foot 1.
    std::vector<bool> seen(n, false);
    std::deque<StationLink> queue;
    for (const auto& l : out[i]) l.apex >= 0 ? queue.push_front(l) : queue.push_back(l);
    seen[i] = true;
    std::vector<StationLink>& tree = trees_[i];
    while (!queue.empty()) {
      const StationLink l = queue.front();
      queue.pop_front();
      if (seen[l.to]) continue;
      seen[l.to] = true;
      tree.push_back(l);
      for (const auto& next : out[l.to])
        if (!seen[next.to]) next.apex >= 0 ? queue.push_front(next) : queue.push_back(next);
    }
    for (const auto& l : out[i])
      if (l.apex >= 0) apices_.push_back(l.apex);
  }
  for (const auto& [i, tree] : trees_) ends_.push_back(s.segments[i].a), ends_.push_back(s.segments[i].b);
  std::sort(ends_.begin(), ends_.end());
  ends_.erase(std::unique(ends_.begin(), ends_.end()), ends_.end());
  std::sort(apices_.begin(), apices_.end());
  apices_.erase(std::unique(apices_.begin(), apices_.end()), apices_.end());
}

double station_radius(const PlcState& s, const StationLink& link, const P3& p) {
  const P3& e = s.points[link.apex];
  const InputSegment &from = s.segments[link.from], &to = s.segments[link.to];
  const K::Vector_3 d1 = s.points[from.a == link.apex ? from.b : from.a] - e;
  const K::Vector_3 d2 = s.points[to.a == link.apex ? to.b : to.a] - e;
  const K::Vector_3 c = CGAL::cross_product(d1, d2);
  const double sin2 = CGAL::to_double(c * c) / (CGAL::to_double(d1 * d1) * CGAL::to_double(d2 * d2));
  const double stretch = 1.0 + sin2 / 4;
  const double r = distance(p, e);
  return link.to > link.from ? r * stretch : r / stretch;
}

std::optional<double> station_parameter(const PlcState& s, const StationLink& link, const P3& p) {
  const InputSegment& to = s.segments[link.to];
  const P3 &a = s.points[to.a], &b = s.points[to.b];
  double t = 0;
  if (link.apex >= 0) {
    const double r = station_radius(s, link, p) / distance(a, b);
    t = link.apex == to.a ? r : 1.0 - r;
  } else {
    const K::Vector_3 d = b - a;
    t = CGAL::to_double((p - a) * d) / CGAL::to_double(d * d);
  }
  if (!(t > 0.0 && t < 1.0)) return std::nullopt;
  return t;
}

std::optional<P3> station_rounding(const P3& ideal, const P3* apex, double radius,
                                   const std::function<bool(const P3&)>& accept) {
  const std::array<double, 3> c = {ideal.x(), ideal.y(), ideal.z()};
  auto ulp = [](double x) { return std::nextafter(std::abs(x), HUGE_VAL) - std::abs(x); };
  if (!apex) {
    std::vector<std::array<int, 3>> offsets;
    for (int i = -1; i <= 1; ++i)
      for (int j = -1; j <= 1; ++j)
        for (int k = -1; k <= 1; ++k) offsets.push_back({i, j, k});
    std::stable_sort(offsets.begin(), offsets.end(), [](const auto& x, const auto& y) {
      return std::abs(x[0]) + std::abs(x[1]) + std::abs(x[2]) < std::abs(y[0]) + std::abs(y[1]) + std::abs(y[2]);
    });
    for (const auto& o : offsets) {
      const P3 q(c[0] + o[0] * ulp(c[0]), c[1] + o[1] * ulp(c[1]), c[2] + o[2] * ulp(c[2]));
      if (accept(q)) return q;
    }
    return std::nullopt;
  }
  const std::array<double, 3> e = {apex->x(), apex->y(), apex->z()};
  // The radial step of one ulp in each coordinate; the finest one is solved for, the other two are enumerated.
  std::array<double, 3> step{};
  for (int d = 0; d < 3; ++d) step[d] = ulp(c[d]) * std::abs(c[d] - e[d]) / radius;
  int fine = 0;
  for (int d = 1; d < 3; ++d)
    if (step[d] < step[fine]) fine = d;
  const int u = (fine + 1) % 3, v = (fine + 2) % 3;
  auto distance_to_apex = [&](const std::array<double, 3>& p) {
    double sum = 0;
    for (int d = 0; d < 3; ++d) sum += (p[d] - e[d]) * (p[d] - e[d]);
    return std::sqrt(sum);
  };
  std::vector<std::pair<double, std::array<double, 3>>> candidates;
  for (int i = -kStationSearch; i <= kStationSearch; ++i)
    for (int j = -kStationSearch; j <= kStationSearch; ++j) {
      std::array<double, 3> p = c;
      p[u] += i * ulp(c[u]);
      p[v] += j * ulp(c[v]);
      const double miss = radius - distance_to_apex(p);
      const double sign = (c[fine] - e[fine]) >= 0 ? 1.0 : -1.0;
      // The fine coordinate's steps to the sphere: none where it does not move the radius (step 0), and no
      // candidate where the sphere is out of reach (a NaN, an infinity or beyond 2^20 steps: lround would overflow).
      const double steps = step[fine] > 0.0 ? sign * miss / step[fine] : 0.0;
      if (!(std::abs(steps) <= 1048576.0)) continue;
      const long k0 = std::lround(steps);
      for (long k = k0 - 1; k <= k0 + 1; ++k) {
        std::array<double, 3> q = p;
        q[fine] += static_cast<double>(k) * ulp(c[fine]);
        candidates.push_back({std::abs(distance_to_apex(q) - radius), q});
      }
    }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  for (std::size_t n = 0; n < candidates.size() && n < 64; ++n) {
    const auto& q = candidates[n].second;
    if (accept(P3(q[0], q[1], q[2]))) return P3(q[0], q[1], q[2]);
  }
  return std::nullopt;
}

}  // namespace nonobtuse::gabriel3d
