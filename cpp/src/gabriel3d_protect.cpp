// Protecting balls at apex vertices: their sizes (from the local feature size) and the lookup by point.
#include "gabriel3d_protect.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace nonobtuse::gabriel3d {

double local_feature_size(const PlcState& s, const PLC3& plc, int v) {
  const P3& p = s.points[v];
  double best = HUGE_VAL;
  auto keep = [&](double d2) { best = std::min(best, std::sqrt(d2)); };
  for (int u = 0; u < s.n_input; ++u)
    if (u != v) keep(CGAL::to_double(CGAL::squared_distance(p, s.points[u])));
  for (const auto& seg : s.segments)
    if (seg.a != v && seg.b != v) keep(CGAL::to_double(CGAL::squared_distance(p, K::Segment_3(s.points[seg.a],
                                                                                                s.points[seg.b]))));
  // Facets through v: every triangle of such a facet may lie at distance 0 from v (the facet is one plane).
  std::set<int> through;
  for (int f : s.point_facets[v]) through.insert(s.facets[f]->id);
  for (std::size_t t = 0; t < plc.triangles.size(); ++t) {
    if (through.count(plc.facet_ids[t])) continue;
    const auto& tri = plc.triangles[t];
    keep(CGAL::to_double(CGAL::squared_distance(
        p, K::Triangle_3(s.points[tri[0]], s.points[tri[1]], s.points[tri[2]]))));
  }
  return best;
}

double protecting_radius(double lfs) {
  if (!(lfs < HUGE_VAL)) return 1.0;  // a lone vertex: any radius; the caller's segments bound it anyway
  int exponent = 0;
  std::frexp(lfs / 4.0, &exponent);  // lfs / 4 = m 2^exponent with m in [1/2, 1)
  return std::ldexp(1.0, exponent - 1);
}

std::vector<ProtectingBall> protecting_balls(const PlcState& s, const PLC3& plc) {
  std::set<int> apices;
  for (const auto& angle : segment_facet_angles(s))
    if (angle.degrees < 90.0) apices.insert(angle.vertices[0]);
  std::vector<ProtectingBall> balls;
  for (int v : apices) balls.push_back({v, protecting_radius(local_feature_size(s, plc, v))});
  return balls;
}

namespace {
std::vector<P3> apex_points(const PlcState& s, const std::vector<ProtectingBall>& balls) {
  std::vector<P3> out;
  for (const auto& b : balls) out.push_back(s.points[b.apex]);
  return out;
}
}  // namespace

Protection::Protection(const PlcState& s, std::vector<ProtectingBall> balls)
    : s_(s), balls_(std::move(balls)), apices_(apex_points(s, balls_)), index_(apices_) {}

const ProtectingBall* Protection::strictly_containing(const P3& p) const {
  const int i = index_.nearest(p);
  if (i < 0) return nullptr;
  const ProtectingBall& ball = balls_[i];
  const double r2 = ball.radius * ball.radius;  // a power of two squared: exact
  return CGAL::compare_squared_distance(p, s_.points[ball.apex], r2) == CGAL::SMALLER ? &ball : nullptr;
}

std::optional<P3> onto_sphere(const P3& apex, double radius, const P3& p) {
  const K::Vector_3 d = p - apex;
  const double length = std::sqrt(CGAL::to_double(d.squared_length()));
  if (!(length > 0)) return std::nullopt;
  return apex + d * (radius / length);
}

}  // namespace nonobtuse::gabriel3d
