// Internal: the closed diametral spheres of a 3D boundary's subfacets and subsegments, found from a query point
// (interior quality refinement, quality3d_interior.cpp).
#pragma once
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <vector>

#include "gabriel3d_index.h"

namespace nonobtuse::quality3d {

using gabriel3d::P3;
using gabriel3d::PointIndex;
using gabriel3d::search_ball;
using gabriel3d::SearchBall;

// The closed diametral spheres of the subfacets and subsegments, found from a query point: the spheres' search
// balls (which contain them, see search_ball) are grouped by radius in power-of-two classes, each a kd-tree over
// the ball centers; a query asks each class for the centers within the class's largest radius of the point, and the
// exact predicate decides.
class SphereIndex {
 public:
  SphereIndex(const std::vector<P3>& pts, const std::vector<Triangle>& faces, const std::vector<Segment>& segments)
      : pts_(pts), faces_(faces), segments_(segments) {
    std::map<int, std::size_t> class_of;
    auto add = [&](const SearchBall& ball, int row) {
      if (ball.everything || !std::isfinite(ball.radius)) {
        always_.push_back(row);
        return;
      }
      int e = 0;
      std::frexp(ball.radius, &e);
      auto [it, fresh] = class_of.emplace(e, classes_.size());
      if (fresh) classes_.push_back({std::ldexp(1.0, e), {}, {}, nullptr});
      Class& c = classes_[it->second];
      c.centers.emplace_back(ball.center[0], ball.center[1], ball.center[2]);
      c.rows.push_back(row);
    };
    for (std::size_t f = 0; f < faces.size(); ++f)
      add(search_ball(pts[faces[f][0]], pts[faces[f][1]], pts[faces[f][2]]), static_cast<int>(f));
    for (std::size_t s = 0; s < segments.size(); ++s)
      add(search_ball(pts[segments[s][0]], pts[segments[s][1]]), -1 - static_cast<int>(s));
    for (Class& c : classes_) c.index = std::make_unique<PointIndex>(c.centers);
  }

  static constexpr int kNone = std::numeric_limits<int>::min();

  // The first subfacet (its row) or subsegment (-1 - its row) whose closed diametral sphere holds q, or kNone
  // (exact).
  int find(const P3& q) const {
    for (int row : always_)
      if (holds(row, q)) return row;
    for (const Class& c : classes_) {
      int found = kNone;
      SearchBall around{{q.x(), q.y(), q.z()}, c.radius, false};
      c.index->for_each_in(around, [&](int i) {
        if (found == kNone && holds(c.rows[i], q)) found = c.rows[i];
      });
      if (found != kNone) return found;
    }
    return kNone;
  }

  bool hits(const P3& q) const { return find(q) != kNone; }

 private:
  struct Class {
    double radius;  // every search ball of the class has a smaller radius
    std::vector<P3> centers;
    std::vector<int> rows;  // face row, or -1 - segment row
    std::unique_ptr<PointIndex> index;
  };
  bool holds(int row, const P3& q) const {
    if (row >= 0) {
      const Triangle& f = faces_[row];
      return CGAL::side_of_bounded_sphere(pts_[f[0]], pts_[f[1]], pts_[f[2]], q) != CGAL::ON_UNBOUNDED_SIDE;
    }
    const Segment& s = segments_[-1 - row];
    return CGAL::side_of_bounded_sphere(pts_[s[0]], pts_[s[1]], q) != CGAL::ON_UNBOUNDED_SIDE;
  }
  const std::vector<P3>& pts_;
  const std::vector<Triangle>& faces_;
  const std::vector<Segment>& segments_;
  std::vector<Class> classes_;
  std::vector<int> always_;
};

}  // namespace nonobtuse::quality3d
