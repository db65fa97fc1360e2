// The boundary of an interior refinement, split for circumcenters that encroach it (see quality3d_boundary.h).
#include "quality3d_boundary.h"

#include <algorithm>

#include "gabriel3d_collar.h"

namespace nonobtuse::quality3d {
namespace {

using gabriel3d::FacetCDT;
using gabriel3d::Key;

PLC3 surface_plc(const std::vector<Point3>& points, const std::vector<Triangle>& faces,
                 const std::vector<int>& face_facets, const std::vector<Segment>& segments) {
  PLC3 plc;
  plc.points = points;
  plc.triangles = faces;
  plc.facet_ids = face_facets;
  plc.segments = segments;
  return plc;
}

P3 midpoint(const P3& a, const P3& b) {
  return P3(a.x() + 0.5 * (b.x() - a.x()), a.y() + 0.5 * (b.y() - a.y()), a.z() + 0.5 * (b.z() - a.z()));
}

// The points of a list from index `from` on, indexed: is one of them strictly inside the diametral sphere of ab
// (c null) or of triangle abc? (exact)
class FreshPoints {
 public:
  FreshPoints(const std::vector<P3>& points, std::size_t from)
      : pts_(points.begin() + from, points.end()), index_(pts_) {}
  bool inside(const P3& a, const P3& b, const P3* c) const {
    bool hit = false;
    index_.for_each_in(c ? gabriel3d::search_ball(a, b, *c) : gabriel3d::search_ball(a, b), [&](int t) {
      if (hit) return;
      const CGAL::Bounded_side side =
          c ? CGAL::side_of_bounded_sphere(a, b, *c, pts_[t]) : CGAL::side_of_bounded_sphere(a, b, pts_[t]);
      hit = side == CGAL::ON_BOUNDED_SIDE;
    });
    return hit;
  }

 private:
  std::vector<P3> pts_;
  gabriel3d::PointIndex index_;
};

}  // namespace

BoundarySplitter::BoundarySplitter(const std::vector<Point3>& points, const std::vector<Triangle>& faces,
                                   const std::vector<int>& face_facets, const std::vector<Segment>& segments,
                                   double min_length, long long max_points, double sharp_dihedral,
                                   double small_apex, double volume_sharp)
    : s_(gabriel3d::build_plc_state(surface_plc(points, faces, face_facets, segments))),
      index_(s_.points),
      balls_(s_.points),
      min_length_(min_length),
      max_points_(max_points),
      features_(s_, sharp_dihedral, small_apex),
      volume_features_(s_, std::min(sharp_dihedral, volume_sharp), std::min(small_apex, volume_sharp)) {
  for (const auto& [k, parent] : s_.subsegments) balls_.add(k);
  subs_from_ = faces_from_ = s_.points.size();
}

void BoundarySplitter::add_interior_point(const P3& p) {
  const int i = static_cast<int>(s_.points.size());
  s_.points.push_back(p);
  s_.point_facets.emplace_back();
  s_.at.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, i);
  index_.add(i);
  features_.added(i, 0);
  volume_features_.added(i, 0);
}

int BoundarySplitter::common_facet(int a, int b, int c) const {
  for (int f : s_.point_facets[a])
    if (std::count(s_.point_facets[b].begin(), s_.point_facets[b].end(), f) &&
        std::count(s_.point_facets[c].begin(), s_.point_facets[c].end(), f))
      return f;
  return -1;
}

bool BoundarySplitter::on_one_facet(const std::array<int, 4>& p) const {
  for (int f : s_.point_facets[p[0]])
    if (std::all_of(p.begin() + 1, p.end(), [&](int v) {
          return std::count(s_.point_facets[v].begin(), s_.point_facets[v].end(), f) > 0;
        }))
      return true;
  return false;
}

