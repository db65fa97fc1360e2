// The incremental set of encroached subsegments against brute force, as points are added on segments and facets.
#include <gtest/gtest.h>

#include <cmath>
#include <iterator>

#include "gabriel3d_encroached.h"
#include "gabriel3d_split_rule.h"

namespace nonobtuse::gabriel3d {
namespace {

// Two facets sharing the segment from (0, 0, 0) to (1, 0, 0) at a dihedral angle of 10 degrees: points of one
// facet encroach subsegments of the other.
PLC3 two_facets_at_10_degrees() {
  const double d = 10.0 * 3.14159265358979323846 / 180.0, c = std::cos(d), s = std::sin(d);
  PLC3 plc;
  plc.points = {{0, 0, 0}, {1, 0, 0}, {3, 1, 0}, {0.5, 3, 0}, {-2, 1, 0}, {3, c, s}, {0.5, 3 * c, 3 * s}, {-2, c, s}};
  plc.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 1, 5}, {0, 5, 6}, {0, 6, 7}};
  plc.facet_ids = {0, 0, 0, 1, 1, 1};
  return plc;
}

// Every subsegment with a point strictly inside its diametral sphere (exact, every point tested).
std::vector<Key> brute_force(const PlcState& s) {
  std::vector<Key> out;
  for (const auto& [sub, parent] : s.subsegments)
    for (std::size_t i = 0; i < s.points.size(); ++i)
      if (static_cast<int>(i) != sub.first && static_cast<int>(i) != sub.second &&
          CGAL::side_of_bounded_sphere(s.points[sub.first], s.points[sub.second], s.points[i]) ==
              CGAL::ON_BOUNDED_SIDE) {
        out.push_back(sub);
        break;
      }
  return out;
}

TEST(Gabriel3DEncroached, IncrementalSetIsWhatAFullScanFinds) {
  PlcState s = build_plc_state(two_facets_at_10_degrees());
  PointIndex index(s.points);
  EncroachedSubsegments encroached(s, index);
  auto next = [state = 2024u]() mutable {
    state = state * 1103515245u + 12345u;
    return (state >> 8) / double(1 << 24);
  };
  std::size_t most = 0;
  for (int step = 0; step < 300; ++step) {
    std::optional<Key> split;
    int m = -1;
    if (step % 3 != 2) {  // split a subsegment
      auto it = std::next(s.subsegments.begin(), static_cast<long>(next() * s.subsegments.size()));
      const auto [a, b] = it->first;
      const double t = 0.2 + 0.6 * next();
      split = it->first;
      m = split_subsegment(s, a, b, t, interpolate(s.points[a], s.points[b], t));
    } else {  // a point inside a domain face of a facet: the centroid of its corners, rounded
      const int f = next() < 0.5 ? 0 : 1;
      const FacetCDT& cdt = s.facets[f]->cdt;
      std::vector<FacetCDT::Face_handle> faces;
      for (auto fh = cdt.finite_faces_begin(); fh != cdt.finite_faces_end(); ++fh)
        if (fh->info().in_domain) faces.push_back(fh);
      auto fh = faces[static_cast<std::size_t>(next() * faces.size())];
      const P3 p = CGAL::centroid(s.points[fh->vertex(0)->info()], s.points[fh->vertex(1)->info()],
                                  s.points[fh->vertex(2)->info()]);
      FacetCDT::Locate_type lt;
      int li = 0;
      auto loc = cdt.locate(s.facets[f]->project(p), lt, li, fh);
      if (!strictly_in_domain(cdt, lt, loc, li) || s.at.count({p.x(), p.y(), p.z()})) continue;
      m = insert_in_facet(s, f, p, lt, loc, li);
    }
    index.add(m);
    encroached.added(m, split);
    const std::vector<Key> expected = brute_force(s);
    ASSERT_EQ(encroached.sorted(), expected) << "after point " << m;
    most = std::max(most, expected.size());
  }
  EXPECT_GT(most, 5u);  // the comparison was not only between empty sets
}

}  // namespace
}  // namespace nonobtuse::gabriel3d
