// The Delaunay tetrahedralization of a PLC's vertices restricted to its regions, and which facets it covers.
#include <algorithm>
#include <optional>

#include "gabriel3d_plc.h"
#include "nonobtuse/plc_predicates.h"
#include "points_delaunay.h"

namespace nonobtuse {
namespace {

// The Delaunay tetrahedralization of the PLC's points, and the answer for a PLC with a one-triangle facet whose
// triangle is not a Delaunay face, from that tetrahedralization alone: such a facet is not covered (its
// triangulation has that one subfacet, and the only Delaunay face with its corners on it would be the triangle
// itself), so the tetrahedralization does not conform. No answer when there is no such facet (the triangulation is
// kept for restrict_delaunay: built once); neither (the general path decides, and names any error) when an index is
// out of range, a triangle is collinear or two points coincide.
struct FirstLook {
  std::optional<PlcDelaunay> answer;
  std::optional<PointsDelaunay> dt;
};

FirstLook one_triangle_facet_not_delaunay(const PLC3& plc) {
  if (plc.facet_ids.size() != plc.triangles.size()) return {};
  std::vector<int> ids = plc.facet_ids;
  std::sort(ids.begin(), ids.end());
  auto alone = [&](int id) { return std::upper_bound(ids.begin(), ids.end(), id) -
                                        std::lower_bound(ids.begin(), ids.end(), id) == 1; };
  const long n = static_cast<long>(plc.points.size());
  for (const auto& t : plc.triangles)
    for (int v : t)
      if (v < 0 || v >= n) return {};
  if (std::any_of(plc.triangles.begin(), plc.triangles.end(), [&](const PlcTriangle& t) {
        using gabriel3d::to_cgal;
        return CGAL::collinear(to_cgal(plc.points[t[0]]), to_cgal(plc.points[t[1]]), to_cgal(plc.points[t[2]]));
      }))
    return {};
  FirstLook out;
  try {
    out.dt.emplace(points_delaunay(plc.points));
  } catch (const InvalidInput&) {
    return {};  // coincident points: build_plc_state names them
  }
  DelaunayFaces d = faces_and_cells(*out.dt, plc.points.size(), plc.triangles);
  std::vector<int> uncovered;
  for (std::size_t t = 0; t < plc.triangles.size(); ++t)
    if (!d.is_face[t] && alone(plc.facet_ids[t])) uncovered.push_back(plc.facet_ids[t]);
  if (uncovered.empty()) return out;
  out.dt.reset();  // its memory goes before the sort
  std::sort(uncovered.begin(), uncovered.end());
  sort_cells(plc.points.size(), d.cells);
  out.answer.emplace();
  out.answer->uncovered_facets = std::move(uncovered);
  out.answer->delaunay_cells = std::move(d.cells);
  return out;
}

}  // namespace

PlcDelaunay delaunay_restricted_to_plc(const PLC3& plc) {
  FirstLook first = one_triangle_facet_not_delaunay(plc);
  if (first.answer) return std::move(*first.answer);
  const gabriel3d::PlcState s = gabriel3d::build_plc_state(plc);
  gabriel3d::Restricted r = first.dt ? gabriel3d::restrict_delaunay(s, plc, std::move(*first.dt))
                                     : gabriel3d::restrict_delaunay(s, plc);
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