void BoundarySplitter::subfacets(std::vector<Triangle>& faces, std::vector<int>& facets) const {
  std::vector<std::pair<Triangle, int>> rows;
  for (std::size_t f = 0; f < s_.facets.size(); ++f) {
    const FacetCDT& cdt = s_.facets[f]->cdt;
    for (auto fh = cdt.finite_faces_begin(); fh != cdt.finite_faces_end(); ++fh)
      if (fh->info().in_domain)
        rows.push_back({{fh->vertex(0)->info(), fh->vertex(1)->info(), fh->vertex(2)->info()}, static_cast<int>(f)});
  }
  // The face order of a triangulation depends on its history of walks: sorted, with each row's smallest corner
  // first (the orientation kept).
  for (auto& [t, f] : rows) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::sort(rows.begin(), rows.end());
  faces.clear();
  facets.clear();
  for (const auto& [t, f] : rows) faces.push_back(t), facets.push_back(f);
}

std::vector<Segment> BoundarySplitter::subsegments() const {
  std::vector<Segment> out;
  for (const auto& [k, parent] : s_.subsegments) out.push_back({k.first, k.second});
  return out;
}

bool BoundarySplitter::encroached(int a, int b, int c) const {
  return gabriel3d::deepest_encroacher(s_.points, index_, a, b, c).vertex >= 0;
}

// A split point is refused when it is an existing point, closer than min_length to one, or over the budget: the
// circumcenter that asked for it stays blocked (counted), and the exact check of the result decides.
bool BoundarySplitter::may_add(const P3& p) {
  bool ok = added < max_points_ && (step_end_ < 0 || added < step_end_) && !s_.at.count({p.x(), p.y(), p.z()});
  if (ok && min_length_ > 0) {
    gabriel3d::SearchBall ball{{p.x(), p.y(), p.z()}, min_length_, false};
    index_.for_each_in(ball, [&](int i) {
      ok = ok && CGAL::compare_squared_distance(p, s_.points[i], min_length_ * min_length_) != CGAL::SMALLER;
    });
  }
  refused += !ok;
  return ok;
}

void BoundarySplitter::added_point(int i, char sharp, char volume_sharp) {
  index_.add(i);
  features_.added(i, sharp);
  volume_features_.added(i, volume_sharp);
  hits_.clear();  // a split changes the subsegments
  ++added;
}

bool BoundarySplitter::near_small_angle(int f, int a, int b, int c, double shortest, bool over_volume) const {
  const SharpFeatures& features = over_volume ? volume_features_ : features_;
  const double limit = shortest * shortest;
  auto short_halves = [&](int u, int w) {  // |uw| / 2 < shortest
    return CGAL::compare_squared_distance(s_.points[u], s_.points[w], 4 * limit) == CGAL::SMALLER;
  };
  auto sharp_split = [&](int u, int w) {  // the subsegment is sharp and its midpoint protected
    return features.sharp_subsegment(s_, u, w) &&
           features.protects(s_, midpoint(s_.points[std::min(u, w)], s_.points[std::max(u, w)]));
  };
  if (f < 0) return sharp_split(a, b) || short_halves(a, b);
  int corner[3] = {a, b, c};  // sorted, as split_subfacet rounds the circumcenter
  std::sort(corner, corner + 3);
  const auto center = gabriel3d::rounded_circumcenter(s_.points[corner[0]], s_.points[corner[1]],
                                                      s_.points[corner[2]]);
  if (!center) return false;
  const std::vector<Key>& hit = encroached_subsegments(f, *center);
  if (!hit.empty())
    return std::any_of(hit.begin(), hit.end(), [&](const Key& k) {
      return sharp_split(k.first, k.second) || short_halves(k.first, k.second);
    });
  return ((features.sharp_point(a) || features.sharp_point(b) || features.sharp_point(c)) &&
          features.protects(s_, *center)) ||
         CGAL::compare_squared_distance(*center, s_.points[a], limit) == CGAL::SMALLER;
}

bool BoundarySplitter::leaves_alone(int row, const std::vector<Triangle>& faces, const std::vector<Segment>& segments,
                                    double shortest, bool over_volume) const {
  if (row < 0) return near_small_angle(-1, segments[-1 - row][0], segments[-1 - row][1], -1, shortest, over_volume);
  const auto [a, b, c] = faces[row];
  const int f = common_facet(a, b, c);
  return f >= 0 && near_small_angle(f, a, b, c, shortest, over_volume);
}

