// Closed diametral spheres of a 3D boundary against candidate interior points (interior quality refinement).
#include "nonobtuse/quality3d.h"

#include <string>

#include "gabriel3d_index.h"

namespace nonobtuse {

ClosedSphereHits closed_diametral_sphere_hits(const std::vector<Point3>& points, const std::vector<Triangle>& faces,
                                              const std::vector<Segment>& segments,
                                              const std::vector<Point3>& candidates) {
  using namespace gabriel3d;
  std::vector<P3> pts, cand;
  pts.reserve(points.size());
  for (const auto& p : points) pts.push_back(to_cgal(p));
  cand.reserve(candidates.size());
  for (const auto& p : candidates) cand.push_back(to_cgal(p));
  auto check_index = [&](int v, const char* what, std::size_t row) {
    if (v < 0 || static_cast<std::size_t>(v) >= pts.size())
      throw InvalidInput(std::string(what) + " " + std::to_string(row) + " refers to point " + std::to_string(v) +
                         ", but there are " + std::to_string(pts.size()) + " points");
  };
  ClosedSphereHits hits;
  hits.closed_face.assign(cand.size(), -1);
  hits.closed_segment.assign(cand.size(), -1);
  PointIndex index(cand);
  // The search ball contains the exact diametral sphere, boundary included (its radius bounds the distance from its
  // center to every point of the sphere), so a candidate on the sphere is proposed too.
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (int v : faces[f]) check_index(v, "face", f);
    const P3 &a = pts[faces[f][0]], &b = pts[faces[f][1]], &c = pts[faces[f][2]];
    if (CGAL::collinear(a, b, c))
      throw InvalidInput("face " + std::to_string(f) + " has collinear corners: no diametral sphere");
    index.for_each_in(search_ball(a, b, c), [&](int t) {
      if (hits.closed_face[t] < 0 && CGAL::side_of_bounded_sphere(a, b, c, cand[t]) != CGAL::ON_UNBOUNDED_SIDE)
        hits.closed_face[t] = static_cast<int>(f);
    });
  }
  for (std::size_t s = 0; s < segments.size(); ++s) {
    for (int v : segments[s]) check_index(v, "segment", s);
    const P3 &a = pts[segments[s][0]], &b = pts[segments[s][1]];
    if (a == b) throw InvalidInput("segment " + std::to_string(s) + " has coincident ends");
    index.for_each_in(search_ball(a, b), [&](int t) {
      if (hits.closed_segment[t] < 0 && CGAL::side_of_bounded_sphere(a, b, cand[t]) != CGAL::ON_UNBOUNDED_SIDE)
        hits.closed_segment[t] = static_cast<int>(s);
    });
  }
  return hits;
}

}  // namespace nonobtuse
