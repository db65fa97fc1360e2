// The Refiner's stations (gabriel3d_stations.h): a point on a grouped segment is placed on the group's other
// segments too.
#include <algorithm>
#include <cmath>
#include <map>

#include "gabriel3d_refiner.h"
#include "gabriel3d_split_rule.h"

namespace nonobtuse::gabriel3d {

namespace {

// The parameter of p along input segment `seg` (floating point).
double along(const PlcState& s, int seg, const P3& p) {
  const P3 &a = s.points[s.segments[seg].a], &b = s.points[s.segments[seg].b];
  const K::Vector_3 d = b - a;
  return CGAL::to_double((p - a) * d) / CGAL::to_double(d * d);
}

// The subsegment of input segment `seg` whose parameter range holds t strictly inside, if any.
std::optional<Key> subsegment_at(const PlcState& s, int seg, double t) {
  for (const auto& [sub, parent] : s.subsegments) {
    if (parent != seg) continue;
    const double tu = along(s, seg, s.points[sub.first]), tw = along(s, seg, s.points[sub.second]);
    if (std::min(tu, tw) < t && t < std::max(tu, tw)) return sub;
  }
  return std::nullopt;
}

bool inside(const P3& a, const P3& b, const P3& p) {
  return CGAL::side_of_bounded_sphere(a, b, p) == CGAL::ON_BOUNDED_SIDE;
}

}  // namespace

std::optional<Stop> Refiner::place_station(int segment, int m, const std::vector<int>& around) {
  struct Placed {
    int point;
    std::vector<int> around;
  };
  std::map<int, Placed> placed{{segment, {m, around}}};
  for (const StationLink& link : stations_->tree(segment)) {
    const auto from = placed.find(link.from);
    if (from == placed.end()) continue;
    const P3& p = s_.points[from->second.point];
    if (from->second.point == link.apex) {  // the apex itself is its own image
      placed[link.to] = {link.apex, {}};
      continue;
    }
    const auto t = station_parameter(s_, link, p);
    if (!t) continue;
    const InputSegment& to = s_.segments[link.to];
    const P3 ideal = interpolate(s_.points[to.a], s_.points[to.b], *t);
    const auto sub = subsegment_at(s_, link.to, *t);
    if (!sub) continue;
    const auto [u, w] = *sub;
    if (too_short(s_.points[u], ideal) || too_short(ideal, s_.points[w])) continue;  // a point is there already
    if (auto stop = budget_left()) return stop;
    const auto accept = [&](const P3& q) {
      if (s_.at.count({q.x(), q.y(), q.z()})) return false;
      for (const auto& [seg, other] : placed) {
        const P3& o = s_.points[other.point];
        if (inside(s_.points[u], q, o) || inside(q, s_.points[w], o)) return false;
        for (int n : other.around)
          if (inside(o, s_.points[n], q)) return false;
      }
      return true;
    };
    const P3* apex = link.apex >= 0 ? &s_.points[link.apex] : nullptr;
    const double radius = apex ? station_radius(s_, link, p) : 0.0;
    const std::optional<P3> q = station_rounding(ideal, apex, radius, accept);
    const P3 point = q ? *q : ideal;
    if (s_.at.count({point.x(), point.y(), point.z()})) continue;
    const double tu = along(s_, link.to, s_.points[u]), tw = along(s_, link.to, s_.points[w]);
    const int id = split_subsegment(s_, u, w, (*t - tu) / (tw - tu), point);
    ++steiner_on_segments;
    inserted(id, *sub);
    placed[link.to] = {id, {u, w}};
  }
  for (const auto& [seg, p] : placed)
    for (const auto& [other, q] : placed)
      if (other != seg && q.point >= s_.n_input && p.point >= s_.n_input)
        for (int f : s_.segments[other].facets) {
          const auto& mine = s_.segments[seg].facets;
          if (std::find(mine.begin(), mine.end(), f) != mine.end()) continue;
          if (auto stop = place_foot(f, p.point, q.point, other)) return stop;
        }
  return std::nullopt;
}

std::optional<Stop> Refiner::place_foot(int f, int p, int base, int along) {
  Facet& facet = *s_.facets[f];
  const double n[3] = {facet.u[1] * facet.v[2] - facet.u[2] * facet.v[1],
                       facet.u[2] * facet.v[0] - facet.u[0] * facet.v[2],
                       facet.u[0] * facet.v[1] - facet.u[1] * facet.v[0]};
  const P3& a = s_.points[p];
  const P3& b = s_.points[base];
  const K::Vector_3 t = s_.points[s_.segments[along].b] - s_.points[s_.segments[along].a];
  const double tt = CGAL::to_double(t * t);
  double v[3] = {a.x() - b.x(), a.y() - b.y(), a.z() - b.z()};
  const double vt =
      (v[0] * CGAL::to_double(t.x()) + v[1] * CGAL::to_double(t.y()) + v[2] * CGAL::to_double(t.z())) / tt;
  v[0] -= vt * CGAL::to_double(t.x()), v[1] -= vt * CGAL::to_double(t.y()), v[2] -= vt * CGAL::to_double(t.z());
  const double vn = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
  for (int d = 0; d < 3; ++d) v[d] = (v[d] - vn * n[d]) * (1.0 + 1.0 / 64);
  const P3 point(b.x() + v[0], b.y() + v[1], b.z() + v[2]);
  if (s_.at.count({point.x(), point.y(), point.z()})) return std::nullopt;
  FacetCDT::Locate_type lt;
  int li = 0;
  auto loc = facet.cdt.locate(facet.project(point), lt, li);
  if (!strictly_in_domain(facet.cdt, lt, loc, li)) return std::nullopt;
  if (auto stop = budget_left()) return stop;
  const int id = insert_in_facet(s_, f, point, lt, loc, li);
  ++steiner_on_facets;
  inserted(id);
  return std::nullopt;
}

std::optional<Stop> Refiner::place_apex_stations() {
  for (int apex : stations_->apices())
    for (std::size_t seg = 0; seg < s_.segments.size(); ++seg) {
      if (!stations_->grouped(static_cast<int>(seg))) continue;
      const InputSegment& in = s_.segments[seg];
      if (in.a != apex && in.b != apex) continue;
      // The apex's neighbor on this segment: the other end of its subsegment at the apex.
      std::vector<int> around;
      for (const auto& [sub, parent] : s_.subsegments)
        if (parent == static_cast<int>(seg) && (sub.first == apex || sub.second == apex))
          around.push_back(sub.first == apex ? sub.second : sub.first);
      if (auto stop = place_station(static_cast<int>(seg), apex, around)) return stop;
    }
  return std::nullopt;
}

}  // namespace nonobtuse::gabriel3d