bool BoundarySplitter::split_subsegment(int a, int b) {
  if (a > b) std::swap(a, b);  // the rounded midpoint does not depend on the order
  const P3 m = midpoint(s_.points[a], s_.points[b]);
  if (!may_add(m)) return false;
  const char sharp = features_.midpoint_mark(s_, a, b), volume_sharp = volume_features_.midpoint_mark(s_, a, b);
  const int i = gabriel3d::split_subsegment(s_, a, b, 0.5, m);
  balls_.remove(gabriel3d::key(a, b));
  balls_.add(gabriel3d::key(a, i));
  balls_.add(gabriel3d::key(i, b));
  added_point(i, sharp, volume_sharp);
  return true;
}

const std::vector<Key>& BoundarySplitter::encroached_subsegments(int f, const P3& z) const {
  auto [cached, fresh] = hits_.try_emplace({f, z.x(), z.y(), z.z()});
  if (!fresh) return cached->second;
  std::vector<Key> hit;
  balls_.for_each_near(z, [&](const Key& k) {
    const std::vector<int>& on = s_.segments[s_.subsegments.at(k)].facets;
    if (std::find(on.begin(), on.end(), f) != on.end() &&
        CGAL::side_of_bounded_sphere(s_.points[k.first], s_.points[k.second], z) == CGAL::ON_BOUNDED_SIDE)
      hit.push_back(k);
  });
  std::sort(hit.begin(), hit.end());
  return cached->second = std::move(hit);
}

bool BoundarySplitter::split_subfacet(int f, int a, int b, int c) {
  int corner[3] = {a, b, c};  // sorted: the rounded circumcenter does not depend on the order
  std::sort(corner, corner + 3);
  a = corner[0], b = corner[1], c = corner[2];
  const auto center = gabriel3d::rounded_circumcenter(s_.points[a], s_.points[b], s_.points[c]);
  if (!center) return false;
  const gabriel3d::Facet& facet = *s_.facets[f];
  // Shewchuk's rule: a subfacet circumcenter strictly inside a subsegment's diametral sphere is not inserted; the
  // subsegments of the facet it encroaches are split instead.
  const std::vector<Key> hit = encroached_subsegments(f, *center);  // a copy: the splits clear the cache
  if (!hit.empty()) {
    bool any = false;
    for (const Key& k : hit) any = split_subsegment(k.first, k.second) || any;
    return any;
  }
  // With no subsegment encroached, the circumcenter of a subfacet lies in its facet (Ruppert's lemma, in the facet's
  // plane); outside it only through rounding or cocircular points: refused then.
  FacetCDT::Locate_type lt;
  int li = 0;
  auto loc = facet.cdt.locate(facet.project(*center), lt, li, facet.vertex.at(a)->face());
  const bool inside = (lt == FacetCDT::FACE && loc->info().in_domain) ||
                      (lt == FacetCDT::EDGE && !facet.cdt.is_constrained({loc, li}) && loc->info().in_domain &&
                       loc->neighbor(li)->info().in_domain);
  if (!inside) {
    ++refused;
    return false;
  }
  if (!may_add(*center)) return false;
  added_point(gabriel3d::insert_in_facet(s_, f, *center, lt, loc, li), 0, 0);
  return true;
}

