// 2D domains and meshes: triangulate.
#include <pybind11/pybind11.h>

#include "bind_mesh2d.h"
#include "nonobtuse/triangulate.h"

namespace nonobtuse::bindings {

py::dict mesh_to_dict(const Mesh2& mesh) {
  py::dict d;
  d["points"] = from_points2(mesh.points);
  d["triangles"] = from_index_rows<3>(mesh.triangles);
  d["segments"] = from_index_rows<2>(mesh.segments);
  d["triangle_region"] = from_vector(mesh.triangle_region);
  return d;
}

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
  m.def(
      "triangulate",
      [](const DoubleArray& points, const IndexArray& segments, const DoubleArray& holes,
         const DoubleArray& regions, bool convex_hull_boundary) {
        Domain2 d = domain_from_arrays(points, segments, holes, regions, convex_hull_boundary);
        Mesh2 mesh;
        {
          py::gil_scoped_release release;
          mesh = triangulate(d);
        }
        return mesh_to_dict(mesh);
      },
      py::arg("points"), py::arg("segments"), py::arg("holes"), py::arg("regions"),
      py::arg("convex_hull_boundary"),
      "Constrained Delaunay triangulation of a validated domain. regions: (r, 3) rows x, y, attribute.\n"
      "Returns a dict: points (n,2) float64, triangles (m,3) int64 ccw, segments (k,2) int64,\n"
      "triangle_region (m,) float64.");
}

}  // namespace nonobtuse::bindings
