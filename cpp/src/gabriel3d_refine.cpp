// The Refiner's methods (gabriel3d_refiner.h): Ruppert-like Gabriel refinement of a PLC, subsegments first, then
// subfacets, until every diametral sphere is empty.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <tuple>

#include "gabriel3d_refiner.h"
#include "gabriel3d_split_rule.h"

namespace nonobtuse::gabriel3d {

namespace {

// A length for a stop reason: 3 significant digits at any scale (std::to_string printed 1e-9 as 0.000000).
std::string length_text(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

}  // namespace

std::optional<Stop> Refiner::budget_left() const {
  if (steiner_on_segments + steiner_on_facets >= o_.max_steiner)
    return Stop{RefineStatus::BudgetExhausted, "max_steiner (" + std::to_string(o_.max_steiner) + ") reached"};
  if (work_ >= o_.max_work)
    return Stop{RefineStatus::BudgetExhausted, "max_work (" + std::to_string(o_.max_work) + " work units) reached"};
  if (out_of_time())
    return Stop{RefineStatus::BudgetExhausted, "time_limit (" + std::to_string(o_.time_limit) + " s) reached"};
  if (below_floor_)
    return Stop{RefineStatus::MinLengthReached,
                "a split left a subsegment shorter than the first pass's cascade floor (" +
                    length_text(*floor_) + ", 1/1000 of the input's smallest scale)"};
  return std::nullopt;
}

std::vector<Key> Refiner::encroached_subsegments() {
  add_work(s_.subsegments.size());
  return encroached_subsegments_.sorted();
}

std::vector<SubfacetRef> Refiner::encroached_subfacets() const {
  std::vector<SubfacetRef> out;
  for (std::size_t f = 0; f < s_.facets.size(); ++f) {
    const FacetCDT& cdt = s_.facets[f]->cdt;
    for (auto fh = cdt.finite_faces_begin(); fh != cdt.finite_faces_end(); ++fh) {
      if (!fh->info().in_domain) continue;
      int a = fh->vertex(0)->info(), b = fh->vertex(1)->info(), c = fh->vertex(2)->info();
      if (CGAL::collinear(s_.points[a], s_.points[b], s_.points[c])) continue;  // rounding; left to the final check
      if (subfacet_encroached(static_cast<int>(f), a, b, c, &fh->info().scan)) out.push_back(canonical({static_cast<int>(f), a, b, c}));
      if (out_of_time()) return {};  // one facet can hold most subfacets; run() stops after the scan
    }
  }
  // The face order of a triangulation depends on where the walks of point location went (randomized): sort.
  std::sort(out.begin(), out.end());
  return out;
}

std::optional<Stop> Refiner::too_short(const P3& p, const P3& q) const {
  if (o_.min_length > 0 && CGAL::compare_squared_distance(p, q, o_.min_length * o_.min_length) == CGAL::SMALLER)
    return Stop{RefineStatus::MinLengthReached,
                "a split would create an edge shorter than min_length (" + length_text(o_.min_length) + ")"};
  return std::nullopt;
}

std::optional<Stop> Refiner::too_close(const P3& p, int* near) const {
  if (o_.min_length <= 0) return std::nullopt;
  SearchBall ball{{p.x(), p.y(), p.z()}, o_.min_length, false};
  std::optional<Stop> stop;
  index_.for_each_in(ball, [&](int i) {
    if (stop) return;
    stop = too_short(p, s_.points[i]);
    if (stop && near) *near = i;
    if (stop) stop->reason += ": a new point within min_length of vertex " + std::to_string(i);
  });
  return stop;
}

void Refiner::mirror(int m) {
  if (mirror_pairs_.empty() || images_.count(m)) return;
  const std::vector<int> on = s_.point_facets[m];
  for (const MirrorPair& pair : mirror_pairs_) {
    if (std::find(on.begin(), on.end(), pair.from) == on.end() || std::find(on.begin(), on.end(), pair.to) != on.end())
      continue;
    if (budget_left()) return;
    ++work_;
    const auto image = mirrored_point(s_, pair, m);
    if (!image || s_.at.count({image->point.x(), image->point.y(), image->point.z()}) || too_close(image->point) ||
        (protection_ && protection_->strictly_containing(image->point)))
      continue;
    const int id = insert_in_facet(s_, pair.to, image->point, image->lt, image->loc, image->li);
    images_.insert(id);
    // The image of a point on the sphere of a ball at an end of the mirrored segment is on that sphere (the
    // reflection fixes the segment's line): the arc rule treats it as a sphere point (the fan subfacets with it are
    // split on their arcs, arc_split_point). Measured (split="mirrored", fallback limits, spike k=10 on 1..10,
    // 12..30 by 2, 35..85 by 5): 23 -> 24 of 31 angles converge (85 degrees too), none lost; with the refusal in
    // split_subfacet, 28 of 31.
    const InputSegment& seg = s_.segments[pair.segment];
    const bool on_sphere = segment_sphere_points_.count(m) || arc_points_.count(m);
    if (on_sphere && (sphere_of(seg.a, m) > 0 || sphere_of(seg.b, m) > 0)) arc_points_.insert(id);
    ++steiner_on_facets;
    inserted(id);
  }
}

void Refiner::partner(int m, int a, int b) {
  if (needle_.corners.empty()) return;
  // Breadth first over the corners: each segment reached gets one point, the partner of its neighbour's.
  struct Placed {
    int point, a, b, segment;
  };
  std::vector<Placed> queue{{m, a, b, s_.subsegments.at(key(a, m))}};
  std::set<int> reached{queue[0].segment};
  for (std::size_t i = 0; i < queue.size(); ++i)
    for (int index : needle_.of_segment[queue[i].segment])
      for (int side : {0, 1}) {
        const NeedleCorner& corner = needle_.corners[index];
        const Placed x = queue[i];
        if (corner.seg[side] != x.segment || reached.count(corner.seg[1 - side]) || budget_left()) continue;
        work_ += 4;  // the partner's exact sphere checks
        // The walk of point location from the apex crossed every piece of the other segment on the way (a quarter
        // of u.off's run, exact collinearity tests): it starts at an end of a piece whose sphere holds the point.
        const auto nearby = [&](const P3& y) {
          for (const Key& sub : encroached_subsegments_.holding(y))
            if (s_.subsegments.at(sub) == corner.seg[1 - side]) return sub.first;
          return -1;
        };
        const std::optional<PartnerSplit> p = partner_split(s_, corner, side, x.point, x.a, x.b, nearby);
        // The rungs to the points of this chain are about r theta long, under min_length near the corner by
        // design; every other point, and both new subsegments, must respect it.
        if (!p || too_short(s_.points[p->u], p->point) || too_short(p->point, s_.points[p->w])) continue;
        bool near = false;
        index_.for_each_in({{p->point.x(), p->point.y(), p->point.z()}, o_.min_length, false}, [&](int j) {
          near = near || (std::none_of(queue.begin(), queue.end(), [&](const Placed& q) { return q.point == j; }) &&
                          too_short(p->point, s_.points[j]));
        });
        if (near) continue;
        const int id = split_subsegment(s_, p->u, p->w, p->t, p->point);
        ++steiner_on_segments;
        inserted(id, key(p->u, p->w));
        reached.insert(corner.seg[1 - side]);
        queue.push_back({id, p->u, p->w, corner.seg[1 - side]});
      }
}

double Refiner::sphere_of(int v, int m) const {
  for (const auto& ball : protection_->balls())
    if (ball.apex == v)
      return CGAL::compare_squared_distance(s_.points[m], s_.points[v], 4.0 * ball.radius * ball.radius) ==
                     CGAL::SMALLER
                 ? ball.radius
                 : 0.0;
  return 0.0;
}

bool Refiner::protected_piece(const Key& sub) const {
  auto [a, b] = sub;
  return (segment_sphere_points_.count(b) && sphere_of(a, b) > 0) ||
         (segment_sphere_points_.count(a) && sphere_of(b, a) > 0);
}

bool Refiner::below_floor(const P3& a, const P3& b) {
  auto shorter = [&](double length) {
    return CGAL::compare_squared_distance(a, b, length * length) == CGAL::SMALLER;
  };
  if (!(cascade_floor_.bound > 0) || !shorter(cascade_floor_.bound)) return false;
  if (!floor_) floor_ = cascade_floor_.evaluate();
  return *floor_ > 0 && shorter(*floor_);
}

void Refiner::inserted(int m, const std::optional<Key>& split) {
  index_.add(m);
  if (delaunay_) delaunay_->feed(s_.points);
  if (split)
    for (int end : {split->first, split->second})
      below_floor_ = below_floor_ || below_floor(s_.points[m], s_.points[end]);
  encroached_subsegments_.added(m, split);
#ifdef NONOBTUSE_CHECK_INVARIANTS
  check_invariants(s_);
  encroached_subsegments_.check_against_full_scan();
#endif
  long n = steiner_on_segments + steiner_on_facets;
  if (o_.progress && o_.progress_every > 0 && n % o_.progress_every == 0)
    o_.progress({n, last_encroached_segments_, last_encroached_facets_, seconds()});
}

std::optional<Stop> Refiner::split(const Key& sub, bool always, bool* inserted_point, const P3* pending) {
  auto [a, b] = sub;
  // Counted as the encroachment query this set lookup replaces.
  if (!s_.subsegments.count(sub) || (!always && (++work_, !encroached_subsegments_.contains(sub))))
    return std::nullopt;
  if (auto stop = budget_left()) return stop;
  const P3 &pa = s_.points[a], &pb = s_.points[b];
  const bool a_input = a < s_.n_input, b_input = b < s_.n_input;
  std::optional<double> greedy;
  // Greedy keeps the shells rule on subsegments with an end at an input vertex e where two input segments meet at
  // an acute angle: a greedy point x placed beyond the foot of an encroacher v on the other segment [e, v] sees
  // [e, v] at an obtuse angle (it encroaches it) and starts the ping-pong that shells end. Measured on the corpus
  // (experiments/README.md): greedy there too converged on 2 of the 7 inputs shells converges on; shells only on
  // subsegments with exactly one end at an acute input vertex, on 6 (rotor.off ran out of budget).
  const bool acute_end = (a_input && acute_[a]) || (b_input && acute_[b]);
  if (o_.split == SplitRule::Greedy && !acute_end) greedy = greedy_split_parameter(s_, index_, a, b, pending);
  const double t = greedy                              ? *greedy
                   : o_.split == SplitRule::Midpoint ? 0.5
                                                     : shell_cutting_evenly(pa, pb, a_input, b_input);
  const P3 m = interpolate(pa, pb, t);
  if (auto stop = too_short(pa, m)) return stop;
  if (auto stop = too_short(m, pb)) return stop;
  if (s_.at.count({m.x(), m.y(), m.z()}))  // rounding hit an existing vertex: no progress possible here
    return Stop{RefineStatus::Stalled, "the split point of subsegment (" + std::to_string(a) + ", " +
                                            std::to_string(b) + ") rounds onto an existing vertex"};
  const int parent = s_.subsegments.at(sub);
  int id = split_subsegment(s_, a, b, t, m);
  ++steiner_on_segments;
  if (greedy) ++greedy_splits;
  *inserted_point = true;
  inserted(id, sub);
  mirror(id);
  if (stations_) return stations_->grouped(parent) ? place_station(parent, id, {a, b}) : std::nullopt;
  partner(id, a, b);
  return std::nullopt;
}

// Splits subfacet f at its circumcenter, or splits the subsegments that point encroaches or lies beyond.
std::optional<Stop> Refiner::split_subfacet(const SubfacetRef& r, bool require_face, bool* inserted_point) {
  Facet& facet = *s_.facets[r.facet];
  FacetCDT::Face_handle fh;
  auto va = facet.vertex.at(r.a), vb = facet.vertex.at(r.b), vc = facet.vertex.at(r.c);
  if (require_face ? !facet.cdt.is_face(va, vb, vc, fh) || !subfacet_encroached(r.facet, r.a, r.b, r.c)
                   : !encroached(r.a, r.b, r.c))
    return std::nullopt;
  if (!require_face) fh = va->face();
  const std::optional<P3> rounded = rounded_circumcenter(s_.points[r.a], s_.points[r.b], s_.points[r.c]);
  if (!rounded) return std::nullopt;  // refused, as below (collinear after rounding, or beyond double range)
  P3 center = *rounded;
  const ProtectingBall* ball = protection_ ? protection_->strictly_containing(center) : nullptr;
  if (ball && facet.vertex.count(ball->apex)) {
    const std::optional<P3> on_sphere = arc_split_point(s_, facet, *ball, center, segment_sphere_points_, arc_points_);
    if (!on_sphere) return std::nullopt;  // the circumcenter is the apex itself: refused
    center = *on_sphere;
  } else {
    ball = nullptr;
  }
  // A circumcenter that encroaches a subsegment of this facet is not inserted: the subsegments are split instead.
  std::vector<Key> hit = facet_subsegments_holding(r.facet, center);
  // The protected strategy's collar rule (gabriel3d_collar.cpp): onto the one hit subsegment's collar circle.
  const auto held = [&](const P3& y) { return !facet_subsegments_holding(r.facet, y).empty(); };
  if (protection_ && hit.size() == 1)
    if (auto y = facet_collar_point(s_, facet, collared_, hit[0], center, held);
        y && !protection_->strictly_containing(*y))
      center = *y, hit.clear(), ball = nullptr;
  Q2 q = facet.project(center);
  FacetCDT::Locate_type lt;
  int li = 0;
  auto loc = facet.cdt.locate(q, lt, li, fh);
  const bool inside = strictly_in_domain(facet.cdt, lt, loc, li);
  if (hit.empty() && !inside) {
    // Outside the facet (or on its boundary): split the subsegment the circumcenter lies beyond.
    Q2 g = CGAL::centroid(va->point(), vb->point(), vc->point());
    if (auto sub = first_crossed_subsegment(facet, g, q)) {
      // With mirrored meshes, a protected piece [e, x_s] is not split here: its midpoint, r / 2 from e inside the
      // ball, lies strictly inside the diametral sphere of every fan subfacet at e within about 60 degrees of the
      // segment (radius r / (2 cos(phi / 2)) >= r / 2), which breaks (1)-(2) of the arc rule's argument
      // (arc_split_point) and restarts the fans' refinement (measured on spike 65, 10,110 points). The circumcenter
      // is refused instead, the subfacet left to the other splits, the stall handling and the budgets; the exact
      // check of the result decides. Measured with the sphere images above (split="mirrored", fallback limits, the
      // spike's 31 angles): 24 -> 28 of 31 converge (3, 6, 55, 60, 65, 75 gained; 24 lost). The protected strategy
      // keeps the split (the same refusal there moved its cascade to the base edges, experiments/README.md).
      if (!mirror_pairs_.empty() && protected_piece(*sub)) return std::nullopt;
      hit.push_back(*sub);
    }
  }
  if (!hit.empty()) {
    for (const Key& sub : hit)
      if (auto stop = split(sub, true, inserted_point, &center)) return stop;
    return std::nullopt;
  }
  if (!inside || s_.at.count({center.x(), center.y(), center.z()})) return std::nullopt;  // refused; see run()
  if (auto stop = budget_left()) return stop;
  int near = -1;
  if (auto stop = too_close(center, &near)) {
    // A vertex of this facet closer than min_length to the circumcenter and strictly inside the subfacet's
    // circumcircle in the facet's frame (exact): the subfacet is no Delaunay face of the facet, only the rounding
    // of the frame and of Steiner points kept it a face of the 3D Delaunay mesh (repair() meets it: the second
    // face of a cospherical pair whose circumcenter was inserted in an earlier round; measured on mc_two_spheres
    // and mc_gyroid, the vertex sat 2e-16 from the circumcenter of a subfacet of circumradius 4e-3). That is no
    // cascade toward a small feature: the circumcenter is refused (an edge of rounding length otherwise) and the
    // stall handling of refine_with takes over. Any other point that close is a min_length stop.
    const auto it = facet.vertex.find(near);
    if (it != facet.vertex.end() && CGAL::side_of_bounded_circle(va->point(), vb->point(), vc->point(),
                                                                 it->second->point()) == CGAL::ON_BOUNDED_SIDE)
      return std::nullopt;
    // A point moved onto a ball's sphere (arc_split_point) next to an arc point of the same ball: the arc point's
    // cospherical twin (the shells rule makes exactly cocircular trapezoids at small corners, whose two subfacets
    // have the same circumcenter up to rounding; measured on part.off at the 6.4 degree corner of vertex 20, facet
    // 223). Refused like the circumcenter above, not a min_length stop: the protected pass then converges on part.off
    // (4,601 points) instead of ending there and leaving it to the mirrored pass (5,071).
    if (ball && arc_points_.count(near) && sphere_of(ball->apex, near) > 0) return std::nullopt;
    return stop;
  }
  int id = insert_in_facet(s_, r.facet, center, lt, loc, li);
  if (ball) arc_points_.insert(id);
  ++steiner_on_facets;
  *inserted_point = true;
  inserted(id);
  mirror(id);
  return std::nullopt;
}

std::vector<Key> Refiner::facet_subsegments_holding(int f, const P3& p) const {
  std::vector<Key> out = encroached_subsegments_.holding(p);
  out.erase(std::remove_if(out.begin(), out.end(),
                           [&](const Key& sub) {
                             const std::vector<int>& on = s_.segments[s_.subsegments.at(sub)].facets;
                             return std::find(on.begin(), on.end(), f) == on.end();
                           }),
            out.end());
  return out;
}

// Splits every input segment through a protected apex where it leaves the apex's ball
// (split_segments_on_spheres), as subsegment splits counted on segments; with mirrored meshes, then mirrors those
// points. Not before: an image of a sphere point x_s of facet G, across a mirrored segment sigma of G and F through
// the same apex e, lies on e's sphere too (the reflection fixes e), and is refused while sigma is still one input
// segment (its diametral ball holds the image); once every ball has its points, sigma's piece at e is [e, x_sigma]
// and the image goes in. So F's fan at e holds the images of its neighbours' fan points: F's fan subfacet
// (e, x_sigma, y) and G's (e, x_sigma, x_s) are mirror images, and the mirror argument (mirrored_point,
// gabriel3d_mirror.cpp) keeps each out of the other's diametral sphere for any dihedral angle. What it does not
// cover: F's images from a third facet (at a spike corner the base gets the generator's point from both side
// facets, 0.6 degrees apart on the sphere at 80 degrees; they miss the side fans' spheres there, checked by the exact
// test, not by the argument) and the points later rules put in the ball. Measured (split="mirrored", spike k=10 at
// 80 degrees): mirrored as they were placed, the images of the generators' sphere points were all refused and the
// run ended at max_steiner (10,110, of which 9,915 on the base corners' spheres); mirrored afterwards, it converges
// with 157 points. A pass with stations (step.off's rerun, whose mirrored meshes serve its 15.8 and 20.7 degree
// dihedral edges) mirrors them as they are placed, as before: mirrored afterwards, that rerun ends at min_length
// (measured 2026-12-03 on main after the merge of both rules; as placed it converges with 1,910 points).
std::optional<Stop> Refiner::place_protecting_points() {
  std::optional<Stop> stop;
  auto place = [&](int from, int to, double t) {
    const P3 m = interpolate(s_.points[from], s_.points[to], t);
    if (!stop) stop = budget_left();
    if (!stop) stop = too_short(s_.points[from], m);
    if (!stop) stop = too_short(m, s_.points[to]);
    if (stop && stop->status == RefineStatus::MinLengthReached)  // a diagnosable input, not a cascade
      stop->reason += ": where input segment (" + std::to_string(from) + ", " + std::to_string(to) +
                      ") leaves a protecting ball, whose radius (a power of two <= lfs / 4 at its apex) or the rest "
                      "of the segment is below min_length; a smaller min_length lets it through";
    if (stop || s_.at.count({m.x(), m.y(), m.z()})) return -1;
    const int id = split_subsegment(s_, from, to, t, m);
    segment_sphere_points_.insert(id);
    ++steiner_on_segments;
    inserted(id, key(from, to));
    if (stations_) mirror(id);  // as placed: see above
    return id;
  };
  split_segments_on_spheres(s_, protection_->balls(), place, [&] { return !stop; });
  if (!stop && !stations_)
    for (int id : segment_sphere_points_) mirror(id);
  return stop;
}

std::optional<Stop> Refiner::run() {
  for (;;) {
    if (auto stop = budget_left()) return stop;
    bool progress = false;
    // Level 1: subsegments, until none is encroached.
    for (auto subs = encroached_subsegments(); !subs.empty(); subs = encroached_subsegments()) {
      last_encroached_segments_ = static_cast<long>(subs.size());
      bool round_progress = false;
      for (const Key& sub : subs)
        if (auto stop = split(sub, false, &round_progress)) return stop;
      if (!round_progress)
        return Stop{RefineStatus::Stalled, "encroached subsegments remain but none could be split"};
      progress = true;
    }
    last_encroached_segments_ = 0;
    // Level 2: the subfacets found encroached by one scan, each re-checked when its turn comes. Subsegments split
    // on the way (encroached by a circumcenter) get priority again at the next level-1 scan; a rescan after every
    // such split would cost a full pass over the subfacets per Steiner point.
    auto subfacets = encroached_subfacets();
    if (auto stop = budget_left()) return stop;  // (a scan cut short by time_limit is empty)
    last_encroached_facets_ = static_cast<long>(subfacets.size());
    if (subfacets.empty()) return std::nullopt;
    for (const auto& r : subfacets) {
      if (auto stop = budget_left()) return stop;  // refused circumcenters insert nothing but cost a facet walk
      if (auto stop = split_subfacet(r, true, &progress)) return stop;
    }
    if (!progress)  // every encroached subfacet's circumcenter was refused: the same state would repeat forever
      return Stop{RefineStatus::Stalled, "encroached subfacets remain whose circumcenters cannot be inserted"};
  }
}

// Which of the mixes: the corpus outcomes depend on the order (fragile inputs converge with some orders and not
// others); of the offsets 0 .. 8 times the increment measured (experiments/README.md, "repair order"), 3 converged on
// all 30 corpus files by the first or the protected pass.
constexpr std::uint64_t kRepairOrderOffset = 3 * 0x9E3779B97F4A7C15ULL;

std::vector<std::size_t> scattered_order(const std::vector<Triangle>& faces) {
  struct Row {
    std::uint64_t mix;
    Triangle sorted;
    std::size_t index;
  };
  std::vector<Row> rows;
  rows.reserve(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) {
    Triangle t = faces[i];
    std::sort(t.begin(), t.end());
    // splitmix64's finalizer of the three indices packed in 63 bits (21 bits each: a mix, not a key; ties are
    // sorted), offset by a multiple of its golden-ratio increment
    std::uint64_t x = static_cast<std::uint64_t>(t[0]) ^ static_cast<std::uint64_t>(t[1]) << 21 ^
                      static_cast<std::uint64_t>(t[2]) << 42;
    x += kRepairOrderOffset;
    x = (x ^ x >> 30) * 0xBF58476D1CE4E5B9ULL;
    x = (x ^ x >> 27) * 0x94D049BB133111EBULL;
    rows.push_back({x ^ x >> 31, t, i});
  }
  std::sort(rows.begin(), rows.end(),
            [](const Row& p, const Row& q) { return std::tie(p.mix, p.sorted) < std::tie(q.mix, q.sorted); });
  std::vector<std::size_t> order;
  order.reserve(rows.size());
  for (const Row& row : rows) order.push_back(row.index);
  return order;
}

std::optional<Stop> Refiner::repair(const Restricted& mesh, const std::vector<Key>& segments,
                                    const GabrielReport& report, bool* progress) {
  const std::size_t first_new = s_.points.size();
  for (const auto& e : report.segments)
    if (auto stop = split(segments[e.index], false, progress)) return stop;
  // (facet, edge) of the faces split in this pass: the points [first, last) that split inserted
  std::map<std::pair<int, Key>, std::pair<std::size_t, std::size_t>> split_edges;
  std::vector<Triangle> encroached;
  for (const auto& e : report.faces) encroached.push_back(mesh.boundary_faces[e.index]);
  for (std::size_t e : scattered_order(encroached)) {
    if (auto stop = budget_left()) return stop;
    const int row = report.faces[e].index;
    auto [a, b, c] = mesh.boundary_faces[row];
    // A face with a Steiner point of this pass on its facet strictly inside its diametral sphere is left to the
    // next round's Delaunay mesh, where it is usually gone. Cospherical faces (four points on a circle of a facet,
    // both diagonals' faces in the report) share one circumcenter: splitting the second one too put its rounded
    // circumcenter an ulp or two from the first (measured: 19 such pairs on gc_spot.ply, edges of 1e-17).
    const int f = mesh.face_facets[row];
    bool pierced = false;
    for (std::size_t i = first_new; i < s_.points.size() && !pierced; ++i)
      pierced = s_.point_facets[i] == std::vector<int>{f} &&
                CGAL::side_of_bounded_sphere(s_.points[a], s_.points[b], s_.points[c], s_.points[i]) ==
                    CGAL::ON_BOUNDED_SIDE;
    if (pierced) continue;
    // With stations: the twin of a face split in this pass (same facet, an edge in common) with a point of that
    // split strictly inside its diametral sphere is left to the next round too. Near-cocircular quads give two
    // faces of about the same circumcenter, each encroached by the other's fourth vertex; their circumcenters hit
    // grouped segments, whose station points are not this facet's alone (so not caught above), and splitting both
    // doubled the encroached faces every round (step.off's protected rerun, facet 12, with most repair orders).
    // Measured without stations too: anchor.off and rotor.off took 20% more points, so only here.
    bool twin = false;
    if (stations_)
      for (const Key& edge : {key(a, b), key(b, c), key(c, a)})
        if (auto it = split_edges.find({f, edge}); it != split_edges.end())
          for (std::size_t i = it->second.first; i < it->second.second && !twin; ++i)
            twin = CGAL::side_of_bounded_sphere(s_.points[a], s_.points[b], s_.points[c], s_.points[i]) ==
                   CGAL::ON_BOUNDED_SIDE;
    if (twin) continue;
    const std::size_t before = s_.points.size();
    if (auto stop = split_subfacet(canonical({f, a, b, c}), false, progress)) return stop;
    if (stations_ && s_.points.size() > before)
      for (const Key& edge : {key(a, b), key(b, c), key(c, a)}) split_edges[{f, edge}] = {before, s_.points.size()};
  }
  return std::nullopt;
}


}  // namespace nonobtuse::gabriel3d
