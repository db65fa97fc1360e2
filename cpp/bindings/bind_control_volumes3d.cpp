// 3D control volumes: exact signs of the dual (Voronoi face) areas. Conversion only.
#include <pybind11/pybind11.h>

#include "convert.h"
#include "nonobtuse/control_volumes3d.h"

namespace nonobtuse::bindings {

void bind_control_volumes3d(py::module_& m) {
  m.def(
      "dual_area_signs",
      [](const DoubleArray& points, const IndexArray& tets) {
        std::vector<Point3> p = to_points3(points);
        std::vector<std::array<int, 4>> t = to_index_rows<4>(tets, p.size(), "tets");
        DualAreaSigns r;
        {
          py::gil_scoped_release release;
          r = dual_area_signs(p, t);
        }
        py::dict d;
        d["edges"] = from_index_rows(r.edges);
        d["sign"] = from_vector(std::vector<std::int8_t>(r.signs.begin(), r.signs.end()));
        d["exact_evaluations"] = r.exact_evaluations;
        return d;
      },
      py::arg("points"), py::arg("tets"),
      "Exact sign of the Voronoi face area dual to every edge of a tet mesh (per-tet decomposition, clipped to\n"
      "the mesh). points (n,3) float64, tets (t,4) int64 positively oriented (InvalidInputError otherwise).\n"
      "Returns a dict: edges (E,2) int64 (a < b, sorted), sign (E,) int8 (-1, 0, +1), exact_evaluations (int:\n"
      "edges the interval filter left to exact arithmetic).");
}

}  // namespace nonobtuse::bindings
