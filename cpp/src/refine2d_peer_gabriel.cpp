// Peer baseline for benchmarks: CGAL's make_conforming_Gabriel_2 on the domain's constrained Delaunay
// triangulation (midpoint splits of every encroached constraint, on both sides, until every constrained edge is
// Gabriel). Not a strategy of refine(): it also refines outside the domain and both sides of interfaces.
#include <CGAL/Triangulation_conformer_2.h>

#include "cdt.h"
#include "nonobtuse/refine2d.h"

namespace nonobtuse {

long long conforming_gabriel_steiner_points(const Domain2& domain) {
  cdt::CDT t;
  cdt::build(t, domain);
  std::size_t before = t.number_of_vertices();
  CGAL::make_conforming_Gabriel_2(t);
  return static_cast<long long>(t.number_of_vertices() - before);
}

}  // namespace nonobtuse
