// Benchmark peer: CGAL make_conforming_Gabriel_2 on our constrained Delaunay triangulation.
#include <CGAL/Triangulation_conformer_2.h>

#include "cdt.h"
#include "nonobtuse/peers2d.h"

namespace nonobtuse {

std::size_t conforming_gabriel_points(const Domain2& domain) {
  cdt::CDT t;
  cdt::build(t, domain);
  CGAL::make_conforming_Gabriel_2(t);
  return t.number_of_vertices();
}

}  // namespace nonobtuse