long BoundarySplitter::follow(const std::function<bool(int, int, int)>& is_face) {
  long missing = 0;
  for (auto& facet : s_.facets) {
    FacetCDT& cdt = facet->cdt;
    auto face_of = [&](FacetCDT::Face_handle fh) {
      return is_face(fh->vertex(0)->info(), fh->vertex(1)->info(), fh->vertex(2)->info());
    };
    // Each flip turns two subfacets into two faces of the tetrahedralization, so the loop ends.
    for (bool flipped = true; flipped;) {
      flipped = false;
      for (auto fh = cdt.finite_faces_begin(); fh != cdt.finite_faces_end() && !flipped; ++fh) {
        if (!fh->info().in_domain || face_of(fh)) continue;
        for (int i = 0; i < 3 && !flipped; ++i) {
          FacetCDT::Face_handle f = fh, g = fh->neighbor(i);
          if (cdt.is_constrained({f, i}) || cdt.is_infinite(g) || !g->info().in_domain) continue;
          const auto p = f->vertex(i), u = f->vertex(FacetCDT::cw(i)), w = f->vertex(FacetCDT::ccw(i));
          const auto q = g->vertex(g->index(f));
          // the quadrilateral p u q w is strictly convex in the frame (exact): the flip is valid
          const bool convex = CGAL::orientation(p->point(), q->point(), u->point()) ==
                                  -CGAL::orientation(p->point(), q->point(), w->point()) &&
                              CGAL::orientation(u->point(), w->point(), p->point()) ==
                                  -CGAL::orientation(u->point(), w->point(), q->point()) &&
                              !CGAL::collinear(p->point(), q->point(), u->point()) &&
                              !CGAL::collinear(u->point(), w->point(), p->point());
          if (!convex || !is_face(p->info(), q->info(), u->info()) || !is_face(p->info(), q->info(), w->info()))
            continue;
          cdt.flip(f, i);
          flipped = true;
        }
      }
    }
    for (auto fh = cdt.finite_faces_begin(); fh != cdt.finite_faces_end(); ++fh)
      missing += fh->info().in_domain && !face_of(fh);
  }
  return missing;
}

bool BoundarySplitter::restore_gabriel(const std::function<bool()>& stop) {
  for (;;) {
    // Level 1: subsegments, until none is encroached.
    for (;;) {
      const FreshPoints fresh(s_.points, subs_from_);
      std::vector<Key> subs, free;
      for (const auto& [k, parent] : s_.subsegments) {
        const bool hit = std::binary_search(free_subs_.begin(), free_subs_.end(), k)
                             ? fresh.inside(s_.points[k.first], s_.points[k.second], nullptr)
                             : encroached(k.first, k.second, -1);
        (hit ? subs : free).push_back(k);  // in key order: sorted
      }
      free_subs_ = std::move(free);
      subs_from_ = s_.points.size();
      if (subs.empty()) break;
      for (const Key& k : subs)
        if (stop() || !split_subsegment(k.first, k.second)) return false;
    }
    // Level 2: the subfacets one scan finds encroached, each split when its turn comes if it is still a face.
    const FreshPoints fresh(s_.points, faces_from_);
    std::vector<std::array<int, 4>> found, free;  // facet, corners
    for (std::size_t f = 0; f < s_.facets.size(); ++f) {
      const FacetCDT& cdt = s_.facets[f]->cdt;
      for (auto fh = cdt.finite_faces_begin(); fh != cdt.finite_faces_end(); ++fh) {
        if (!fh->info().in_domain) continue;
        std::array<int, 4> r{static_cast<int>(f), fh->vertex(0)->info(), fh->vertex(1)->info(), fh->vertex(2)->info()};
        std::sort(r.begin() + 1, r.end());
        const P3 &a = s_.points[r[1]], &b = s_.points[r[2]], &c = s_.points[r[3]];
        if (CGAL::collinear(a, b, c)) continue;
        const bool hit = std::binary_search(free_faces_.begin(), free_faces_.end(), r) ? fresh.inside(a, b, &c)
                                                                                      : encroached(r[1], r[2], r[3]);
        (hit ? found : free).push_back(r);
      }
    }
    std::sort(free.begin(), free.end());
    free_faces_ = std::move(free);
    faces_from_ = s_.points.size();
    if (found.empty()) return true;
    std::sort(found.begin(), found.end());
    for (const auto& [f, a, b, c] : found) {
      const gabriel3d::Facet& facet = *s_.facets[f];
      FacetCDT::Face_handle fh;
      if (!facet.cdt.is_face(facet.vertex.at(a), facet.vertex.at(b), facet.vertex.at(c), fh) || !encroached(a, b, c))
        continue;  // split already, or no longer encroached
      if (stop() || !split_subfacet(f, a, b, c)) return false;
    }
  }
}

}  // namespace nonobtuse::quality3d
