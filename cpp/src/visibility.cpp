// Visibility from a subsegment: the walk over its diametral disk and exact shading by obstacles.
#include "visibility.h"

#include <algorithm>
#include <array>

namespace nonobtuse::refine2d {

namespace {

// A face waiting in walk_seen, with the last constraints met on the way to it (indices into the constraints met).
constexpr int kRecent = 4;
// Skipping a face is never needed for correctness, only for speed: the first kFreeFaces faces of a walk are
// crossed out of without the umbra tests, which would cost more than they save on the small disks of most sides
// (a convex polygon's, where nearly collinear neighbours also make the orientations slow).
constexpr std::size_t kFreeFaces = 16;
struct SeenEntry {
  Face_handle face;
  std::array<int, kRecent> recent;
};

// The Walked::Seen walk from the side's domain faces over its disk (right_in_domain: the side's other side is a
// domain side too); visit(face) for every face entered. After the first kFreeFaces faces, an unconstrained edge
// [u, w] near the disk is crossed unless
// - u and w both lie in the umbra (in_umbra, from fat_side) of one blocker: a constraint other than the side, among
//   those of the face being left, the last kRecent met on the way to it, and the first four met that touch the
//   side's ends (the walls that bound what the side sees); or
// - !right_in_domain, and u and w both lie strictly right of fat_side's right edge.
// Why the walk still enters every face that a sight line passes through before its first constraint (so that
// the first constraint on it is an obstacle and its end vertex an encroacher): such a sight line from a point y
// of fat_side enters the domain through the side and then crosses unconstrained edges at points p with [y, p]
// meeting no constraint but the side. Such a p is in no blocker's umbra (y sees it), and it is not strictly right
// of the fat side when the domain lies left only (the sight line runs from y to a vertex strictly left of the
// side). Either rule is a set inclusion tested exactly on corners of convex sets (the umbra and the half-plane are
// convex), so the walk never skips such an edge.
template <class Visit>
void walk_seen(const State& st, const Side& side, bool right_in_domain, Visit&& visit, int lane) {
  const Point &s = side.s->point(), &e = side.e->point();
  const DiskReach disk(s, e);
  const std::array<Point, 4> source = fat_side(s, e);
  auto beyond_right = [&](const Point& p) { return CGAL::orientation(source[1], source[2], p) == CGAL::RIGHT_TURN; };
  std::vector<Segment2> met;
  std::vector<int> walls;  // the constraints met touching s or e (at most four)
  const unsigned walk = ++st.lane(lane).face_walks;
  std::vector<SeenEntry> stack;
  for (Face_handle f : st.domain_faces(side)) {
    f->info().visit[lane] = walk;
    stack.push_back({f, {-1, -1, -1, -1}});
  }
  std::size_t entered = 0;
  while (!stack.empty()) {
    const SeenEntry entry = stack.back();
    stack.pop_back();
    Face_handle f = entry.face;
    visit(f);
    ++entered;
    std::array<int, kRecent> recent;  // the face's own constraints first, then its path's
    int k = 0;
    for (int i = 0; i < 3; ++i) {
      if (!f->is_constrained(i)) continue;
      Vertex_handle u = f->vertex(CDT::ccw(i)), w = f->vertex(CDT::cw(i));
      if ((u == side.s && w == side.e) || (u == side.e && w == side.s)) continue;
      recent[k++] = static_cast<int>(met.size());
      if (walls.size() < 4 && (u == side.s || u == side.e || w == side.s || w == side.e))
        walls.push_back(static_cast<int>(met.size()));
      met.emplace_back(u->point(), w->point());
    }
    for (int j = 0; k < kRecent; ++j) recent[k++] = entry.recent[j];
    auto hidden = [&](const Point& u, const Point& w) {
      if (!right_in_domain && beyond_right(u) && beyond_right(w)) return true;
      auto shades = [&](int c) { return c >= 0 && in_umbra(source, u, met[c]) && in_umbra(source, w, met[c]); };
      return std::any_of(recent.begin(), recent.end(), shades) || std::any_of(walls.begin(), walls.end(), shades);
    };
    for (int i = 0; i < 3; ++i) {
      if (f->is_constrained(i)) continue;
      Face_handle g = f->neighbor(i);
      if (g->info().visit[lane] == walk || st.cdt().is_infinite(g)) continue;
      const Point &u = f->vertex(CDT::ccw(i))->point(), &w = f->vertex(CDT::cw(i))->point();
      if (!disk.near(u, w) || (entered > kFreeFaces && hidden(u, w))) continue;
      g->info().visit[lane] = walk;
      stack.push_back({g, recent});
    }
  }
}

}  // namespace

DiskWalk walk_diametral_disk(const State& st, const Side& side, int lane, Walked walked) {
  DiskWalk out;
  const Point &s = side.s->point(), &e = side.e->point();
  const bool left = st.is_boundary_side(side), right = st.is_boundary_side({side.e, side.s});
  auto on_domain_side = [&](const Point& q) { return (left && encroaches(s, e, q)) || (right && encroaches(e, s, q)); };
  std::vector<Vertex_handle> reached;  // the vertices of the faces reached (walks skip infinite faces), once each
  WalkLane& scratch = st.lane(lane);
  const unsigned stamp = ++scratch.vertex_lists;
  std::vector<unsigned>& listed = scratch.vertex_stamp;
  // Obstacles only where they come near the disk (the walk's own pruning test): a sight line from a point of the
  // edge to a vertex in the disk lies in the closed disk, and covered_from only uses obstacles that meet the
  // triangle (v, a, b) inside it or end at a or b; the faces reached reach far beyond the disk (a polygon's
  // fans), and their far constrained edges would make every covered_from linear in them.
  const DiskReach disk(s, e);
  auto visit = [&](Face_handle f) {
    for (int i = 0; i < 3; ++i) {
      const auto index = static_cast<std::size_t>(f->vertex(i)->info());
      if (index >= listed.size()) listed.resize(index + 1, 0);
      if (listed[index] != stamp) {
        listed[index] = stamp;
        reached.push_back(f->vertex(i));
      }
      Vertex_handle u = f->vertex(CDT::ccw(i)), w = f->vertex(CDT::cw(i));
      if (f->is_constrained(i) && !((u == side.s && w == side.e) || (u == side.e && w == side.s)) &&
          disk.near(u->point(), w->point()))
        out.obstacles.emplace_back(u->point(), w->point());
    }
    return false;
  };
  if (walked == Walked::Seen)
    walk_seen(st, side, right, visit, lane);
  else
    walk_disk(st, st.domain_faces(side), s, e, visit, lane);
  for (Vertex_handle v : reached)
    if (v != side.s && v != side.e && on_domain_side(v->point())) out.encroachers.push_back(v);
  // Deterministic order (the walk order depends on face handles): by vertex index.
  std::sort(out.encroachers.begin(), out.encroachers.end(),
            [](Vertex_handle a, Vertex_handle b) { return a->info() < b->info(); });
  return out;
}

bool sees(const State& st, const Side& start, const Point& a, const Point& b, Vertex_handle v, Sight sight) {
  if (sight.in_front != nullptr) return !sight.in_front->covered(v, a, b);
  if (sight.obstacles != nullptr) return !covered_from(v->point(), a, b, *sight.obstacles);
  bool found = false;
  walk_disk(st, st.domain_faces(start), a, b, [&](Face_handle f) { return found = f->has_vertex(v); });
  return found;
}

}  // namespace nonobtuse::refine2d
