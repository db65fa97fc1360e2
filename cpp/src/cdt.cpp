#include "cdt.h"

#include <CGAL/Delaunay_triangulation_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <utility>

#include "fork_join.h"
#include "nonobtuse/triangulate.h"

namespace nonobtuse::cdt {
namespace {

std::string describe(const Point& p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x() << ", " << p.y() << ")";
  return s.str();
}

void insert_hull_constraints(CDT& cdt) {
  std::vector<std::pair<Vertex_handle, Vertex_handle>> hull;
  auto inf = cdt.infinite_vertex();
  auto fc = cdt.incident_faces(inf), done = fc;
  if (fc == nullptr) return;
  do {
    int i = fc->index(inf);
    hull.emplace_back(fc->vertex(CDT::ccw(i)), fc->vertex(CDT::cw(i)));
  } while (++fc != done);
  for (auto& [a, b] : hull) cdt.insert_constraint(a, b);
}

// Stable LSD radix sort by key, 16 bits a pass; a pass in which every key has the same digit is skipped.
struct Keyed {
  std::uint64_t key;
  int index;
};
void radix_sort(std::vector<Keyed>& items) {
  std::vector<Keyed> tmp(items.size());
  std::vector<std::size_t> count(1 << 16);
  for (int shift = 0; shift < 64 && !items.empty(); shift += 16) {
    auto digit = [shift](const Keyed& k) { return (k.key >> shift) & 0xffff; };
    std::fill(count.begin(), count.end(), 0);
    for (const Keyed& k : items) ++count[digit(k)];
    if (count[digit(items[0])] == items.size()) continue;
    for (std::size_t d = 0, sum = 0; d < count.size(); ++d) sum += std::exchange(count[d], sum);
    for (const Keyed& k : items) tmp[count[digit(k)]++] = k;
    items.swap(tmp);
  }
}

// The domain's points, each with its input index, in insertion order: biased randomized rounds (Amenta, Choi and
// Rote's BRIO: a point is in round r = 0..7 with probability 7/8^(r+1) (round 7 takes the rest), from a hash of
// its index; coarsest round first, so that early rounds span the domain and later points mostly land inside the
// hull), each round along a
// Hilbert curve through k near-square slabs cut across the bounding box's long side, slabs in order (each curve
// ends where the next slab's begins). Over the whole box a Hilbert curve's cells keep the box's aspect, so on a
// long thin layer (1000:1) consecutive points would lie far apart along it and every point location would walk
// across many triangles. Keys on a 2^16 grid per slab, sorted by radix: half the time of CGAL's spatial_sort
// (median cuts) for a million points. The order only affects speed: the Delaunay flips break cocircular ties by
// CGAL's symbolic perturbation.
std::vector<std::pair<Point, int>> insertion_order(const std::vector<Point2>& pts) {
  std::vector<std::pair<Point, int>> out(pts.size());
  if (pts.empty()) return out;
  auto [xlo, xhi] = std::minmax_element(pts.begin(), pts.end(), [](const Point2& a, const Point2& b) { return a.x < b.x; });
  auto [ylo, yhi] = std::minmax_element(pts.begin(), pts.end(), [](const Point2& a, const Point2& b) { return a.y < b.y; });
  const bool along_x = xhi->x - xlo->x >= yhi->y - ylo->y;
  const double lo = along_x ? xlo->x : ylo->y, length = along_x ? xhi->x - xlo->x : yhi->y - ylo->y;
  const double across_lo = along_x ? ylo->y : xlo->x, width = along_x ? yhi->y - ylo->y : xhi->x - xlo->x;
  const std::size_t k = width > 0 ? std::clamp<double>(std::floor(length / width), 1.0, 0xffff) : 1;
  auto grid = [](double t) { return static_cast<std::uint32_t>(std::clamp(t * 65536.0, 0.0, 65535.0)); };
  std::vector<Keyed> keyed(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double along = along_x ? pts[i].x : pts[i].y, across = along_x ? pts[i].y : pts[i].x;
    const double t = length > 0 ? (along - lo) / length * k : 0.0;  // slab j covers t in [j, j + 1)
    const std::size_t j = std::min(k - 1, static_cast<std::size_t>(t));
    const std::uint32_t h = hilbert_index(grid(t - j), grid(width > 0 ? (across - across_lo) / width : 0.0));
    std::uint64_t mix = (i + 1) * 0x9e3779b97f4a7c15ull;  // splitmix64 of the index
    mix = (mix ^ (mix >> 30)) * 0xbf58476d1ce4e5b9ull;
    mix = (mix ^ (mix >> 27)) * 0x94d049bb133111ebull;
    mix ^= mix >> 31;
    int round = 0;  // P(round >= r) = 8^-r
    for (; round < 7 && (mix & 7) == 0; mix >>= 3) ++round;
    keyed[i] = {static_cast<std::uint64_t>(7 - round) << 48 | static_cast<std::uint64_t>(j) << 32 | h,
                static_cast<int>(i)};
  }
  radix_sort(keyed);
  for (std::size_t i = 0; i < pts.size(); ++i) out[i] = {to_cgal(pts[keyed[i].index]), keyed[i].index};
  return out;
}

// Backstops for a domain that skipped nonobtuse.validate (which names problems with more context): predicates on
// non-finite coordinates are undefined, and a constraint from a vertex to itself corrupts the triangulation.
void require_finite_and_proper(const Domain2& domain) {
  auto finite = [](double x, double y) { return std::isfinite(x) && std::isfinite(y); };
  for (std::size_t i = 0; i < domain.points.size(); ++i)
    if (!finite(domain.points[i].x, domain.points[i].y))
      throw InvalidInput("point " + std::to_string(i) + " has a coordinate that is not finite");
  for (std::size_t i = 0; i < domain.holes.size(); ++i)
    if (!finite(domain.holes[i].x, domain.holes[i].y))
      throw InvalidInput("hole " + std::to_string(i) + " has a coordinate that is not finite");
  for (std::size_t i = 0; i < domain.regions.size(); ++i)
    if (!finite(domain.regions[i].at.x, domain.regions[i].at.y) || !std::isfinite(domain.regions[i].attribute))
      throw InvalidInput("region " + std::to_string(i) + " has a coordinate or attribute that is not finite");
  for (std::size_t s = 0; s < domain.segments.size(); ++s)
    if (domain.segments[s][0] == domain.segments[s][1])
      throw InvalidInput("segment " + std::to_string(s) + " (" + std::to_string(domain.segments[s][0]) + ", " +
                         std::to_string(domain.segments[s][1]) + ") has zero length");
}

}  // namespace

// The Hilbert curve, four levels at a time: kHilbert[state << 8 | x4 << 4 | y4] = (next state) << 8 | (the 8 bits
// of the curve index for these levels), x4, y4 the next 4 bits of the coordinates. The state is the transform the
// coarser levels put on the quadrant: coordinates swapped (bit 0) and both reflected (bit 1). One level, from the
// top: (rx, ry) the transformed bits, digit (3 rx) xor ry; in a lower quadrant (ry = 0) the curve turns, swapped
// (and reflected too when rx = 1) for the levels below.
static const std::array<std::uint16_t, 1024> kHilbert = [] {
  std::array<std::uint16_t, 1024> table{};
  for (unsigned state = 0; state < 4; ++state)
    for (unsigned xy = 0; xy < 256; ++xy) {
      unsigned swapped = state & 1, reflected = state >> 1, digits = 0;
      for (int b = 3; b >= 0; --b) {
        const unsigned xb = (xy >> (4 + b)) & 1, yb = (xy >> b) & 1;
        const unsigned rx = (swapped ? yb : xb) ^ reflected, ry = (swapped ? xb : yb) ^ reflected;
        digits = digits << 2 | ((3 * rx) ^ ry);
        if (ry == 0) reflected ^= rx, swapped ^= 1;
      }
      table[state << 8 | xy] = static_cast<std::uint16_t>((reflected << 1 | swapped) << 8 | digits);
    }
  return table;
}();

std::uint32_t hilbert_index(std::uint32_t x, std::uint32_t y) {
  std::uint32_t d = 0, state = 0;
  for (int shift = 12; shift >= 0; shift -= 4) {
    const std::uint32_t entry = kHilbert[state << 8 | ((x >> shift) & 15) << 4 | ((y >> shift) & 15)];
    d = d << 8 | (entry & 0xff);
    state = entry >> 8;
  }
  return d;
}

namespace {

// The points into the empty cdt (info = input index), spatially sorted. They go into a Delaunay triangulation over
// the same data structure, which is then swapped in: Delaunay_triangulation_2 inserts without the constraint
// bookkeeping, and both break cocircular ties by the same symbolic perturbation, so this is the CDT of the points
// without constraints. Throws InvalidInput on duplicate points.
std::vector<Vertex_handle> insert_points(CDT& cdt, const std::vector<Point2>& points) {
  CGAL::Delaunay_triangulation_2<K, Tds> dt;
  std::vector<Vertex_handle> vh(points.size());
  Face_handle hint;
  for (const auto& [p, i] : insertion_order(points)) {
    std::size_t before = dt.number_of_vertices();
    vh[i] = dt.insert(p, hint);
    if (dt.number_of_vertices() == before)
      throw InvalidInput("duplicate points: point " + std::to_string(std::max(i, vh[i]->info())) + " equals point " +
                         std::to_string(std::min(i, vh[i]->info())) + " at " + describe(p));
    vh[i]->info() = i;
    hint = vh[i]->face();
  }
  static_cast<CGAL::Triangulation_2<K, Tds>&>(cdt).swap(dt);
  return vh;
}

}  // namespace

std::vector<Vertex_handle> build(CDT& cdt, const Domain2& domain) {
  if (cdt.number_of_vertices() != 0) throw InternalError("cdt::build: the triangulation is not empty");
  require_finite_and_proper(domain);
  const std::vector<Vertex_handle> vh = insert_points(cdt, domain.points);
  for (std::size_t s = 0; s < domain.segments.size(); ++s) {
    auto [a, b] = domain.segments[s];
    try {
      cdt.insert_constraint(vh.at(a), vh.at(b));
    } catch (const CDT::Intersection_of_constraints_exception&) {
      throw InvalidInput("segment " + std::to_string(s) + " (" + std::to_string(a) + ", " + std::to_string(b) +
                         ") crosses another segment away from their endpoints");
    }
  }
  if (domain.convex_hull_boundary) insert_hull_constraints(cdt);
  mark_domain(cdt, domain);
  return vh;
}

bool is_simple_pslg(const std::vector<Point2>& points, const std::vector<Segment>& segments) {
  CDT cdt;
  std::vector<Vertex_handle> vh;
  try {
    vh = insert_points(cdt, points);
  } catch (const InvalidInput&) {
    return false;
  }
  if (cdt.dimension() < 2) return false;
  std::vector<std::uint64_t> keys;
  keys.reserve(segments.size());
  for (const auto& [a, b] : segments) {
    if (a == b) return false;
    try {
      cdt.insert_constraint(vh.at(a), vh.at(b));
    } catch (const CDT::Intersection_of_constraints_exception&) {
      return false;
    }
    keys.push_back(static_cast<std::uint64_t>(std::min(a, b)) << 32 | static_cast<std::uint32_t>(std::max(a, b)));
  }
  for (const auto& [a, b] : segments)
    if (!cdt.is_edge(vh[a], vh[b])) return false;
  std::sort(keys.begin(), keys.end());
  return std::adjacent_find(keys.begin(), keys.end()) == keys.end();
}

bool same_domain(const Domain2& a, const Domain2& b) {
  auto same = [](const Point2& p, const Point2& q) { return p.x == q.x && p.y == q.y; };
  auto same_region = [&](const RegionSeed& r, const RegionSeed& t) {
    return same(r.at, t.at) && r.attribute == t.attribute;
  };
  return a.convex_hull_boundary == b.convex_hull_boundary && a.segments == b.segments &&
         std::equal(a.points.begin(), a.points.end(), b.points.begin(), b.points.end(), same) &&
         std::equal(a.holes.begin(), a.holes.end(), b.holes.begin(), b.holes.end(), same) &&
         std::equal(a.regions.begin(), a.regions.end(), b.regions.begin(), b.regions.end(), same_region);
}

void mark_domain(CDT& cdt, const Domain2& domain) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = FaceInfo{};
  cdt.region_attribute.assign(1, 0.0);
  if (cdt.dimension() < 2) return;  // collinear points: no face, nothing inside
  // Fill from `stack` across unconstrained edges; set(face) marks each face reached.
  auto fill = [&](std::vector<Face_handle> stack, auto&& reached, auto&& set) {
    while (!stack.empty()) {
      Face_handle f = stack.back();
      stack.pop_back();
      if (reached(f)) continue;
      set(f);
      for (int i = 0; i < 3; ++i)
        if (!cdt.is_constrained(Edge(f, i)) && !reached(f->neighbor(i))) stack.push_back(f->neighbor(i));
    }
  };
  // Exterior: component -2; holes: component -3. As in Triangle's hole carving, only these are walked; without
  // regions every other face is in the domain, marked in container order (sequential memory; a flood fill over a
  // million domain faces was most of this function's time).
  std::vector<Face_handle> outside;
  auto inf_faces = cdt.incident_faces(cdt.infinite_vertex()), done = inf_faces;
  if (inf_faces != nullptr) do outside.push_back(inf_faces); while (++inf_faces != done);
  auto marked = [](Face_handle f) { return f->info().component != -1; };
  fill(outside, marked, [](Face_handle f) { f->info().component = -2; });
  for (const auto& h : domain.holes) {
    Face_handle f = cdt.locate(to_cgal(h));
    if (f == nullptr || cdt.is_infinite(f)) continue;
    fill({f}, marked, [](Face_handle g) { g->info().component = -3; });
  }
  if (domain.regions.empty()) {  // one class of domain faces: component 0, region attribute 0
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
      if (f->info().component == -1) f->info().component = 0;
    return;
  }
  // Regions: domain components 0, 1, ... by flood fill, each with the attribute of a region seed inside it.
  int next = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info().component != -1) continue;
    int c = next++;
    fill({f}, marked, [c](Face_handle g) { g->info().component = c; });
  }
  cdt.region_attribute.assign(std::max(next, 1), 0.0);
  for (const auto& r : domain.regions) {
    Face_handle f = cdt.locate(to_cgal(r.at));
    if (f != nullptr && f->info().in_domain()) cdt.region_attribute[f->info().component] = r.attribute;
  }
}

