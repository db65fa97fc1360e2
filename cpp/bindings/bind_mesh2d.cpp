// 2D domains and meshes: the Mesh2D result class, triangulate.
#include <pybind11/pybind11.h>

#include <string>

#include "bind_mesh2d.h"
#include "nonobtuse/triangulate.h"

namespace nonobtuse::bindings {

Domain2 domain_from_arrays(const DoubleArray& points, const IndexArray& segments, const DoubleArray& holes,
                           const DoubleArray& region_seeds, bool convex_hull_boundary) {
  Domain2 d;
  d.points = to_points2(points);
  d.segments = to_index_rows<2>(segments, d.points.size(), "segments");
  d.holes = to_points2(holes, "holes");
  require_shape(region_seeds, 3, "regions");
  auto* r = region_seeds.data();
  for (py::ssize_t i = 0; region_seeds.ndim() == 2 && i < region_seeds.shape(0); ++i)
    d.regions.push_back({{r[3 * i], r[3 * i + 1]}, r[3 * i + 2]});
  d.convex_hull_boundary = convex_hull_boundary;
  return d;
}

void bind_mesh2d(py::module_& m) {
  py::class_<Mesh2>(m, "Mesh2D",
                    "A triangulated 2D domain (read-only; each array attribute is a new array on each access).")
      .def_property_readonly("points", [](const Mesh2& s) { return from_points2(s.points); },
                             "(n, 2) float64: the domain's points in input order, then Steiner points.")
      .def_property_readonly("triangles", [](const Mesh2& s) { return from_index_rows<3>(s.triangles); },
                             "(m, 3) int64, counter-clockwise, domain triangles only.")
      .def_property_readonly("segments", [](const Mesh2& s) { return from_index_rows<2>(s.segments); },
                             "(k, 2) int64: every constrained subsegment (boundary, interface, dangling).")
      .def_property_readonly("triangle_region", [](const Mesh2& s) { return from_vector(s.triangle_region); },
                             "(m,) float64 region attribute per triangle (0 where no region seed reached).")
      .def("__repr__", [](const Mesh2& s) {
        return "<Mesh2D points=" + std::to_string(s.points.size()) +
               " triangles=" + std::to_string(s.triangles.size()) + " segments=" + std::to_string(s.segments.size()) +
               ">";
      });
  m.def(
      "triangulate",
      [](const DoubleArray& points, const IndexArray& segments, const DoubleArray& holes,
         const DoubleArray& regions, bool convex_hull_boundary) {
        Domain2 d = domain_from_arrays(points, segments, holes, regions, convex_hull_boundary);
        py::gil_scoped_release release;
        return triangulate(d);
      },
      py::arg("points"), py::arg("segments"), py::arg("holes"), py::arg("regions"),
      py::arg("convex_hull_boundary"),
      "Constrained Delaunay triangulation of a validated domain. regions: (r, 3) rows x, y, attribute.\n"
      "Returns a Mesh2D.");
}

}  // namespace nonobtuse::bindings
