// Interior quality and size: the Quality2DOptions given to refine and the Quality2DStats it returns.
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <sstream>

#include "nonobtuse/quality2d.h"
#include "nonobtuse/types.h"

namespace nonobtuse::bindings {
namespace py = pybind11;

void bind_quality2d(py::module_& m) {
  py::class_<Quality2DOptions>(m, "Quality2DOptions", "What makes a triangle bad for refine (see nonobtuse.refine).")
      .def(py::init<>())
      .def_readwrite("min_angle_degrees", &Quality2DOptions::min_angle_degrees)
      .def_readwrite("max_area", &Quality2DOptions::max_area, "<= 0: none")
      .def_readwrite("region_max_area", &Quality2DOptions::region_max_area, "[(attribute, area), ...]")
      .def_readwrite("max_interior", &Quality2DOptions::max_interior, "< 0: default_interior_budget")
      .def_readwrite("minimal_boundary_first", &Quality2DOptions::minimal_boundary_first,
                     "greedy strategy: the minimal boundary before the quality refinement (default False: "
                     "Triangle's midpoints and shells by the quality refinement)")
      .def("enabled", &Quality2DOptions::enabled, "whether any criterion is set")
      .def(
          "set_max_area_at",
          [](Quality2DOptions& o, std::function<double(double, double)> f) {
            // The core calls it at triangle centroids (holding the GIL while Python runs); a value that is not a
            // positive finite number is bad input, named with its place.
            o.max_area_at = [f = std::move(f)](double x, double y) {
              const double a = f(x, y);
              if (!(a > 0.0 && std::isfinite(a))) {
                std::ostringstream msg;
                msg.precision(17);
                msg << "size(" << x << ", " << y << ") returned " << a << ": a maximum area must be a positive "
                    << "finite number";
                throw InvalidInput(msg.str());
              }
              return a;
            };
          },
          py::arg("size"), "size(x, y) -> the largest area of a triangle whose centroid is (x, y)");
  py::class_<Quality2DStats>(m, "Quality2DStats", "What the interior refinement did and left (read-only).")
      .def_readonly("interior_points", &Quality2DStats::interior_points)
      .def_readonly("interior_budget", &Quality2DStats::interior_budget)
      .def_readonly("boundary_splits", &Quality2DStats::boundary_splits)
      .def_readonly("boundary_points_removed", &Quality2DStats::boundary_points_removed)
      .def_readonly("bad_triangles", &Quality2DStats::bad_triangles)
      .def_readonly("small_angle_triangles", &Quality2DStats::small_angle_triangles)
      .def_readonly("triangles", &Quality2DStats::triangles)
      .def_readonly("min_angle_degrees", &Quality2DStats::min_angle_degrees)
      .def_readonly("min_angle_outside_small_angles_degrees",
                    &Quality2DStats::min_angle_outside_small_angles_degrees)
      .def_readonly("max_area", &Quality2DStats::max_area);
  m.def("default_interior_budget", &default_interior_budget, py::arg("n_points"), py::arg("domain_area"),
        py::arg("smallest_area_limit"), "The interior budget refine uses when max_interior < 0 (quality2d.h).");
}

}  // namespace nonobtuse::bindings
