// The exact Gabriel certificate of a 3D boundary: empty open diametral spheres of faces and segments.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <string>

#include "fork_join.h"
#include "gabriel3d_index.h"
#include "gabriel3d_scan_memo.h"

namespace nonobtuse::gabriel3d {
namespace {

using I = CGAL::Interval_nt<false>;  // needs the rounding mode set upward: callers hold a Protect_FPU_rounding

struct IVec {
  I x, y, z;
};
IVec operator-(const IVec& a, const IVec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
IVec operator*(const I& s, const IVec& a) { return {s * a.x, s * a.y, s * a.z}; }
I dot(const IVec& a, const IVec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
IVec cross(const IVec& a, const IVec& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
IVec ivec(const P3& p) { return {I(p.x()), I(p.y()), I(p.z())}; }

// The smallest ball around a double center that contains every ball with center in `center` and radius in
// `radius` (all intervals).
SearchBall enclose(const IVec& center, const I& radius) {
  SearchBall ball;
  const I* c[3] = {&center.x, &center.y, &center.z};
  I spread2(0);
  for (int k = 0; k < 3; ++k) {
    double mid = 0.5 * (c[k]->inf() + c[k]->sup());
    if (!std::isfinite(mid)) {
      ball.everything = true;
      return ball;
    }
    ball.center[k] = mid;
    double d = std::max((I(c[k]->sup()) - I(mid)).sup(), (I(mid) - I(c[k]->inf())).sup());
    spread2 += I(d) * I(d);
  }
  ball.radius = (radius + CGAL::sqrt(spread2)).sup();
  ball.everything = !std::isfinite(ball.radius);
  return ball;
}

using EK = CGAL::Exact_predicates_exact_constructions_kernel;

EK::Point_3 exact_circumcenter(const P3& a, const P3& b, const P3& c) {
  auto center = CGAL::circumcenter(EK::Point_3(a.x(), a.y(), a.z()), EK::Point_3(b.x(), b.y(), b.z()),
                                   EK::Point_3(c.x(), c.y(), c.z()));
  CGAL::exact(center);
  return center;
}

bool finite(const P3& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

}  // namespace

std::optional<P3> rounded_circumcenter(const P3& a, const P3& b, const P3& c) {
  if (CGAL::collinear(a, b, c)) return std::nullopt;
  // The floating-point construction divides by a determinant that underflows to 0 on needles (debug builds of
  // CGAL assert that it does not): computed first, the same way, so that such triangles go to the exact center.
  double num_x, num_y, num_z, den;
  CGAL::determinants_for_circumcenterC3(a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), c.x(), c.y(), c.z(), num_x, num_y,
                                        num_z, den);
  if (den != 0) {
    P3 center = CGAL::circumcenter(a, b, c);
    if (finite(center)) return center;
  }
  auto exact = exact_circumcenter(a, b, c);
  P3 center(CGAL::to_double(exact.x()), CGAL::to_double(exact.y()), CGAL::to_double(exact.z()));
  if (finite(center)) return center;
  return std::nullopt;
}

SearchBall search_ball(const P3& a, const P3& b) {
  CGAL::Protect_FPU_rounding<true> upward;
  IVec ia = ivec(a), ib = ivec(b);
  IVec center = I(0.5) * IVec{ia.x + ib.x, ia.y + ib.y, ia.z + ib.z};
  IVec d = ib - ia;
  return enclose(center, I(0.5) * CGAL::sqrt(dot(d, d)));
}

SearchBall search_ball(const P3& a, const P3& b, const P3& c) {
  {
    CGAL::Protect_FPU_rounding<true> upward;
    IVec ia = ivec(a), u = ivec(b) - ia, v = ivec(c) - ia;
    IVec w = cross(u, v);
    I denominator = I(2) * dot(w, w);
    if (denominator.inf() > 0.0) {
      // Circumcenter relative to a: ((|u|^2 v - |v|^2 u) x (u x v)) / (2 |u x v|^2).
      IVec t = cross(dot(u, u) * v - dot(v, v) * u, w);
      IVec offset{t.x / denominator, t.y / denominator, t.z / denominator};
      IVec center{ia.x + offset.x, ia.y + offset.y, ia.z + offset.z};
      SearchBall ball = enclose(center, CGAL::sqrt(dot(offset, offset)));
      // Accept when the interval evaluation was tight; a nearly collinear (needle) triangle makes it loose, and
      // a loose ball would make the search visit far too many points.
      if (!ball.everything && ball.radius <= 1.001 * CGAL::sqrt(dot(offset, offset)).inf()) return ball;
    }
  }
  // Needle triangles: the exact circumcenter (lazy exact kernel), enclosed in the tightest double intervals.
  if (CGAL::collinear(a, b, c)) {  // no diametral sphere: callers reject or skip such faces
    SearchBall ball;
    ball.everything = true;
    return ball;
  }
  auto center = exact_circumcenter(a, b, c);
  IVec ic{I(CGAL::to_interval(center.x())), I(CGAL::to_interval(center.y())), I(CGAL::to_interval(center.z()))};
  CGAL::Protect_FPU_rounding<true> upward;
  IVec r = ic - ivec(a);
  return enclose(ic, CGAL::sqrt(dot(r, r)));
}

PointIndex::PointIndex(const std::vector<P3>& points) : points_(points) {
  order_.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    order_.push_back({{points[i].x(), points[i].y(), points[i].z()}, static_cast<int>(i)});
  rebuild();
}

void PointIndex::add(int i) {
  pending_.push_back(i);
  // Every query scans the pending list: keep it near sqrt(n) (a rebuild costs O(n log n)), not a fraction of n,
  // which made each query O(n) and refinement quadratic.
  if (pending_.size() > 256 && pending_.size() * pending_.size() > 16 * order_.size()) {
    for (int j : pending_) order_.push_back({{points_[j].x(), points_[j].y(), points_[j].z()}, j});
    pending_.clear();
    rebuild();
  }
}

void PointIndex::rebuild() {
  nodes_.clear();
  if (!order_.empty()) build(0, static_cast<int>(order_.size()));
}

int PointIndex::build(int begin, int end) {
  Node node;
  node.begin = begin;
  node.end = end;
  node.lo = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
  node.hi = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (int k = begin; k < end; ++k) {
    const auto& p = order_[k].p;
    for (int d = 0; d < 3; ++d) {
      node.lo[d] = std::min(node.lo[d], p[d]);
      node.hi[d] = std::max(node.hi[d], p[d]);
    }
  }
  int id = static_cast<int>(nodes_.size());
  nodes_.push_back(node);
  if (end - begin <= 8) return id;
  int axis = 0;
  for (int d = 1; d < 3; ++d)
    if (node.hi[d] - node.lo[d] > node.hi[axis] - node.lo[axis]) axis = d;
  int mid = (begin + end) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](const Item& i, const Item& j) { return i.p[axis] < j.p[axis]; });
  int left = build(begin, mid);
  int right = build(mid, end);
  nodes_[id].left = left;
  nodes_[id].right = right;
  return id;
}

int PointIndex::nearest(const P3& q) const {
  int best = -1;
  double best2 = HUGE_VAL;
  auto consider = [&](int i) {
    double d2 = CGAL::to_double(CGAL::squared_distance(points_[i], q));
    if (d2 < best2) best2 = d2, best = i;
  };
  for (int i : pending_) consider(i);
  if (nodes_.empty()) return best;
  std::array<double, 3> c{q.x(), q.y(), q.z()};
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (box_distance2(node, c) > best2) continue;
    if (node.left < 0) {
      for (int k = node.begin; k < node.end; ++k) consider(order_[k].i);
    } else {  // visit the nearer child first (pushed last)
      bool left_first = box_distance2(nodes_[node.left], c) <= box_distance2(nodes_[node.right], c);
      stack[top++] = left_first ? node.right : node.left;
      stack[top++] = left_first ? node.left : node.right;
    }
  }
  return best;
}

namespace {

// The deepest confirmed encroacher of segment ab (c == -1) or triangle abc among the candidates offered: the
// smallest (-depth, index) among those the exact predicate confirms and `ignore` lets through, as a sort by that
// key would find first. A candidate is tested only when its key beats the best so far: no sort, and ignore() (a
// facet's 2D test) only for points strictly inside the sphere. The answer does not depend on the offering order.
class Deepest {
 public:
  Deepest(const std::vector<P3>& points, int a, int b, int c)
      : points_(points), a_(a), b_(b), c_(c),
        ball_(c < 0 ? search_ball(points[a], points[b]) : search_ball(points[a], points[b], points[c])),
        center_(ball_.center[0], ball_.center[1], ball_.center[2]) {
    const P3 &pa = points[a], &pb = points[b];
    if (ball_.everything) center_ = c < 0 ? CGAL::midpoint(pa, pb) : CGAL::centroid(pa, pb, points[c]);
    radius_ = std::sqrt(CGAL::to_double(CGAL::squared_distance(center_, pa)));
  }
  const SearchBall& ball() const { return ball_; }
  // Offers point t (not a corner).
  void offer(int t, const std::function<bool(int)>& ignore) {
    const double depth = 1.0 - std::sqrt(CGAL::to_double(CGAL::squared_distance(center_, points_[t]))) / radius_;
    const std::pair<double, int> key{-depth, t};
    if (best_.second >= 0 && !(key < best_)) return;
    const P3 &pa = points_[a_], &pb = points_[b_], &pt = points_[t];
    bool inside = c_ < 0 ? CGAL::side_of_bounded_sphere(pa, pb, pt) == CGAL::ON_BOUNDED_SIDE
                         : CGAL::side_of_bounded_sphere(pa, pb, points_[c_], pt) == CGAL::ON_BOUNDED_SIDE;
    if (inside && !(ignore && ignore(t))) best_ = key;
  }
  Encroachment result() const {
    if (best_.second < 0) return {};
    return {-1, best_.second, -best_.first};
  }

