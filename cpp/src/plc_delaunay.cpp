// The Delaunay tetrahedralization of a PLC's vertices restricted to its regions, and which facets it covers.
#include "gabriel3d_plc.h"
#include "nonobtuse/plc_predicates.h"

namespace nonobtuse {

PlcDelaunay delaunay_restricted_to_plc(const PLC3& plc) {
  const gabriel3d::PlcState s = gabriel3d::build_plc_state(plc);
  gabriel3d::Restricted r = gabriel3d::restrict_delaunay(s, plc);
  std::vector<long> subfacets(s.facets.size(), 0), covered(s.facets.size(), 0);
  for (std::size_t f = 0; f < s.facets.size(); ++f) {
    const auto& cdt = s.facets[f]->cdt;
    for (auto fh = cdt.finite_faces_begin(); fh != cdt.finite_faces_end(); ++fh) subfacets[f] += fh->info().in_domain;
  }
  for (int f : r.face_facets) ++covered[f];
  PlcDelaunay out;
  for (std::size_t f = 0; f < s.facets.size(); ++f)
    if (covered[f] != subfacets[f]) out.uncovered_facets.push_back(s.facets[f]->id);
  out.tets = std::move(r.tets);
  out.tet_regions = std::move(r.tet_regions);
  out.boundary_faces = std::move(r.boundary_faces);
  out.face_markers = std::move(r.face_markers);
  return out;
}

}  // namespace nonobtuse
