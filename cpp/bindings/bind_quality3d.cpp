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
}

}  // namespace nonobtuse::bindings
