// 2D domain validation: exact segment intersections and domain coverage (conversion only).
#include <pybind11/pybind11.h>

#include <memory>
#include <string>

#include "bind_mesh2d.h"
#include "nonobtuse/validate2d.h"

namespace nonobtuse::bindings {

namespace {

py::array_t<std::int8_t> seed_places(const std::vector<SeedPlace>& places) {
  std::vector<std::int8_t> v(places.size());
  std::transform(places.begin(), places.end(), v.begin(), [](SeedPlace p) { return static_cast<std::int8_t>(p); });
  return from_vector(v);
}

}  // namespace

void bind_validate2d(py::module_& m) {
  py::class_<SegmentIntersections>(m, "SegmentIntersections",
                                   "Exact segment intersections, sorted int64 (k, 2) arrays (read-only; a new array "
                                   "on each access).")
      .def_property_readonly("crossings", [](const SegmentIntersections& r) { return from_index_rows<2>(r.crossings); },
                             "(s, t): proper crossings")
      .def_property_readonly(
          "points_on_segments", [](const SegmentIntersections& r) { return from_index_rows<2>(r.points_on_segments); },
          "(p, s): point p strictly inside segment s")
      .def_property_readonly("overlaps", [](const SegmentIntersections& r) { return from_index_rows<2>(r.overlaps); },
                             "(s, t): collinear with a common piece")
      .def("__repr__", [](const SegmentIntersections& r) {
        return "<SegmentIntersections crossings=" + std::to_string(r.crossings.size()) +
               " points_on_segments=" + std::to_string(r.points_on_segments.size()) +
               " overlaps=" + std::to_string(r.overlaps.size()) + ">";
      });
  py::class_<Triangulation2, std::shared_ptr<Triangulation2>>(
      m, "Triangulation2",
      "Opaque: the constrained Delaunay triangulation inspect_domain built, for refine to take over (once).")
      .def_property_readonly("empty", &Triangulation2::empty, "True once refine took it");
  py::class_<DomainCoverage>(m, "DomainCoverage", "What a domain's constrained Delaunay triangulation covers.")
      .def_readonly("encloses_area", &DomainCoverage::encloses_area,
                    "some triangle is enclosed by segments (holes ignored)")
      .def_readonly("domain_triangles", &DomainCoverage::domain_triangles)
      .def_property_readonly("segments_outside", [](const DomainCoverage& c) { return from_vector(c.segments_outside); },
                             "int32: segments with no domain triangle on either side")
      .def_property_readonly("holes", [](const DomainCoverage& c) { return seed_places(c.holes); },
                             "int8 per hole seed: 0 inside, 1 outside, 2 on a point or segment")
      .def_property_readonly("regions", [](const DomainCoverage& c) { return seed_places(c.regions); },
                             "int8 per region seed, likewise")
      .def_readonly("triangulation", &DomainCoverage::triangulation,
                    "the triangulation when kept (keep_triangulation=True and a triangle), else None")
      .def("__repr__", [](const DomainCoverage& c) {
        return "<DomainCoverage domain_triangles=" + std::to_string(c.domain_triangles) +
               " segments_outside=" + std::to_string(c.segments_outside.size()) + ">";
      });
  m.def(
      "find_segment_intersections",
      [](const DoubleArray& points, const IndexArray& segments) {
        std::vector<Point2> pts = to_points2(points);
        std::vector<Segment> segs = to_index_rows<2>(segments, pts.size(), "segments");
        py::gil_scoped_release release;
        return find_segment_intersections(pts, segs);
      },
      py::arg("points"), py::arg("segments"),
      "Exact segment intersections. points (n,2) float64 finite and pairwise distinct; segments (m,2) int64 of\n"
      "distinct points. Returns a SegmentIntersections.");
  m.def(
      "inspect_domain",
      [](const DoubleArray& points, const IndexArray& segments, const DoubleArray& holes,
         const DoubleArray& regions, bool convex_hull_boundary, bool keep_triangulation) {
        Domain2 dom = domain_from_arrays(points, segments, holes, regions, convex_hull_boundary);
        py::gil_scoped_release release;
        return inspect_domain(dom, keep_triangulation);
      },
      py::arg("points"), py::arg("segments"), py::arg("holes"), py::arg("regions"),
      py::arg("convex_hull_boundary"), py::arg("keep_triangulation") = false,
      "What the domain covers (its constrained Delaunay triangulation). Inputs as for triangulate, validated\n"
      "(no crossings, no points inside segments). Returns a DomainCoverage; with keep_triangulation its\n"
      "triangulation is kept for refine.");
}

}  // namespace nonobtuse::bindings
