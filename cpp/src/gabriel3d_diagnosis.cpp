// Diagnosis of a Gabriel refinement: the small input angles that drive it and where its Steiner points went.
// Angles are floating point: they explain a run, they decide nothing.
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "gabriel3d_plc.h"

namespace nonobtuse::gabriel3d {
namespace {

constexpr std::size_t kFew = 5;
constexpr double kDegrees = 180.0 / 3.14159265358979323846;

using Vec = std::array<double, 3>;
Vec sub(const P3& a, const P3& b) { return {a.x() - b.x(), a.y() - b.y(), a.z() - b.z()}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double angle(const Vec& a, const Vec& b) {  // in [0, 180]
  return std::atan2(std::sqrt(dot(cross(a, b), cross(a, b))), dot(a, b)) * kDegrees;
}
Vec normal(const Facet& f) { return cross(f.u, f.v); }

// Appends the kFew smallest angles of one kind, ties in input order (as a stable sort would list them first).
void keep_smallest(std::vector<InputAngle>& all, std::vector<InputAngle>&& kind) {
  std::vector<std::size_t> order(kind.size());
  std::iota(order.begin(), order.end(), 0);
  const auto few = order.begin() + static_cast<std::ptrdiff_t>(std::min(kFew, order.size()));
  std::partial_sort(order.begin(), few, order.end(), [&](std::size_t x, std::size_t y) {
    return kind[x].degrees < kind[y].degrees || (kind[x].degrees == kind[y].degrees && x < y);
  });
  for (auto it = order.begin(); it != few; ++it) all.push_back(std::move(kind[*it]));
}

// The input segments at each input vertex.
std::vector<std::vector<int>> segments_at(const PlcState& s) {
  std::vector<std::vector<int>> at(s.n_input);
  for (std::size_t g = 0; g < s.segments.size(); ++g) {
    at[s.segments[g].a].push_back(static_cast<int>(g));
    at[s.segments[g].b].push_back(static_cast<int>(g));
  }
  return at;
}

// Angles between input segments (PLC segments and facet edges) at their shared input vertices.
std::vector<InputAngle> segment_segment(const PlcState& s, const std::vector<std::vector<int>>& at) {
  std::vector<InputAngle> out;
  for (int v = 0; v < s.n_input; ++v)
    for (std::size_t i = 0; i < at[v].size(); ++i)
      for (std::size_t j = i + 1; j < at[v].size(); ++j) {
        const auto &si = s.segments[at[v][i]], &sj = s.segments[at[v][j]];
        int a = si.a == v ? si.b : si.a, b = sj.a == v ? sj.b : sj.a;
        double deg = angle(sub(s.points[a], s.points[v]), sub(s.points[b], s.points[v]));
        out.push_back({"segment-segment", deg, {v, a, b}, {}});
      }
  return out;
}

// CGAL::to_double(p.x()) (k == 0) or of p.y(): the steps of Lazy_exact_nt's To_double on the point's
// approximation, which is the coordinate's, without constructing the coordinate's lazy number (an allocation and
// a release each: most of points_into's time); where that interval is too wide, through the coordinate as before.
double to_double(const Q2& p, int k) {
  const CGAL::Interval_nt<false>& i = k == 0 ? CGAL::approx(p).x() : CGAL::approx(p).y();
  double r;
  if (CGAL::fit_in_double(i, r)) return r;
  if (CGAL::has_smaller_relative_precision(i, EK::FT::get_relative_precision_of_to_double()))
    return CGAL::to_double(i);
  return CGAL::to_double(k == 0 ? p.x() : p.y());
}

// Does the direction d from facet vertex v, projected onto the facet's plane, point into the facet (into one of
// its domain triangles at v)? Floating point: a diagnosis.
bool points_into(const Facet& f, int v, const Vec& d) {
  auto vh = f.vertex.at(v);
  const Q2& o = vh->point();
  double ox = to_double(o, 0), oy = to_double(o, 1);
  double dx = dot(d, f.u), dy = dot(d, f.v);
  auto turn = [&](const Q2& p) {  // cross(p - o, d): positive when d is counter-clockwise from p - o
    return (to_double(p, 0) - ox) * dy - (to_double(p, 1) - oy) * dx;
  };
  auto fc = f.cdt.incident_faces(vh), done = fc;
  do {
    if (f.cdt.is_infinite(fc) || !fc->info().in_domain) continue;
    int i = fc->index(vh);
    const Q2 &p = fc->vertex(FacetCDT::ccw(i))->point(), &q = fc->vertex(FacetCDT::cw(i))->point();
    // d inside the angle from p - o (included) to q - o (excluded), ccw: a direction along an edge between two
    // domain triangles counts once (a cone's generator over a regular polygon's fan diagonal does).
    const bool along_p = turn(p) == 0 && (to_double(p, 0) - ox) * dx + (to_double(p, 1) - oy) * dy > 0;
    if ((turn(p) > 0 || along_p) && turn(q) < 0) return true;
  } while (++fc != done);
  return false;
}

// The facet's corner opposite edge ab in one of its input triangles: a vertex of the facet's triangulation
// adjacent to both a and b on the domain side.
int apex(const Facet& f, int a, int b) {
  FacetCDT::Face_handle fh;
  int i = 0;
  if (!f.cdt.is_edge(f.vertex.at(a), f.vertex.at(b), fh, i)) return -1;
  for (auto g : {fh, fh->neighbor(i)})
    if (!f.cdt.is_infinite(g) && g->info().in_domain) return g->vertex(g == fh ? i : g->index(fh))->info();
  return -1;
}

std::vector<SteinerCount> top(std::vector<SteinerCount> counts) {
  counts.erase(std::remove_if(counts.begin(), counts.end(), [](const auto& c) { return c.count == 0; }),
               counts.end());
  std::stable_sort(counts.begin(), counts.end(), [](const auto& x, const auto& y) { return x.count > y.count; });
  if (counts.size() > kFew) counts.resize(kFew);
  return counts;
}

// Calls emit(angle) for every segment-facet angle (see segment_facet_angles) unless skip(its degrees); the facet's
// domain test (points_into, most of the cost) runs only for the angles not skipped.
template <class Skip, class Emit>
void for_each_segment_facet_angle(const PlcState& s, Skip&& skip, Emit&& emit) {
  const auto at = segments_at(s);
  for (int v = 0; v < s.n_input; ++v)
    for (int g : at[v]) {
      const auto& seg = s.segments[g];
      int end = seg.a == v ? seg.b : seg.a;
      Vec d = sub(s.points[end], s.points[v]);
      for (int f : s.point_facets[v]) {
        const Facet& facet = *s.facets[f];
        if (facet.vertex.count(end)) continue;
        double deg = std::abs(90.0 - angle(d, normal(facet)));
        if (skip(deg) || !points_into(facet, v, d)) continue;
        emit(InputAngle{"segment-facet", deg, {v, end}, {facet.id}});
      }
    }
}

}  // namespace

// Dihedral angles between facets sharing an input segment (angle between the two half-planes).
std::vector<InputAngle> dihedral_angles(const PlcState& s) {
  std::vector<InputAngle> out;
  for (const auto& seg : s.segments) {
    Vec e = sub(s.points[seg.b], s.points[seg.a]);
    for (std::size_t i = 0; i < seg.facets.size(); ++i)
      for (std::size_t j = i + 1; j < seg.facets.size(); ++j) {
        int p = apex(*s.facets[seg.facets[i]], seg.a, seg.b), q = apex(*s.facets[seg.facets[j]], seg.a, seg.b);
        if (p < 0 || q < 0) continue;
        Vec wp = cross(e, cross(sub(s.points[p], s.points[seg.a]), e));  // components orthogonal to e
        Vec wq = cross(e, cross(sub(s.points[q], s.points[seg.a]), e));
        out.push_back({"dihedral", angle(wp, wq), {seg.a, seg.b},
                       {s.facets[seg.facets[i]]->id, s.facets[seg.facets[j]]->id}});
      }
  }
  return out;
}

// Angles between an input segment and a facet through one of its ends, where the segment leans over the facet
// (its projection points into the facet); other directions are covered by the segment-segment angles.
std::vector<InputAngle> segment_facet_angles(const PlcState& s) {
  std::vector<InputAngle> out;
  for_each_segment_facet_angle(s, [](double) { return false; }, [&](InputAngle&& a) { out.push_back(std::move(a)); });
  return out;
}

std::vector<InputAngle> smallest_input_angles(const PlcState& s) {
  std::vector<InputAngle> out;
  keep_smallest(out, segment_segment(s, segments_at(s)));
  // Only the kFew smallest segment-facet angles are kept, ties in input order: an angle no smaller than the
  // kFew-th smallest of those listed before it cannot be among them, and skips the domain test.
  std::vector<InputAngle> segment_facet;
  std::vector<double> few;  // the kFew smallest degrees listed so far, ascending
  auto skip = [&](double deg) { return few.size() == kFew && deg >= few.back(); };
  for_each_segment_facet_angle(s, skip, [&](InputAngle&& a) {
    few.insert(std::upper_bound(few.begin(), few.end(), a.degrees), a.degrees);
    if (few.size() > kFew) few.pop_back();
    segment_facet.push_back(std::move(a));
  });
  keep_smallest(out, std::move(segment_facet));
  keep_smallest(out, dihedral_angles(s));
  std::stable_sort(out.begin(), out.end(), [](const auto& x, const auto& y) { return x.degrees < y.degrees; });
  return out;
}

namespace {

// Where the encroached subsegments of `check` lie: input segment and the encroacher's (see encroached_per_segment).
std::vector<SteinerCount> count_encroached(const PlcState& s, const GabrielReport& check) {
  std::vector<int> on_segment(s.points.size(), -1);  // per Steiner point on a segment: its input segment
  std::vector<Key> rows;                              // the check's segment rows: s.subsegments in map order
  for (const auto& [sub, parent] : s.subsegments) {
    rows.push_back(sub);
    for (int end : {sub.first, sub.second})
      if (end >= s.n_input) on_segment[end] = parent;
  }
  std::map<std::vector<int>, long> counts;
  for (const auto& e : check.segments) {
    const InputSegment& seg = s.segments[s.subsegments.at(rows[e.index])];
    std::vector<int> where{seg.a, seg.b};
    if (e.vertex < s.n_input) {
      where.push_back(e.vertex);
    } else if (on_segment[e.vertex] >= 0) {
      where.push_back(s.segments[on_segment[e.vertex]].a);
      where.push_back(s.segments[on_segment[e.vertex]].b);
    }
    ++counts[where];
  }
  std::vector<SteinerCount> out;
  for (auto& [where, count] : counts) out.push_back({where, count});
  return top(std::move(out));
}

}  // namespace

void count_steiner(const PlcState& s, const GabrielReport& check, Refine3DDiagnosis& d) {
  std::vector<P3> input(s.points.begin(), s.points.begin() + s.n_input);
  PointIndex index(input);
  std::vector<SteinerCount> per_vertex(s.n_input);
  for (int v = 0; v < s.n_input; ++v) per_vertex[v].where = {v};
  for (std::size_t p = s.n_input; p < s.points.size(); ++p) ++per_vertex[index.nearest(s.points[p])].count;
  d.per_vertex = top(std::move(per_vertex));
  std::vector<SteinerCount> per_segment;
  for (const auto& seg : s.segments) per_segment.push_back({{seg.a, seg.b}, seg.steiner});
  d.per_segment = top(std::move(per_segment));
  d.encroached_per_segment = count_encroached(s, check);
}

double smallest_subsegment(const PlcState& s) {
  double best = HUGE_VAL;
  for (const auto& [sub, parent] : s.subsegments)
    best = std::min(best, CGAL::to_double(CGAL::squared_distance(s.points[sub.first], s.points[sub.second])));
  return s.subsegments.empty() ? 0.0 : std::sqrt(best);
}

}  // namespace nonobtuse::gabriel3d
