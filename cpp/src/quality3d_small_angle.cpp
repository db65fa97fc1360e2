// The sharp features of a 3D boundary and their protecting region (see quality3d_small_angle.h).
#include "quality3d_small_angle.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gabriel3d_collar.h"

namespace nonobtuse::quality3d {

SharpFeatures::SharpFeatures(const gabriel3d::PlcState& s, double sharp_dihedral, double small_apex)
    : sharp_segment_(s.segments.size(), 0), mark_(s.points.size(), 0) {
  for (const auto& angle : gabriel3d::dihedral_angles(s)) {
    if (angle.degrees >= sharp_dihedral) continue;
    const int a = angle.vertices[0], b = angle.vertices[1];
    sharp_segment_[s.subsegments.at(gabriel3d::key(a, b))] = 1;
    mark_[a] = std::max<char>(mark_[a], kOnSharpSegment);
    mark_[b] = std::max<char>(mark_[b], kOnSharpSegment);
  }
  mark_sharp_apexes(s, small_apex);
  protect(s);
}

void SharpFeatures::mark_sharp_apexes(const gabriel3d::PlcState& s, double small_apex) {
  std::vector<std::vector<int>> ends(s.points.size());  // the other ends of the subsegments at each point
  for (const auto& [k, parent] : s.subsegments) ends[k.first].push_back(k.second), ends[k.second].push_back(k.first);
  const double cos_limit = std::cos(small_apex * 3.14159265358979323846 / 180.0);
  for (std::size_t v = 0; v < ends.size(); ++v)
    for (std::size_t i = 0; i < ends[v].size() && mark_[v] != kNearApex; ++i)
      for (std::size_t j = i + 1; j < ends[v].size(); ++j) {
        const auto d = s.points[ends[v][i]] - s.points[v], e = s.points[ends[v][j]] - s.points[v];
        if (d * e > cos_limit * std::sqrt(d.squared_length() * e.squared_length())) mark_[v] = kNearApex;
      }
  for (const auto& angle : gabriel3d::segment_facet_angles(s))
    if (angle.degrees < small_apex) mark_[angle.vertices[0]] = kNearApex;
}

void SharpFeatures::protect(const gabriel3d::PlcState& s) {
  auto guard = [&](const gabriel3d::SearchBall& ball, std::array<int, 3> element, double radius2) {
    if (ball.everything || !std::isfinite(ball.radius)) return;  // beyond the double range: no guard
    balls_.add(ball, static_cast<int>(guards_.size()));
    guards_.push_back({element, radius2});
    centers_.emplace_back(ball.center[0], ball.center[1], ball.center[2]);
  };
  std::vector<double> shortest(s.points.size(), std::numeric_limits<double>::infinity());  // squared, per point
  for (const auto& [k, parent] : s.subsegments) {
    const P3 &a = s.points[k.first], &b = s.points[k.second];
    const double length2 = CGAL::squared_distance(a, b);
    shortest[k.first] = std::min(shortest[k.first], length2);
    shortest[k.second] = std::min(shortest[k.second], length2);
    if (sharp_segment_[parent]) guard({{CGAL::midpoint(a, b).x(), CGAL::midpoint(a, b).y(), CGAL::midpoint(a, b).z()},
                                       std::sqrt(length2) * (1 + 0x1p-40), false},
                                      {-1, -1, -1}, length2);
    if (mark_[k.first] || mark_[k.second]) guard(gabriel3d::search_ball(a, b), {k.first, k.second, -1}, 0);
  }
  for (std::size_t v = 0; v < mark_.size(); ++v)
    if (mark_[v] == kNearApex && std::isfinite(shortest[v]))
      guard({{s.points[v].x(), s.points[v].y(), s.points[v].z()}, std::sqrt(shortest[v]) * (1 + 0x1p-40), false},
            {-1 - static_cast<int>(v), -1, -1}, shortest[v]);
  for (const auto& facet : s.facets)
    for (auto fh = facet->cdt.finite_faces_begin(); fh != facet->cdt.finite_faces_end(); ++fh) {
      const int a = fh->vertex(0)->info(), b = fh->vertex(1)->info(), c = fh->vertex(2)->info();
      if (fh->info().in_domain && (mark_[a] || mark_[b] || mark_[c]) &&
          !CGAL::collinear(s.points[a], s.points[b], s.points[c]))
        guard(gabriel3d::search_ball(s.points[a], s.points[b], s.points[c]), {a, b, c}, 0);
    }
  balls_.build();
}

bool SharpFeatures::protects(const gabriel3d::PlcState& s, const P3& p) const {
  return balls_.first(p, [&](int i) { return guarded(s, i, p); }) != BallClasses::kNone;
}

bool SharpFeatures::guarded(const gabriel3d::PlcState& s, int i, const P3& p) const {
  const auto& [e, radius2] = guards_[i];
  if (e[1] < 0)  // a ball around a sharp subsegment's midpoint (e[0] == -1) or an apex (-1 - the apex)
    return CGAL::compare_squared_distance(p, e[0] == -1 ? centers_[i] : s.points[-1 - e[0]], radius2) !=
           CGAL::LARGER;
  if (e[2] < 0) return CGAL::side_of_bounded_sphere(s.points[e[0]], s.points[e[1]], p) != CGAL::ON_UNBOUNDED_SIDE;
  return CGAL::side_of_bounded_sphere(s.points[e[0]], s.points[e[1]], s.points[e[2]], p) != CGAL::ON_UNBOUNDED_SIDE;
}

bool SharpFeatures::sharp_subsegment(const gabriel3d::PlcState& s, int a, int b) const {
  auto it = s.subsegments.find(gabriel3d::key(a, b));
  return it != s.subsegments.end() && (sharp_segment_[it->second] || mark_[a] == kNearApex || mark_[b] == kNearApex);
}

char SharpFeatures::midpoint_mark(const gabriel3d::PlcState& s, int a, int b) const {
  return std::max(mark_[a], mark_[b]) == kNearApex ? kNearApex : sharp_subsegment(s, a, b) ? kOnSharpSegment : 0;
}

void SharpFeatures::added(int i, char mark) {
  mark_.resize(i + 1, 0);
  mark_[i] = mark;
}

}  // namespace nonobtuse::quality3d
