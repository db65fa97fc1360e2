// Benchmark peers: conforming_gabriel_points.
#include <pybind11/pybind11.h>

#include "bind_mesh2d.h"
#include "nonobtuse/peers2d.h"

namespace nonobtuse::bindings {

void bind_peers(py::module_& m) {
  m.def(
      "conforming_gabriel_points",
      [](const DoubleArray& points, const IndexArray& segments, const DoubleArray& holes, const DoubleArray& regions,
         bool convex_hull_boundary) {
        Domain2 d = domain_from_arrays(points, segments, holes, regions, convex_hull_boundary);
        py::gil_scoped_release release;
        return conforming_gabriel_points(d);
      },
      py::arg("points"), py::arg("segments"), py::arg("holes"), py::arg("regions"), py::arg("convex_hull_boundary"),
      "CGAL make_conforming_Gabriel_2 on the domain's constrained Delaunay triangulation (benchmark peer): the\n"
      "number of vertices of the result (input points + Steiner points).");
}

}  // namespace nonobtuse::bindings
