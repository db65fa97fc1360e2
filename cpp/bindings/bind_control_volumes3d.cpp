// 3D control volumes: dual (Voronoi face) areas with exact signs, cell volumes. Conversion only.
#include <pybind11/pybind11.h>

#include "convert.h"
#include "nonobtuse/control_volumes3d.h"

namespace nonobtuse::bindings {
namespace {

// f(points, tets) on the converted arrays (the tets' indices checked against the points), the GIL released.
template <class F>
auto on_tets(const DoubleArray& points, const IndexArray& tets, F f) {
  std::vector<Point3> p = to_points3(points);
  std::vector<std::array<int, 4>> t = to_index_rows<4>(tets, p.size(), "tets");
  py::gil_scoped_release release;
  return f(p, t);
}

// The dict of what dual_area_signs computes (control_volumes3d's adds the magnitudes).
py::dict signs_dict(const ControlVolumes3D& r) {
  py::dict d;
  d["edges"] = from_index_rows(r.edges);
  d["sign"] = from_vector(std::vector<std::int8_t>(r.signs.begin(), r.signs.end()));
  d["exact_evaluations"] = r.exact_evaluations;
  return d;
}

}  // namespace

void bind_control_volumes3d(py::module_& m) {
  m.def(
      "control_volumes3d",
      [](const DoubleArray& points, const IndexArray& tets) {
        const ControlVolumes3D r = on_tets(points, tets, control_volumes3d);
        py::dict d = signs_dict(r);
        d["dual_areas"] = from_vector(r.dual_areas);
        d["lengths"] = from_vector(r.lengths);
        d["volumes"] = from_vector(r.volumes);
        d["flat_in_floating_point"] = r.flat_in_floating_point;
        return d;
      },
      py::arg("points"), py::arg("tets"),
      "The Voronoi face area dual to every edge of a tet mesh (per-tet decomposition, clipped to the mesh), its\n"
      "exact sign, and the cell volumes. points (n,3) float64, tets (t,4) int64 positively oriented\n"
      "(InvalidInputError otherwise). Returns a dict: edges (E,2) int64 (a < b, sorted), sign (E,) int8\n"
      "(-1, 0, +1), dual_areas (E,) float64 (exact sign times the float magnitude), lengths (E,) float64,\n"
      "volumes (n,) float64, exact_evaluations (int: edges the interval filter left to exact arithmetic),\n"
      "flat_in_floating_point (int: tets flat in doubles, whose circumcenters are exact, rounded).");
  m.def(
      "dual_area_signs",
      [](const DoubleArray& points, const IndexArray& tets) {
        return signs_dict(on_tets(points, tets, dual_area_signs));
      },
      py::arg("points"), py::arg("tets"),
      "control_volumes3d's edges, sign and exact_evaluations alone (no floating-point magnitudes, lengths or\n"
      "volumes): for counting wrong-signed couplings. The same arguments and errors.");
  m.def(
      "exact_tet_circumspheres",
      [](const DoubleArray& points, const IndexArray& tets) {
        const TetCircumspheres r = on_tets(points, tets, exact_tet_circumspheres);
        return py::make_tuple(from_points3(r.centers), from_vector(r.squared_radii), from_vector(r.volumes));
      },
      py::arg("points"), py::arg("tets"),
      "Circumcenters (t,3), squared circumradii (t,) and signed volumes (t,) of tets (t,4) int64 over points\n"
      "(n,3) float64, each computed exactly and rounded to nearest (ties to even); +-inf beyond the double range;\n"
      "a coplanar tet: center and squared radius inf, volume 0.");
}

}  // namespace nonobtuse::bindings
