// The PLC under refinement: validation, per-facet constrained Delaunay triangulations, subsegment bookkeeping.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "gabriel3d_plc.h"

namespace nonobtuse::gabriel3d {
namespace {

using Vec = std::array<double, 3>;
Vec sub(const P3& a, const P3& b) { return {a.x() - b.x(), a.y() - b.y(), a.z() - b.z()}; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec normalized(const Vec& a) {
  double n = std::sqrt(dot(a, a));
  return {a[0] / n, a[1] / n, a[2] / n};
}

std::string describe(const P3& p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

// An orthonormal frame of the facet's plane: normal = sum of its triangles' area vectors, each turned to the side
// of the first triangle's, so that a facet whose triangles are not consistently oriented (a PLC need not be) still
// gets the normal of its plane.
void set_frame(Facet& facet, const std::vector<P3>& pts, const std::vector<Triangle>& tris) {
  Vec n{0, 0, 0}, first{0, 0, 0};
  for (const auto& t : tris) {
    Vec c = cross(sub(pts[t[1]], pts[t[0]]), sub(pts[t[2]], pts[t[0]]));
    if (&t == &tris.front()) first = c;
    double sign = dot(c, first) < 0 ? -1.0 : 1.0;
    for (int d = 0; d < 3; ++d) n[d] += sign * c[d];
  }
  n = normalized(n);
  const P3& o = pts[tris[0][0]];
  Vec e = sub(pts[tris[0][1]], o);
  double along = dot(e, n);
  for (int d = 0; d < 3; ++d) e[d] -= along * n[d];
  facet.origin = {o.x(), o.y(), o.z()};
  facet.u = normalized(e);
  facet.v = cross(n, facet.u);
}

void add_facet(PlcState& s, int id, const std::vector<Triangle>& tris, const std::map<Key, int>& plc_segments,
               std::map<Key, int>& parent_of) {
  auto facet = std::make_unique<Facet>();
  facet->id = id;
  set_frame(*facet, s.points, tris);
  int f = static_cast<int>(s.facets.size());
  std::map<Key, int> edge_count;
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k) ++edge_count[key(t[k], t[(k + 1) % 3])];
  for (const auto& t : tris)
    for (int v : t) {
      if (facet->vertex.count(v)) continue;
      std::size_t before = facet->cdt.number_of_vertices();
      auto vh = facet->cdt.insert(facet->project(s.points[v]));
      if (facet->cdt.number_of_vertices() == before)
        throw InvalidInput("facet " + std::to_string(id) + ": points " + std::to_string(v) + " and " +
                           std::to_string(vh->info()) + " coincide in the facet's plane (facet not planar?)");
      vh->info() = v;
      facet->vertex[v] = vh;
      s.point_facets[v].push_back(f);
    }
  for (const auto& [e, count] : edge_count) {
    if (count == 2 && !plc_segments.count(e)) continue;  // an interior edge of the facet's own triangulation
    if (count > 2)
      throw InvalidInput("facet " + std::to_string(id) + ": edge (" + std::to_string(e.first) + ", " +
                         std::to_string(e.second) + ") is shared by more than two of its triangles");
    auto va = facet->vertex[e.first], vb = facet->vertex[e.second];
    FacetCDT::Face_handle fh;
    int i = 0;
    try {
      facet->cdt.insert_constraint(va, vb);
    } catch (const FacetCDT::Intersection_of_constraints_exception&) {
      throw InvalidInput("facet " + std::to_string(id) + ": edge (" + std::to_string(e.first) + ", " +
                         std::to_string(e.second) + ") crosses another edge");
    }
    if (!facet->cdt.is_edge(va, vb, fh, i))  // the constraint was split at a vertex lying on it
      throw InvalidInput("facet " + std::to_string(id) + ": edge (" + std::to_string(e.first) + ", " +
                         std::to_string(e.second) + ") passes through another vertex of the facet");
    auto [it, fresh] = parent_of.emplace(e, static_cast<int>(s.segments.size()));
    if (fresh) s.segments.push_back({e.first, e.second, {}, 0});
    s.segments[it->second].facets.push_back(f);
  }
  mark_facet_domain(facet->cdt);
  s.facets.push_back(std::move(facet));
}

// The side of line ab (exact) where x lies, for points of the facet's triangulation.
CGAL::Orientation side(const Q2& a, const Q2& b, const Q2& x) { return CGAL::orientation(a, b, x); }

}  // namespace

Q2 Facet::project(const P3& p) const {
  Vec d{p.x() - origin[0], p.y() - origin[1], p.z() - origin[2]};
  return Q2(dot(d, u), dot(d, v));
}

std::array<double, 3> Facet::normal() const { return cross(u, v); }

void mark_facet_domain(FacetCDT& cdt) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = FacetFaceInfo{};
  std::vector<FacetCDT::Face_handle> frontier;
  auto fc = cdt.incident_faces(cdt.infinite_vertex()), done = fc;
  if (fc != nullptr) do frontier.push_back(fc); while (++fc != done);
  for (auto f : frontier) f->info().nesting = 0;
  // Breadth-first by level: fill a level across unconstrained edges, then cross constraints into the next.
  for (int level = 0; !frontier.empty(); ++level) {
    std::vector<FacetCDT::Face_handle> next, stack = frontier;
    while (!stack.empty()) {
      auto f = stack.back();
      stack.pop_back();
      f->info().in_domain = level % 2 == 1;
      for (int i = 0; i < 3; ++i) {
        auto g = f->neighbor(i);
        if (g->info().nesting != -1) continue;
        if (cdt.is_constrained({f, i})) {
          next.push_back(g);
        } else {
          g->info().nesting = level;
          stack.push_back(g);
        }
      }
    }
    frontier.clear();
    for (auto g : next)
      if (g->info().nesting == -1) {
        g->info().nesting = level + 1;
        frontier.push_back(g);
      }
  }
}

PlcState build_plc_state(const PLC3& plc) {
  PlcState s;
  s.n_input = static_cast<int>(plc.points.size());
  s.point_facets.resize(plc.points.size());
  for (std::size_t i = 0; i < plc.points.size(); ++i) {
    const auto& p = plc.points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InvalidInput("point " + std::to_string(i) + " has a non-finite coordinate");
    auto [it, fresh] = s.at.emplace(std::array<double, 3>{p.x, p.y, p.z}, static_cast<int>(i));
    if (!fresh)
      throw InvalidInput("duplicate points: point " + std::to_string(i) + " equals point " +
                         std::to_string(it->second) + " at " + describe(to_cgal(p)));
    s.points.push_back(to_cgal(p));
  }
  auto check_index = [&](int v, const char* what, std::size_t row) {
    if (v < 0 || v >= s.n_input)
      throw InvalidInput(std::string(what) + " " + std::to_string(row) + " refers to point " + std::to_string(v) +
                         ", but there are " + std::to_string(s.n_input) + " points");
  };
  if (plc.facet_ids.size() != plc.triangles.size())
    throw InvalidInput("facet_ids has " + std::to_string(plc.facet_ids.size()) + " entries for " +
                       std::to_string(plc.triangles.size()) + " triangles");
  std::map<int, std::vector<Triangle>> by_facet;
  for (std::size_t t = 0; t < plc.triangles.size(); ++t) {
    const auto& tri = plc.triangles[t];
    for (int v : tri) check_index(v, "triangle", t);
    if (CGAL::collinear(s.points[tri[0]], s.points[tri[1]], s.points[tri[2]]))
      throw InvalidInput("triangle " + std::to_string(t) + " (" + std::to_string(tri[0]) + ", " +
                         std::to_string(tri[1]) + ", " + std::to_string(tri[2]) + ") is degenerate (collinear)");
    by_facet[plc.facet_ids[t]].push_back(tri);
  }
  std::map<Key, int> plc_segments, parent_of;
  for (std::size_t i = 0; i < plc.segments.size(); ++i) {
    auto [a, b] = plc.segments[i];
    check_index(a, "segment", i);
    check_index(b, "segment", i);
    if (a == b) throw InvalidInput("segment " + std::to_string(i) + " has coincident ends");
    if (parent_of.emplace(key(a, b), static_cast<int>(s.segments.size())).second)
      s.segments.push_back({std::min(a, b), std::max(a, b), {}, 0});
    plc_segments.emplace(key(a, b), static_cast<int>(i));
  }
  for (const auto& [id, tris] : by_facet) add_facet(s, id, tris, plc_segments, parent_of);
  for (const auto& [e, parent] : parent_of) s.subsegments.emplace(e, parent);
  return s;
}

int split_subsegment(PlcState& s, int a, int b, double t, const P3& rounded) {
  int parent = s.subsegments.at(key(a, b));
  int m = static_cast<int>(s.points.size());
  s.points.push_back(rounded);
  s.at.emplace(std::array<double, 3>{rounded.x(), rounded.y(), rounded.z()}, m);
  s.subsegments.erase(key(a, b));
  s.subsegments.emplace(key(a, m), parent);
  s.subsegments.emplace(key(m, b), parent);
  s.point_facets.push_back(s.segments[parent].facets);
  ++s.segments[parent].steiner;
  for (int f : s.segments[parent].facets) {
    Facet& facet = *s.facets[f];
    auto va = facet.vertex.at(a), vb = facet.vertex.at(b);
    FacetCDT::Face_handle fh;
    int i = 0;
    if (!facet.cdt.is_edge(va, vb, fh, i))
      throw InternalError("subsegment (" + std::to_string(a) + ", " + std::to_string(b) + ") missing from facet " +
                          std::to_string(facet.id));
    const Q2 pa = va->point(), pb = vb->point();
    // The sides of ab before the split: in_domain of the face on each side.
    bool in_left = false, in_right = false;
    for (auto g : {fh, fh->neighbor(i)}) {
      if (facet.cdt.is_infinite(g)) continue;
      int apex = g == fh ? i : g->index(fh);
      (side(pa, pb, g->vertex(apex)->point()) == CGAL::LEFT_TURN ? in_left : in_right) = g->info().in_domain;
    }
    // Left lazy: its exact value (rationals) is computed only if a predicate's interval filter fails on it, as the
    // orientation tests below no longer need for the collinear points. Evaluating every split point eagerly was
    // two thirds of split_subsegment (perf, gc_spot).
    Q2 q = pa + (pb - pa) * EK::FT(t);
    auto vm = facet.cdt.insert(q, FacetCDT::EDGE, fh, i);
    vm->info() = m;
    facet.vertex[m] = vm;
    auto fc = facet.cdt.incident_faces(vm), done = fc;
    do {
      bool in = false;
      if (!facet.cdt.is_infinite(fc))
        for (int k = 0; k < 3; ++k) {
          // m, a and b lie on ab (exactly): skipped without the exact orientation test a collinear point needs.
          // They are the only points of ab around m (an edge from m to another would pass through a or b).
          const auto v = fc->vertex(k);
          if (v == vm || v == va || v == vb) continue;
          auto o = side(pa, pb, v->point());
          if (o != CGAL::COLLINEAR) in = o == CGAL::LEFT_TURN ? in_left : in_right;
        }
      fc->info().in_domain = in;
    } while (++fc != done);
  }
  return m;
}

int insert_in_facet(PlcState& s, int f, const P3& point, FacetCDT::Locate_type lt, FacetCDT::Face_handle loc,
                    int li) {
  Facet& facet = *s.facets[f];
  int m = static_cast<int>(s.points.size());
  s.points.push_back(point);
  s.at.emplace(std::array<double, 3>{point.x(), point.y(), point.z()}, m);
  s.point_facets.push_back({f});
  auto vm = facet.cdt.insert(facet.project(point), lt, loc, li);
  vm->info() = m;
  facet.vertex[m] = vm;
  auto fc = facet.cdt.incident_faces(vm), done = fc;
  do fc->info().in_domain = !facet.cdt.is_infinite(fc); while (++fc != done);
  return m;
}

bool noisy_direction(const P3& from, const P3& to, double radius) {
  const double big = std::max({std::abs(from.x()), std::abs(from.y()), std::abs(from.z()), std::abs(to.x()),
                               std::abs(to.y()), std::abs(to.z())});
  const double floor = std::max(std::ldexp(radius, -26), std::ldexp(big, 20 - 52));
  return !(CGAL::compare_squared_distance(from, to, floor * floor) == CGAL::LARGER);
}

bool strictly_in_domain(const FacetCDT& cdt, FacetCDT::Locate_type lt, FacetCDT::Face_handle loc, int li) {
  return (lt == FacetCDT::FACE && loc->info().in_domain) ||
         (lt == FacetCDT::EDGE && !cdt.is_constrained({loc, li}) && loc->info().in_domain &&
          loc->neighbor(li)->info().in_domain);
}

std::optional<Key> first_crossed_subsegment(const Facet& facet, const Q2& g, const Q2& q) {
  std::optional<Key> best;
  std::optional<EK::FT> best_d2;
  EK::Segment_2 walk(g, q);
  for (auto e = facet.cdt.finite_edges_begin(); e != facet.cdt.finite_edges_end(); ++e) {
    if (!facet.cdt.is_constrained(*e)) continue;
    auto u = e->first->vertex(FacetCDT::cw(e->second)), w = e->first->vertex(FacetCDT::ccw(e->second));
    EK::Segment_2 sub(u->point(), w->point());
    if (!CGAL::do_intersect(walk, sub)) continue;
    auto x = CGAL::intersection(walk, sub);
    const Q2* p = boost::get<Q2>(&*x);
    EK::FT d2 = p ? CGAL::squared_distance(g, *p) : EK::FT(0);
    Key k = key(u->info(), w->info());
    if (!best_d2 || d2 < *best_d2 || (d2 == *best_d2 && k < *best)) best_d2 = d2, best = k;
  }
  return best;
}

bool triangle_on_facet(const PlcState& s, int f, int a, int b, int c) {
  const Facet& facet = *s.facets[f];
  auto ia = facet.vertex.find(a), ib = facet.vertex.find(b), ic = facet.vertex.find(c);
  if (ia == facet.vertex.end() || ib == facet.vertex.end() || ic == facet.vertex.end()) return false;
  Q2 g = CGAL::centroid(ia->second->point(), ib->second->point(), ic->second->point());
  FacetCDT::Locate_type lt;
  int li = 0;
  auto loc = facet.cdt.locate(g, lt, li, ia->second->face());  // the walk starts at a corner: short
  if (lt == FacetCDT::FACE) return loc->info().in_domain;
  if (lt == FacetCDT::EDGE) return loc->info().in_domain && loc->neighbor(li)->info().in_domain;
  return false;
}

Restricted subfacet_boundary(const PlcState& s, long* collinear) {
  Restricted out;
  *collinear = 0;
  for (std::size_t f = 0; f < s.facets.size(); ++f) {
    const FacetCDT& cdt = s.facets[f]->cdt;
    for (auto fh = cdt.finite_faces_begin(); fh != cdt.finite_faces_end(); ++fh) {
      if (!fh->info().in_domain) continue;
      // Counter-clockwise in the frame (u, v) with u x v = the facet's normal (set_frame): the input's side.
      int a = fh->vertex(0)->info(), b = fh->vertex(1)->info(), c = fh->vertex(2)->info();
      if (CGAL::collinear(s.points[a], s.points[b], s.points[c])) {
        ++*collinear;
        continue;
      }
      out.boundary_faces.push_back({a, b, c});
      out.face_markers.push_back(s.facets[f]->id);
      out.face_facets.push_back(static_cast<int>(f));
    }
  }
  return out;
}

void check_invariants(const PlcState& s) {
  for (const auto& facet : s.facets)
    if (!facet->cdt.is_valid())
      throw InternalError("facet " + std::to_string(facet->id) + ": triangulation is not valid");
  for (const auto& [e, parent] : s.subsegments)
    for (int f : s.segments[parent].facets) {
      const Facet& facet = *s.facets[f];
      FacetCDT::Face_handle fh;
      int i = 0;
      if (!facet.cdt.is_edge(facet.vertex.at(e.first), facet.vertex.at(e.second), fh, i) ||
          !facet.cdt.is_constrained({fh, i}))
        throw InternalError("subsegment (" + std::to_string(e.first) + ", " + std::to_string(e.second) +
                            ") is not a constrained edge of facet " + std::to_string(facet.id));
    }
}

}  // namespace nonobtuse::gabriel3d
