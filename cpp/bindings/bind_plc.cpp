// 3D PLC predicates: orientation and collinearity signs, triangle-soup self-intersections, Delaunay cells.
#include <optional>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "convert.h"
#include "convert_plc.h"
#include "nonobtuse/plc_predicates.h"

namespace nonobtuse::bindings {

void bind_plc(py::module_& m) {
  m.def(
      "plc_orient3d",
      [](const DoubleArray& points, const IndexArray& quads) {
        auto p = to_points3(points);
        auto q = to_index_rows<4>(quads, p.size(), "quads");
        return from_vector(orient3d_signs(p, q));
      },
      py::arg("points"), py::arg("quads"),
      "Exact orient3d sign (int8: +1, 0 coplanar, -1) of every row (a, b, c, d) of quads (m, 4).");
  m.def(
      "plc_collinear",
      [](const DoubleArray& points, const IndexArray& triples) {
        auto p = to_points3(points);
        auto t = to_index_rows<3>(triples, p.size(), "triples");
        return from_vector(collinear_flags(p, t));
      },
      py::arg("points"), py::arg("triples"),
      "Exact collinearity (int8 1/0) of every row (a, b, c) of triples (m, 3).");
  m.def(
      "plc_self_intersections",
      [](const DoubleArray& points, const IndexArray& triangles, std::size_t max_pairs) {
        auto p = to_points3(points);
        auto t = to_index_rows<3>(triangles, p.size(), "triangles");
        std::vector<std::array<int, 2>> pairs;
        {
          py::gil_scoped_release release;
          pairs = triangle_soup_self_intersections(p, t, max_pairs);
        }
        return from_index_rows<2>(pairs);
      },
      py::arg("points"), py::arg("triangles"), py::arg("max_pairs") = 1,
      "Pairs (k, 2) int64 (i < j) of triangles intersecting beyond shared vertices/edges (exact);\n"
      "triangles must be non-degenerate and distinct. At most max_pairs rows.");
  m.def(
      "delaunay_tetrahedra",
      [](const DoubleArray& points) {
        auto p = to_points3(points);
        std::vector<std::array<int, 4>> cells;
        {
          py::gil_scoped_release release;
          cells = delaunay_tetrahedra(p);
        }
        return from_index_rows<4>(cells);
      },
      py::arg("points"),
      "Finite cells (t, 4) int64 of the Delaunay tetrahedralization of points (n, 3), positively oriented.\n"
      "Raises InvalidInputError when two points coincide.");
  m.def(
      "plc_unbalanced_edge",
      [](const DoubleArray& points, const IndexArray& triangles) {
        auto t = to_index_rows<3>(triangles, to_points3(points).size(), "triangles");
        auto e = unbalanced_edge(t);
        return e[0] < 0 ? py::object(py::none()) : py::object(py::make_tuple(e[0], e[1]));
      },
      py::arg("points"), py::arg("triangles"),
      "The smallest edge (a, b), a < b, that the triangles (m, 3) traverse more often one way than the other,\n"
      "or None when they form a closed oriented surface.");
  m.def(
      "surface_winding_numbers",
      [](const DoubleArray& points, const IndexArray& triangles, const DoubleArray& queries) {
        auto p = to_points3(points);
        auto t = to_index_rows<3>(triangles, p.size(), "triangles");
        auto q = to_points3(queries, "queries");
        std::vector<int> w;
        {
          py::gil_scoped_release release;
          w = surface_winding_numbers(p, t, q);
        }
        return from_vector(std::vector<std::int64_t>(w.begin(), w.end()));
      },
      py::arg("points"), py::arg("triangles"), py::arg("queries"),
      "Exact winding number (q,) int64 of the oriented triangles (m, 3) around each query (q, 3): vertical ray\n"
      "casting from the query symbolically perturbed off the surface; +1 inside an outward closed surface.");
  m.def(
      "delaunay_cells_inside_surface",
      [](const DoubleArray& points, const IndexArray& triangles, const std::optional<IndexArray>& cells) {
        auto p = to_points3(points);
        auto t = to_index_rows<3>(triangles, p.size(), "triangles");
        std::optional<std::vector<std::array<int, 4>>> given;
        if (cells) given = to_index_rows<4>(*cells, p.size(), "cells");
        std::vector<std::array<int, 4>> inside;
        {
          py::gil_scoped_release release;
          inside = given ? cells_inside_surface(p, t, *given) : delaunay_cells_inside_surface(p, t);
        }
        return from_index_rows<4>(inside);
      },
      py::arg("points"), py::arg("triangles"), py::arg("cells") = py::none(),
      "Cells (t, 4) int64 of delaunay_tetrahedra(points) (or of the given cells (c, 4), e.g. the\n"
      "delaunay_cells of delaunay_restricted_to_plc) whose centroid has a non-zero exact winding number with\n"
      "respect to the closed oriented surface triangles (m, 3); sorted.");
  m.def(
      "delaunay_restricted_to_plc",
      [](const DoubleArray& points, const IndexArray& triangles, const IndexArray& facet_ids,
         const IndexArray& segments, const DoubleArray& holes, const DoubleArray& regions) {
        PLC3 plc = to_plc3(points, triangles, facet_ids, segments, holes, regions);
        PlcDelaunay r;
        {
          py::gil_scoped_release release;
          r = delaunay_restricted_to_plc(plc);
        }
        py::dict d;
        d["tets"] = from_index_rows<4>(r.tets);
        d["tet_regions"] = from_vector(r.tet_regions);
        d["boundary_faces"] = from_index_rows<3>(r.boundary_faces);
        d["face_markers"] = from_vector(std::vector<std::int64_t>(r.face_markers.begin(), r.face_markers.end()));
        d["uncovered_facets"] = from_vector(std::vector<std::int64_t>(r.uncovered_facets.begin(),
                                                                      r.uncovered_facets.end()));
        d["delaunay_cells"] = from_index_rows<4>(r.delaunay_cells);
        return d;
      },
      py::arg("points"), py::arg("triangles"), py::arg("facet_ids"), py::arg("segments"), py::arg("holes"),
      py::arg("regions"),
      "The Delaunay tetrahedralization of a PLC's vertices restricted to its regions (exact flood fill across\n"
      "faces on no facet). Returns a dict: tets (t, 4), tet_regions (t,), boundary_faces (f, 3), face_markers\n"
      "(f,), uncovered_facets (facet ids the faces do not cover; empty iff it conforms to every facet),\n"
      "delaunay_cells (c, 4): for a triangle surface that does not conform, every Delaunay cell (tets etc.\n"
      "then empty); else (0, 4).");
}

}  // namespace nonobtuse::bindings