 private:
  const std::vector<P3>& points_;
  int a_, b_, c_;
  SearchBall ball_;
  P3 center_;
  double radius_ = 0.0;
  std::pair<double, int> best_{HUGE_VAL, -1};
};

// deepest_encroacher's answer for a simplex no point of index below `from` encroaches: the points from there on,
// through PointIndex::for_each_in's floating-point filter (which misses no point strictly inside).
Encroachment deepest_since(const std::vector<P3>& points, int a, int b, int c, int from, std::size_t* candidates) {
  Deepest deepest(points, a, b, c);
  const SearchBall& ball = deepest.ball();
  const double r2 = ball.radius * ball.radius * (1.0 + 1e-12);
  for (int t = from; t < static_cast<int>(points.size()); ++t) {
    if (t == a || t == b || t == c) continue;
    const P3& p = points[t];
    const double dx = p.x() - ball.center[0], dy = p.y() - ball.center[1], dz = p.z() - ball.center[2];
    if (!ball.everything && dx * dx + dy * dy + dz * dz > r2) continue;
    if (candidates) ++*candidates;
    deepest.offer(t, {});
  }
  return deepest.result();
}

}  // namespace

Encroachment deepest_encroacher(const std::vector<P3>& points, const PointIndex& index, int a, int b, int c,
                                std::size_t* candidates, const std::function<bool(int)>& ignore) {
  Deepest deepest(points, a, b, c);
  index.for_each_in(deepest.ball(), [&](int t) {
    if (t == a || t == b || t == c) return;
    if (candidates) ++*candidates;
    deepest.offer(t, ignore);
  });
  return deepest.result();
}

std::size_t CheckMemo::Hash::operator()(const std::array<int, 3>& k) const {
  return (static_cast<std::size_t>(k[0]) * 1000003u ^ static_cast<std::size_t>(k[1])) * 1000003u ^
         static_cast<std::size_t>(k[2] + 1);
}

// check_gabriel_until forks from this many rows (a row is a kd-tree query and exact predicates, microseconds: the
// thread's start is paid back many times over; fandisk.off's rounds check 6e4 rows).
constexpr std::size_t kForkRows = 4096;

GabrielReport check_gabriel_until(const std::vector<P3>& pts, const std::vector<Triangle>& faces,
                                  const std::vector<Segment>& segments, const std::function<bool()>& out_of_time,
                                  CheckMemo* memo) {
  auto check_index = [&](int v, const char* what, std::size_t row) {
    if (v < 0 || static_cast<std::size_t>(v) >= pts.size())
      throw InvalidInput(std::string(what) + " " + std::to_string(row) + " refers to point " + std::to_string(v) +
                         ", but there are " + std::to_string(pts.size()) + " points");
  };
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (int v : faces[f]) check_index(v, "face", f);
    auto [a, b, c] = faces[f];
    if (CGAL::collinear(pts[a], pts[b], pts[c]))
      throw InvalidInput("face " + std::to_string(f) + " (" + std::to_string(a) + ", " + std::to_string(b) + ", " +
                         std::to_string(c) + ") has collinear corners: no diametral sphere");
  }
  for (std::size_t s = 0; s < segments.size(); ++s) {
    for (int v : segments[s]) check_index(v, "segment", s);
    if (pts[segments[s][0]] == pts[segments[s][1]])
      throw InvalidInput("segment " + std::to_string(s) + " has coincident ends");
  }
  PointIndex index(pts);
  const int n = static_cast<int>(pts.size());
  const std::size_t rows = faces.size() + segments.size();  // the faces' rows, then the segments'
  // The rows run in two halves on two threads from kForkRows rows, each half with its own part of the report. With a
  // memo, a simplex found clean against the points it knew is tested against the points added since only (when
  // they are at most kMemoReach), the same answer; the halves only read the memo (each row keeps where its entry
  // was), and the rows then record in order what they found clean.
  struct Half {
    GabrielReport report;
    std::size_t reached = 0;  // rows [begin, reached) checked: the rest ran out of time
  };
  std::vector<std::array<int, 3>> keys(memo ? rows : 0);
  using Entry = std::unordered_map<std::array<int, 3>, int, CheckMemo::Hash>::iterator;
  std::vector<Entry> entries(memo ? rows : 0);
  if (memo) memo->clean_below.reserve(memo->clean_below.size() + rows);  // no rehash: the entries stay valid
  auto corners = [&](std::size_t r) -> std::array<int, 3> {
    if (r < faces.size()) return {faces[r][0], faces[r][1], faces[r][2]};
    const Segment& g = segments[r - faces.size()];
    return {g[0], g[1], -1};
  };
  auto check = [&](std::size_t begin, std::size_t end, Half& half) {
    for (half.reached = begin; half.reached < end; ++half.reached) {
      if (out_of_time()) return;
      const std::size_t r = half.reached;
      const auto [a, b, c] = corners(r);
      Encroachment e;
      if (!memo) {
        e = deepest_encroacher(pts, index, a, b, c, &half.report.candidates);
      } else {
        std::array<int, 3>& k = keys[r];
        k = {a, b, c};
        if (c < 0) k = {std::min(a, b), std::max(a, b), -1};
        else std::sort(k.begin(), k.end());
        entries[r] = memo->clean_below.find(k);
        const bool known = entries[r] != memo->clean_below.end() && n - entries[r]->second <= kMemoReach;
        e = known ? deepest_since(pts, a, b, c, entries[r]->second, &half.report.candidates)
                  : deepest_encroacher(pts, index, a, b, c, &half.report.candidates);
      }
      if (e.vertex < 0) continue;
      const bool face = r < faces.size();
      (face ? half.report.faces : half.report.segments)
          .push_back({static_cast<int>(face ? r : r - faces.size()), e.vertex, e.depth});
    }
  };
  Half first, second;
  const bool parallel = rows >= kForkRows;
  const std::size_t middle = parallel ? rows / 2 : rows;
  fork_join(parallel, [&] { check(0, middle, first); }, [&] { check(middle, rows, second); });
  GabrielReport report;
  report.candidates = first.report.candidates + second.report.candidates;
  for (const Half* half : {&first, &second}) {
    report.faces.insert(report.faces.end(), half->report.faces.begin(), half->report.faces.end());
    report.segments.insert(report.segments.end(), half->report.segments.begin(), half->report.segments.end());
  }
  // Rows not reached (time_limit): those of the first half from where it stopped, and of the second.
  auto unchecked = [&](std::size_t from, std::size_t to) {
    for (std::size_t r = from; r < to; ++r) ++(r < faces.size() ? report.unchecked_faces : report.unchecked_segments);
  };
  unchecked(first.reached, middle);
  unchecked(second.reached, rows);
  if (memo) {
    std::size_t next_face = 0, next_segment = 0;  // the encroached rows, in row order
    for (std::size_t r = 0; r < rows; ++r) {
      if ((r < middle && r >= first.reached) || r >= second.reached) continue;
      const bool face = r < faces.size();
      const auto& found = face ? report.faces : report.segments;
      std::size_t& next = face ? next_face : next_segment;
      const int row = static_cast<int>(face ? r : r - faces.size());
      if (next < found.size() && found[next].index == row) {
        ++next;
        memo->clean_below.erase(keys[r]);  // (by key: a simplex listed twice would erase its entry twice)
      } else if (entries[r] != memo->clean_below.end()) {
        entries[r]->second = n;
      } else {
        memo->clean_below.emplace(keys[r], n);
      }
    }
  }
  return report;
}

}  // namespace nonobtuse::gabriel3d

namespace nonobtuse {

GabrielReport check_gabriel(const std::vector<Point3>& points, const std::vector<Triangle>& faces,
                            const std::vector<Segment>& segments) {
  using namespace gabriel3d;
  std::vector<P3> pts;
  pts.reserve(points.size());
  for (const auto& p : points) pts.push_back(to_cgal(p));
  return check_gabriel_until(pts, faces, segments, [] { return false; });
}

}  // namespace nonobtuse

