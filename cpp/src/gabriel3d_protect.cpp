// Protecting balls at apex vertices: their sizes (from the local feature size), the lookup by point, where segments
// leave them and where split points inside them go (the protected strategy's split rule).
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


double power_of_two_piece(double size) {
  double piece = 1.0;
  while (size > 3.0 * piece) piece *= 2.0;
  while (size < 1.5 * piece) piece *= 0.5;
  return piece;
}

void split_segments_on_spheres(const PlcState& s, const std::vector<ProtectingBall>& balls,
                               const std::function<int(int from, int to, double t)>& place,
                               const std::function<bool()>& keep_going) {
  // Each point is the interpolation a + t (b - a) rounded to doubles, like every subsegment split; the exact
  // predicates then decide on the rounded coordinates.
  std::vector<double> radius(s.n_input, 0.0);
  for (const auto& ball : balls) radius[ball.apex] = ball.radius;
  auto length = [&](int a, int b) {
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(s.points[a], s.points[b])));
  };
  for (std::size_t g = 0; g < s.segments.size() && keep_going(); ++g) {
    int a = s.segments[g].a;
    const int b = s.segments[g].b;  // before any split, the input segment is one subsegment
    if (radius[a] > 0)
      if (int id = place(a, b, radius[a] / length(a, b)); id >= 0) a = id;
    if (radius[b] > 0 && keep_going()) place(a, b, 1.0 - radius[b] / length(a, b));
  }
}

// The protected strategy's split rule: a split point c strictly inside the protecting ball B (radius r) of an apex e
// on this facet is moved to B's sphere. When the fan subfacet (e, p, q) of the facet whose angle at e holds c has
// both p and q on the sphere, the point goes on the arc from p to q at angle a from one end ("angular shells"): from
// p when only p is where a segment leaves B, a the power of two (radians) that cuts the arc's angle phi most evenly;
// from q likewise; else a = phi / 2. Otherwise (an edge from e to a point outside B) c moves along the ray from e.
// Termination argument. Inside B lie only e, the point x_s where each segment s through e leaves B
// (split_segments_on_spheres) and these arc points, all on the sphere (to rounding), since the radius (lfs(e) / 4)
// keeps every feature that misses e out of B and no other rule inserts inside B. (1) A protected subsegment [e, x_s]
// is never encroached: its diametral ball lies in B and meets the sphere only at x_s, and a point y with
// |y - e| = r is strictly inside it iff cos angle(y - e, x_s - e) > 1 (the concentric-shells argument): never.
// (2) A fan subfacet (e, p, q) with p, q on the sphere at angle phi < 120 degrees has its diametral sphere centred
// in the facet on the bisector b at r / (2 cos(phi / 2)) < r from e: a point y of the sphere encroaches it iff
// angle(y - e, b) < phi / 2, a point at distance d > r from e only if d < r / cos(phi / 2). Its circumcenter is in B,
// so it is split on its arc. A sphere point y at angular distance eta > 0 from the arc stops encroaching once the
// arc's pieces are below 2 eta, a point at distance d once they are below 2 acos(r / d): each encroacher causes
// finitely many arc points. The one exception is the ping-pong of two facets F, G through a segment s at a small
// dihedral angle: their sphere points near x_s are close in angle to each other's arcs. The angular shells end it as
// concentric shells end it on segments: the first pieces of F's and G's arcs at x_s both end at powers of two
// 2^k from x_s, and a point of G at angle 2^k from x_s is at angular distance > 2^(k-1) (strictly, for a dihedral
// angle > 0: cos dist = cos 2^k cos 2^(k-1) + sin 2^k sin 2^(k-1) cos delta < cos 2^(k-1)) from the bisector of
// F's piece [0, 2^k]: no encroachment once both pieces reach the same shell. (3) Outside the balls, a segment
// through e and a facet through e that it leans over are at least r sin(theta) apart, and features that do not meet
// are lfs apart: a subsegment or subfacet there encroached by a point of such a feature has a diametral radius at
// least that gap, so these splits are bounded by a positive size and the cascade down a segment-facet angle, which
// concentric shells alone run to the floating-point resolution, cannot start. Not covered: chains outside the
// balls through facets meeting along a segment at a small dihedral angle: the segment collars take the facet points
// near such segments (gabriel3d_collar.cpp, with what they leave open); the budgets end what remains, and the exact
// check of the result decides the status.
// (4) A c within rounding of e (noisy_direction: its direction from e is noise) is refused, as c == e is: nothing is
// inserted, so (1)-(3) hold as stated; a subfacet left encroached that way ends the run (stalled or a budget), and
// the exact check of the result decides the status.
std::optional<P3> arc_split_point(const PlcState& s, const Facet& facet, const ProtectingBall& ball, const P3& c,
                                  const std::set<int>& segment_sphere_points, const std::set<int>& arc_points) {
  const P3& e = s.points[ball.apex];
  // c at (or within rounding of: noisy_direction) the apex: its direction from e is then rounding noise, as at a
  // collar's midpoint (gabriel3d_collar.cpp), and the point moved along it can leave the facet's plane by up to r.
  // It happens: a subfacet of three sphere points has e as its circumcenter up to the rounding of those points
  // (measured on spike 80 with split="mirrored": |c - e| = 7e-14 r and 3e-13 r). Refused like c == e.
  if (noisy_direction(e, c, ball.radius)) return std::nullopt;
  const auto ve = facet.vertex.at(ball.apex);
  const Q2 qc = facet.project(c), &qe = ve->point();
  auto on_sphere = [&](int v) { return segment_sphere_points.count(v) || arc_points.count(v); };
  auto fc = facet.cdt.incident_faces(ve), done = fc;
  do {
    if (facet.cdt.is_infinite(fc) || !fc->info().in_domain) continue;
    const int i = fc->index(ve);
    const auto vp = fc->vertex(FacetCDT::ccw(i)), vq = fc->vertex(FacetCDT::cw(i));  // (e, p, q) counter-clockwise
    if (CGAL::orientation(qe, vp->point(), qc) == CGAL::RIGHT_TURN ||
        CGAL::orientation(qe, vq->point(), qc) == CGAL::LEFT_TURN)
      continue;  // c's direction is not in this subfacet's angle at e
    int p = vp->info(), q = vq->info();
    if (!on_sphere(p) || !on_sphere(q)) break;
    if (!segment_sphere_points.count(p) && segment_sphere_points.count(q)) std::swap(p, q);
    const K::Vector_3 wp = s.points[p] - e, wq = s.points[q] - e;
    const double lp = std::sqrt(CGAL::to_double(wp.squared_length()));
    const K::Vector_3 w = wp / lp;
    const K::Vector_3 across = wq - w * CGAL::to_double(wq * w);  // the part of q - e orthogonal to w
    const double la = std::sqrt(CGAL::to_double(across.squared_length()));
    const double phi = std::atan2(la, CGAL::to_double(wq * w));
    const bool dyadic = segment_sphere_points.count(p) && !segment_sphere_points.count(q);
    const double a = dyadic ? power_of_two_piece(phi) : 0.5 * phi;
    return e + (w * std::cos(a) + across * (std::sin(a) / la)) * ball.radius;
  } while (++fc != done);
  return onto_sphere(e, ball.radius, c);
}

}  // namespace nonobtuse::gabriel3d
