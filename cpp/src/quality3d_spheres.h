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

// Balls (SearchBall, finite) with an id each, grouped by radius in power-of-two classes (in the order the classes
// first appear), each a kd-tree over the ball centers: a query asks each class for the centers within the class's
// bound of the point, so a ball is visited from within twice its radius only (with one bound for all, a few large
// balls made every query visit most of the others).
class BallClasses {
 public:
  void add(const SearchBall& ball, int id) {
    int e = 0;
    std::frexp(ball.radius, &e);
    auto [it, fresh] = class_of_.emplace(e, classes_.size());
    if (fresh) classes_.push_back({std::ldexp(1.0, e), {}, {}, nullptr});
    Class& c = classes_[it->second];
    c.centers.emplace_back(ball.center[0], ball.center[1], ball.center[2]);
    c.ids.push_back(id);
  }
  void build() {  // after the last add
    for (Class& c : classes_) c.index = std::make_unique<PointIndex>(c.centers);
  }
  // Offers the ids of the balls near q (every ball that holds q among them) to hit, class by class, until hit
  // accepts one: that id, or kNone when it accepts none.
  template <class Hit>
  int first(const P3& q, Hit&& hit) const {
    for (const Class& c : classes_) {
      int found = kNone;
      c.index->for_each_in(SearchBall{{q.x(), q.y(), q.z()}, c.radius, false}, [&](int i) {
        if (found == kNone && hit(c.ids[i])) found = c.ids[i];
      });
      if (found != kNone) return found;
    }
    return kNone;
  }
  static constexpr int kNone = std::numeric_limits<int>::min();

 private:
  struct Class {
    double radius;  // every search ball of the class has a smaller radius
    std::vector<P3> centers;
    std::vector<int> ids;
    std::unique_ptr<PointIndex> index;
  };
  std::map<int, std::size_t> class_of_;  // binary exponent -> class
  std::vector<Class> classes_;
};

// The closed diametral spheres of the subfacets and subsegments, found from a query point: the spheres' search
// balls (which contain them, see search_ball) in BallClasses, and the exact predicate decides.
class SphereIndex {
 public:
  SphereIndex(const std::vector<P3>& pts, const std::vector<Triangle>& faces, const std::vector<Segment>& segments)
      : pts_(pts), faces_(faces), segments_(segments) {
    auto add = [&](const SearchBall& ball, int row) {
      if (ball.everything || !std::isfinite(ball.radius)) always_.push_back(row);
      else balls_.add(ball, row);
    };
    for (std::size_t f = 0; f < faces.size(); ++f)
      add(search_ball(pts[faces[f][0]], pts[faces[f][1]], pts[faces[f][2]]), static_cast<int>(f));
    for (std::size_t s = 0; s < segments.size(); ++s)
      add(search_ball(pts[segments[s][0]], pts[segments[s][1]]), -1 - static_cast<int>(s));
    balls_.build();
  }

  static constexpr int kNone = BallClasses::kNone;

  // The first subfacet (its row) or subsegment (-1 - its row) whose closed diametral sphere holds q, or kNone
  // (exact).
  int find(const P3& q) const {
    for (int row : always_)
      if (holds(row, q)) return row;
    return balls_.first(q, [&](int row) { return holds(row, q); });
  }

  bool hits(const P3& q) const { return find(q) != kNone; }

 private:
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
  BallClasses balls_;
  std::vector<int> always_;
};

}  // namespace nonobtuse::quality3d
