// 3D Gabriel certificate and refinement: conversion only.
#include <map>
#include <string>

#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "convert.h"
#include "nonobtuse/gabriel3d.h"

namespace nonobtuse::bindings {
namespace {

py::dict report_to_dict(const GabrielReport& r) {
  py::dict d;
  for (auto [name, list] : {std::pair{"faces", &r.faces}, std::pair{"segments", &r.segments}}) {
    std::vector<std::int64_t> index, vertex;
    std::vector<double> depth;
    for (const auto& e : *list) {
      index.push_back(e.index);
      vertex.push_back(e.vertex);
      depth.push_back(e.depth);
    }
    d[(std::string(name) + "_index").c_str()] = from_vector(index);
    d[(std::string(name) + "_vertex").c_str()] = from_vector(vertex);
    d[(std::string(name) + "_depth").c_str()] = from_vector(depth);
  }
  d["candidates"] = r.candidates;
  d["unchecked_faces"] = r.unchecked_faces;
  d["unchecked_segments"] = r.unchecked_segments;
  return d;
}

py::dict diagnosis_to_dict(const Refine3Diagnosis& diag) {
  py::list angles, per_vertex, per_segment;
  for (const auto& a : diag.smallest_angles)
    angles.append(py::dict(py::arg("kind") = a.kind, py::arg("degrees") = a.degrees,
                           py::arg("vertices") = a.vertices, py::arg("facets") = a.facets));
  for (auto [list, counts] : {std::pair{&per_vertex, &diag.per_vertex}, std::pair{&per_segment, &diag.per_segment}})
    for (const auto& c : *counts) list->append(py::dict(py::arg("where") = c.where, py::arg("count") = c.count));
  py::dict d;
  d["smallest_angles"] = angles;
  d["steiner_per_vertex"] = per_vertex;
  d["steiner_per_segment"] = per_segment;
  d["stop_reason"] = diag.stop_reason;
  return d;
}

py::dict result_to_dict(const Refine3Result& r) {
  py::dict d;
  d["points"] = from_points3(r.points);
  d["tets"] = from_index_rows<4>(r.tets);
  d["boundary_faces"] = from_index_rows<3>(r.boundary_faces);
  d["face_markers"] = from_vector(std::vector<std::int64_t>(r.face_markers.begin(), r.face_markers.end()));
  d["segments"] = from_index_rows<2>(r.segments);
  d["tet_regions"] = from_vector(r.tet_regions);
  d["status"] = to_string(r.status);
  d["steiner_on_segments"] = r.steiner_on_segments;
  d["greedy_splits"] = r.greedy_splits;
  d["strategy"] = r.strategy;
  d["other_attempt"] = r.other_attempt;
  d["protecting_balls"] = r.protecting_balls;
  d["steiner_on_facets"] = r.steiner_on_facets;
  d["seconds"] = r.seconds;
  d["smallest_subsegment"] = r.smallest_subsegment;
  d["certificate"] = report_to_dict(r.certificate);
  d["diagnosis"] = diagnosis_to_dict(r.diagnosis);
  d["volume_mesh"] = r.volume_mesh;
  return d;
}

}  // namespace

void bind_gabriel3d(py::module_& m) {
  m.def(
      "check_gabriel",
      [](const DoubleArray& points, const IndexArray& faces, const IndexArray& segments) {
        auto pts = to_points3(points, "points");
        auto f = to_index_rows<3>(faces, pts.size(), "faces");
        auto s = to_index_rows<2>(segments, pts.size(), "segments");
        GabrielReport report;
        {
          py::gil_scoped_release release;
          report = check_gabriel(pts, f, s);
        }
        return report_to_dict(report);
      },
      py::arg("points"), py::arg("faces"), py::arg("segments"),
      "Exact diametral-sphere test of every face (f,3) and segment (k,2) against all points (n,3).\n"
      "Returns a dict: faces_index/faces_vertex (int64), faces_depth (float64), the same for segments, candidates.");
  m.def(
      "refine_gabriel",
      [](const DoubleArray& points, const IndexArray& triangles, const IndexArray& facet_ids,
         const IndexArray& segments, const DoubleArray& holes, const DoubleArray& regions, long max_steiner,
         double min_length, double time_limit, const std::string& split, bool protected_fallback, long progress_every,
         std::function<void(long, long, long, double)> progress) {
        PLC3 plc;
        plc.points = to_points3(points, "points");
        plc.triangles = to_index_rows<3>(triangles, plc.points.size(), "triangles");
        auto* ids = facet_ids.data();
        plc.facet_ids.assign(ids, ids + facet_ids.size());
        plc.segments = to_index_rows<2>(segments, plc.points.size(), "segments");
        plc.holes = to_points3(holes, "holes");
        require_shape(regions, 4, "regions");
        auto* r = regions.data();
        for (py::ssize_t i = 0; regions.ndim() == 2 && i < regions.shape(0); ++i)
          plc.regions.push_back({r[4 * i], r[4 * i + 1], r[4 * i + 2], r[4 * i + 3]});
        const std::map<std::string, SplitRule> rules = {
            {"shells", SplitRule::Shells},
            {"midpoint", SplitRule::Midpoint},
            {"greedy", SplitRule::Greedy},
            {"protected", SplitRule::Protected}};
        if (!rules.count(split))
          throw InvalidInput("split must be 'shells', 'midpoint', 'greedy' or 'protected', not '" + split + "'");
        Refine3Options o;
        o.max_steiner = max_steiner;
        o.min_length = min_length;
        o.time_limit = time_limit;
        o.split = rules.at(split);
        o.protected_fallback = protected_fallback;
        o.progress_every = progress_every;
        if (progress)
          o.progress = [progress](const Refine3Progress& p) {
            py::gil_scoped_acquire acquire;
            progress(p.steiner_points, p.encroached_segments, p.encroached_facets, p.seconds);
          };
        Refine3Result result;
        {
          py::gil_scoped_release release;
          result = refine_gabriel(plc, o);
        }
        return result_to_dict(result);
      },
      py::arg("points"), py::arg("triangles"), py::arg("facet_ids"), py::arg("segments"), py::arg("holes"),
      py::arg("regions"), py::arg("max_steiner"), py::arg("min_length"), py::arg("time_limit"), py::arg("split"),
      py::arg("protected_fallback"), py::arg("progress_every"), py::arg("progress"),
      "Gabriel refinement of a PLC. progress: None or f(steiner, encroached_segments, encroached_facets, seconds).\n"
      "Returns a dict: points, tets, boundary_faces, face_markers, segments, tet_regions, status, steiner counts,\n"
      "seconds, smallest_subsegment, certificate (as check_gabriel), diagnosis.");
}

}  // namespace nonobtuse::bindings
