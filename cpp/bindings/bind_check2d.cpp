// 2D checks: exact edge classification and exact control-volume coupling signs.
#include <pybind11/pybind11.h>

#include <string>

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

using Int8Array = py::array_t<std::int8_t>;

// The classification of every edge as numpy columns, converted once (the Python side reads them repeatedly).
struct EdgeClassification {
  IndexArray edges, triangle, apex;
  Int8Array kind, angle, locally_delaunay;
  Int8Array sign;  // coupling_signs only; empty from classify_edges
};

EdgeClassification classification(const std::vector<EdgeReport>& edges) {
  const auto n = static_cast<py::ssize_t>(edges.size());
  EdgeClassification c{IndexArray({n, py::ssize_t{2}}), IndexArray({n, py::ssize_t{2}}),
                       IndexArray({n, py::ssize_t{2}}), Int8Array(n), Int8Array({n, py::ssize_t{2}}), Int8Array(n),
                       Int8Array(0)};
  auto *ed = c.edges.mutable_data(), *tr = c.triangle.mutable_data(), *ap = c.apex.mutable_data();
  auto *ki = c.kind.mutable_data(), *an = c.angle.mutable_data(), *de = c.locally_delaunay.mutable_data();
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
  return c;
}

}  // namespace

void bind_check2d(py::module_& m) {
  py::class_<EdgeClassification>(m, "EdgeClassification",
                                 "Every edge of a mesh classified exactly, sorted by (a, b), a < b (read-only).")
      .def_readonly("edges", &EdgeClassification::edges, "(E, 2) int64 (a, b), a < b")
      .def_readonly("kind", &EdgeClassification::kind, "(E,) int8: 0 boundary, 1 interface, 2 interior")
      .def_readonly("triangle", &EdgeClassification::triangle, "(E, 2) int64 [left, right], -1 where none")
      .def_readonly("apex", &EdgeClassification::apex, "(E, 2) int64 [left, right], -1 where no triangle")
      .def_readonly("angle", &EdgeClassification::angle,
                    "(E, 2) int8: 0 acute, 1 right, 2 obtuse (meaningless where triangle is -1)")
      .def_readonly("locally_delaunay", &EdgeClassification::locally_delaunay, "(E,) int8")
      .def_readonly("sign", &EdgeClassification::sign,
                    "(E,) int8 exact sign of each coupling coefficient (coupling_signs; empty otherwise)")
      .def("__repr__",
           [](const EdgeClassification& c) { return "<EdgeClassification edges=" + std::to_string(c.kind.size()) + ">"; });
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
        return classification(edges);
      },
      py::arg("points"), py::arg("triangles"), py::arg("segments"), py::arg("triangle_region"),
      "Exact classification of every edge of a ccw triangle mesh (an EdgeClassification).\n"
      "triangle_region: (m,) float64 or empty.");
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
        EdgeClassification c = classification(edges);
        c.sign = from_vector(std::vector<std::int8_t>(signs.begin(), signs.end()));
        return c;
      },
      py::arg("points"), py::arg("triangles"), py::arg("segments"), py::arg("triangle_region"),
      py::arg("conductivity"),
      "classify_edges with sign (E,) int8: the exact sign (-1, 0, +1) of each edge's control-volume coupling\n"
      "coefficient sum_t k_t cot(apex_t) / 2. conductivity: (m,) float64 > 0 per triangle, or empty for k = 1.");
}

}  // namespace nonobtuse::bindings