namespace {

// Mesh points indexed by vertex info.
void write_points(const CDT& cdt, Mesh2& mesh) {
  int n = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) n = std::max(n, v->info() + 1);
  mesh.points.resize(n);
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    if (v->info() < 0) throw InternalError("cdt::to_mesh: a vertex has no index");
    mesh.points[v->info()] = from_cgal(v->point());
  }
}

// Domain triangles with their regions, and the constrained edges bordering the domain, from the domain faces
// beside them (twice for an interface; unsorted).
void write_triangles(const CDT& cdt, Mesh2& mesh) {
  mesh.triangles.reserve(cdt.number_of_faces());
  mesh.triangle_region.reserve(cdt.number_of_faces());
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->info().in_domain()) continue;
    mesh.triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
    mesh.triangle_region.push_back(cdt.region(f));
    for (int i = 0; i < 3; ++i)
      if (f->is_constrained(i)) {
        int a = f->vertex(CDT::cw(i))->info(), b = f->vertex(CDT::ccw(i))->info();
        mesh.segments.push_back({std::min(a, b), std::max(a, b)});
      }
  }
}

}  // namespace

Mesh2 to_mesh(const CDT& cdt, int threads) {
  Mesh2 mesh;
  fork_join(worth_forking(cdt.number_of_faces(), threads), [&] { write_points(cdt, mesh); },
            [&] { write_triangles(cdt, mesh); });
  std::sort(mesh.segments.begin(), mesh.segments.end());
  mesh.segments.erase(std::unique(mesh.segments.begin(), mesh.segments.end()), mesh.segments.end());
  return mesh;
}

}  // namespace nonobtuse::cdt

namespace nonobtuse {

Mesh2 triangulate(const Domain2& domain) {
  cdt::CDT t;
  cdt::build(t, domain);
  Mesh2 mesh = cdt::to_mesh(t);
  if (mesh.triangles.empty())
    throw InvalidInput("the domain contains no triangle (are all points collinear, or is everything a hole?)");
  return mesh;
}

}  // namespace nonobtuse
