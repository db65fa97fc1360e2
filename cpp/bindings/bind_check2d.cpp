// 2D checks: exact edge classification and exact control-volume coupling signs.
#include <pybind11/pybind11.h>

#include "bind_mesh2d.h"
#include "nonobtuse/check2d.h"
#include "nonobtuse/control_volumes2d.h"

namespace nonobtuse::bindings {
namespace {

Mesh2 mesh_from_arrays(const DoubleArray& points, const IndexArray& triangles, const IndexArray& segments,
                       const DoubleArray& triangle_region) {
  Mesh2 m;
  m.points = to_points2(points);
  m.triangles = to_index_rows<3>(triangles, m.points.size(), "triangles");
  m.segments = to_index_rows<2>(segments, m.points.size(), "segments");
  const double* r = triangle_region.data();
  m.triangle_region.assign(r, r + triangle_region.size());
  return m;
}

py::dict edges_to_dict(const std::vector<EdgeReport>& edges) {
  const auto n = static_cast<py::ssize_t>(edges.size());
  IndexArray edge({n, py::ssize_t{2}}), triangle({n, py::ssize_t{2}}), apex({n, py::ssize_t{2}});
  py::array_t<std::int8_t> kind(n), angle({n, py::ssize_t{2}}), delaunay(n);
  auto *ed = edge.mutable_data(), *tr = triangle.mutable_data(), *ap = apex.mutable_data();
  auto *ki = kind.mutable_data(), *an = angle.mutable_data(), *de = delaunay.mutable_data();
  for (py::ssize_t i = 0; i < n; ++i) {
    const EdgeReport& e = edges[i];
    ed[2 * i] = e.edge[0];
    ed[2 * i + 1] = e.edge[1];
    ki[i] = static_cast<std::int8_t>(e.kind);
    de[i] = e.locally_delaunay;
    const EdgeSide* sides[2] = {&e.left, &e.right};
    for (int s = 0; s < 2; ++s) {
      tr[2 * i + s] = sides[s]->triangle;
      ap[2 * i + s] = sides[s]->apex;
      an[2 * i + s] = static_cast<std::int8_t>(sides[s]->angle);
    }
  }
  py::dict d;
  d["edges"] = edge;
  d["kind"] = kind;
  d["triangle"] = triangle;
  d["apex"] = apex;
  d["angle"] = angle;
  d["locally_delaunay"] = delaunay;
  return d;
}

}  // namespace

void bind_check2d(py::module_& m) {
  m.def(
      "classify_edges",
      [](const DoubleArray& points, const IndexArray& triangles, const IndexArray& segments,
         const DoubleArray& triangle_region) {
        Mesh2 mesh = mesh_from_arrays(points, triangles, segments, triangle_region);
        std::vector<EdgeReport> edges;
        {
          py::gil_scoped_release release;
          edges = classify_edges(mesh);
        }
        return edges_to_dict(edges);
      },
      py::arg("points"), py::arg("triangles"), py::arg("segments"), py::arg("triangle_region"),
      "Exact classification of every edge of a ccw triangle mesh, sorted by (a, b), a < b.\n"
      "triangle_region: (m,) float64 or empty. Returns a dict: edges (E,2) int64; kind (E,) int8\n"
      "(0 boundary, 1 interface, 2 interior); triangle, apex (E,2) int64 [left, right], -1 where no triangle;\n"
      "angle (E,2) int8 (0 acute, 1 right, 2 obtuse; meaningless where triangle is -1);\n"
      "locally_delaunay (E,) int8.");
  m.def(
      "coupling_signs",
      [](const DoubleArray& points, const IndexArray& triangles, const IndexArray& segments,
         const DoubleArray& triangle_region, const DoubleArray& conductivity) {
        Mesh2 mesh = mesh_from_arrays(points, triangles, segments, triangle_region);
        std::vector<double> k(conductivity.data(), conductivity.data() + conductivity.size());
        std::vector<EdgeReport> edges;
        std::vector<int> signs;
        {
          py::gil_scoped_release release;
          edges = classify_edges(mesh);
          signs = coupling_signs(mesh, edges, k);
        }
        py::dict d = edges_to_dict(edges);
        d["sign"] = from_vector(std::vector<std::int8_t>(signs.begin(), signs.end()));
        return d;
      },
      py::arg("points"), py::arg("triangles"), py::arg("segments"), py::arg("triangle_region"),
      py::arg("conductivity"),
      "classify_edges plus sign (E,) int8: the exact sign (-1, 0, +1) of each edge's control-volume coupling\n"
      "coefficient sum_t k_t cot(apex_t) / 2. conductivity: (m,) float64 > 0 per triangle, or empty for k = 1.");
}

}  // namespace nonobtuse::bindings
