// 3D interior quality: conversion only.
#include <pybind11/pybind11.h>

#include "convert.h"
#include "nonobtuse/quality3d.h"

namespace nonobtuse::bindings {

void bind_quality3d(py::module_& m) {
  m.def(
      "closed_diametral_sphere_hits",
      [](const DoubleArray& points, const IndexArray& faces, const IndexArray& segments,
         const DoubleArray& candidates) {
        auto pts = to_points3(points, "points");
        auto f = to_index_rows<3>(faces, pts.size(), "faces");
        auto s = to_index_rows<2>(segments, pts.size(), "segments");
        auto c = to_points3(candidates, "candidates");
        ClosedSphereHits hits;
        {
          py::gil_scoped_release release;
          hits = closed_diametral_sphere_hits(pts, f, s, c);
        }
        return py::make_tuple(from_vector(hits.closed_face), from_vector(hits.closed_segment));
      },
      py::arg("points"), py::arg("faces"), py::arg("segments"), py::arg("candidates"),
      "For each candidate (c,3): the first face (f,3) and the first segment (k,2) of points (n,3) whose closed\n"
      "diametral sphere holds it (exact), -1 where none. Returns (face (c,) int32, segment (c,) int32).");
  py::class_<InteriorRefinement>(m, "InteriorRefinement", "What refine_interior returns (read-only).")
      .def_property_readonly("points", [](const InteriorRefinement& r) { return from_points3(r.points); })
      .def_property_readonly("tets", [](const InteriorRefinement& r) { return from_index_rows<4>(r.tets); })
      .def_property_readonly("tet_labels", [](const InteriorRefinement& r) { return from_vector(r.tet_labels); })
      .def_property_readonly("blocked_rows", [](const InteriorRefinement& r) { return from_vector(r.blocked_rows); })
      .def_property_readonly("small_angle_rows",
                             [](const InteriorRefinement& r) { return from_vector(r.small_angle_rows); })
      .def_property_readonly("blocked_centers",
                             [](const InteriorRefinement& r) { return from_points3(r.blocked_centers); })
      .def_property_readonly("faces", [](const InteriorRefinement& r) { return from_index_rows<3>(r.faces); })
      .def_property_readonly("face_facets", [](const InteriorRefinement& r) { return from_vector(r.face_facets); })
      .def_property_readonly("segments", [](const InteriorRefinement& r) { return from_index_rows<2>(r.segments); })
      .def_property_readonly("split_faces",
                             [](const InteriorRefinement& r) { return from_index_rows<3>(r.split_faces); })
      .def_property_readonly("split_face_facets",
                             [](const InteriorRefinement& r) { return from_vector(r.split_face_facets); })
      .def_property_readonly("split_segments",
                             [](const InteriorRefinement& r) { return from_index_rows<2>(r.split_segments); })
      .def_readonly("certified_points", &InteriorRefinement::certified_points)
      .def_readonly("step_centers", &InteriorRefinement::step_centers)
      .def_property_readonly("step_elements",
                             [](const InteriorRefinement& r) { return from_index_rows<3>(r.step_elements); })
      .def_readonly("status", &InteriorRefinement::status)
      .def_readonly("inserted", &InteriorRefinement::inserted)
      .def_readonly("placed", &InteriorRefinement::placed)
      .def_readonly("boundary_points", &InteriorRefinement::boundary_points)
      .def_readonly("boundary_rounds", &InteriorRefinement::boundary_rounds)
      .def_readonly("refused_splits", &InteriorRefinement::refused_splits);
  m.def(
      "refine_interior",
      [](const DoubleArray& points, const IndexArray& tets, const IndexArray& tet_labels, const IndexArray& faces,
         const IndexArray& segments, double radius_edge, const DoubleArray& volume_bounds, long long max_points,
         double time_limit, const DoubleArray& insert, const IndexArray& face_facets, long long max_boundary_points,
         double min_length, double sharp_dihedral_degrees, double small_apex_degrees, const IndexArray& left_alone,
         long long max_step_centers) {
        InteriorMesh mesh;
        mesh.points = to_points3(points, "points");
        mesh.tets = to_index_rows<4>(tets, mesh.points.size(), "tets");
        mesh.faces = to_index_rows<3>(faces, mesh.points.size(), "faces");
        mesh.segments = to_index_rows<2>(segments, mesh.points.size(), "segments");
        mesh.tet_labels.assign(tet_labels.data(), tet_labels.data() + tet_labels.size());
        mesh.face_facets.assign(face_facets.data(), face_facets.data() + face_facets.size());
        mesh.insert = to_points3(insert, "insert");
        if (left_alone.ndim() != 2 || left_alone.shape(1) != 3) throw InvalidInput("left_alone must have shape (e, 3)");
        for (py::ssize_t i = 0; i < left_alone.shape(0); ++i) {  // -1 marks a subsegment: not to_index_rows
          std::array<int, 3> e{};
          for (int k = 0; k < 3; ++k) {
            const auto v = left_alone.at(i, k);
            if (v < (k == 2 ? -1 : 0) || v >= static_cast<long long>(mesh.points.size()))
              throw InvalidInput("left_alone: index out of range at row " + std::to_string(i));
            e[k] = static_cast<int>(v);
          }
          mesh.left_alone.push_back(e);
        }
        InteriorBounds bounds;
        bounds.radius_edge = radius_edge;
        bounds.volume_bounds.assign(volume_bounds.data(), volume_bounds.data() + volume_bounds.size());
        bounds.max_points = max_points;
        bounds.time_limit = time_limit;
        bounds.max_boundary_points = max_boundary_points;
        bounds.min_length = min_length;
        bounds.sharp_dihedral_degrees = sharp_dihedral_degrees;
        bounds.small_apex_degrees = small_apex_degrees;
        bounds.max_step_centers = max_step_centers;
        py::gil_scoped_release release;
        return refine_interior(mesh, bounds);
      },
      py::arg("points"), py::arg("tets"), py::arg("tet_labels"), py::arg("faces"), py::arg("segments"),
      py::arg("radius_edge"), py::arg("volume_bounds"), py::arg("max_points"), py::arg("time_limit"),
      py::arg("insert") = DoubleArray(std::vector<py::ssize_t>{0, 3}), py::arg("face_facets") = IndexArray(0),
      py::arg("max_boundary_points") = 1000000, py::arg("min_length") = 0.0,
      py::arg("sharp_dihedral_degrees") = 85.0, py::arg("small_apex_degrees") = 60.0,
      py::arg("left_alone") = IndexArray(std::vector<py::ssize_t>{0, 3}), py::arg("max_step_centers") = 0,
      "Delaunay refinement of the interior of a mesh (n,3) points, (t,4) tets, (t,) labels with a Gabriel\n"
      "boundary (f,3) faces, (k,2) segments: circumcenters of tets over radius_edge (<= 0: none) or\n"
      "volume_bounds[label] inserted outside every closed diametral sphere, after inserting the points\n"
      "insert (p,3) outside them; with face_facets (f,) the facet id of each face, a center in a closed\n"
      "sphere splits the boundary instead, but near small input angles (sharp_dihedral_degrees,\n"
      "small_apex_degrees: small_angle_rows; see quality3d.h), or in that of a subfacet (a,b,c) or\n"
      "subsegment (a,b,-1) of left_alone (e,3);\n"
      "max_step_centers: blocked centers a boundary step splits for at most (0: all).");
}

}  // namespace nonobtuse::bindings
