// 3D Gabriel certificate and refinement: conversion only.
#include <map>
#include <optional>
#include <string>

#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "convert.h"
#include "convert_plc.h"
#include "nonobtuse/gabriel3d.h"

namespace nonobtuse::bindings {
namespace {

// One kind of encroachment (faces or segments) as numpy columns: index, vertex, depth.
template <class T, class F>
py::array_t<T> column(const std::vector<Encroachment>& list, F field) {
  std::vector<T> v;
  v.reserve(list.size());
  for (const auto& e : list) v.push_back(static_cast<T>(field(e)));
  return from_vector(v);
}

void bind_result_classes(py::module_& m) {
  using Report = GabrielReport;
  py::class_<Report>(m, "GabrielCertificate",
                     "Encroached boundary faces and segments (read-only; a new array on each access).")
      .def_property_readonly("faces", [](const Report& r) { return column<std::int64_t>(r.faces, [](auto& e) { return e.index; }); },
                             "(a,) int64 rows of the faces checked that are encroached")
      .def_property_readonly("face_vertices", [](const Report& r) { return column<std::int64_t>(r.faces, [](auto& e) { return e.vertex; }); },
                             "(a,) int64 the deepest encroaching vertex of each")
      .def_property_readonly("face_depths", [](const Report& r) { return column<double>(r.faces, [](auto& e) { return e.depth; }); },
                             "(a,) float64 1 - |vertex - center| / radius (floating point, for display)")
      .def_property_readonly("segments", [](const Report& r) { return column<std::int64_t>(r.segments, [](auto& e) { return e.index; }); },
                             "(b,) int64 rows of the segments checked that are encroached")
      .def_property_readonly("segment_vertices", [](const Report& r) { return column<std::int64_t>(r.segments, [](auto& e) { return e.vertex; }); })
      .def_property_readonly("segment_depths", [](const Report& r) { return column<double>(r.segments, [](auto& e) { return e.depth; }); })
      .def_readonly("candidates", &Report::candidates, "(simplex, vertex) pairs passed to the exact predicate")
      .def_readonly("unchecked_faces", &Report::unchecked_faces, "rows refine_gabriel's time_limit left unchecked")
      .def_readonly("unchecked_segments", &Report::unchecked_segments)
      .def("__repr__", [](const Report& r) {
        return "<GabrielCertificate encroached faces=" + std::to_string(r.faces.size()) +
               " segments=" + std::to_string(r.segments.size()) + ">";
      });
  py::class_<InputAngle>(m, "InputAngle3D", "One small angle of the input (degrees, floating point).")
      .def_readonly("kind", &InputAngle::kind, "'segment-segment', 'segment-facet' or 'dihedral'")
      .def_readonly("degrees", &InputAngle::degrees)
      .def_readonly("vertices", &InputAngle::vertices)
      .def_readonly("facets", &InputAngle::facets)
      .def("__repr__", [](const InputAngle& a) {
        return "<InputAngle3D " + a.kind + " degrees=" + std::to_string(a.degrees) + ">";
      });
  py::class_<SteinerCount>(m, "SteinerCount", "Steiner points near an input vertex or on an input segment.")
      .def_readonly("where", &SteinerCount::where, "an input vertex, or the two ends of an input segment")
      .def_readonly("count", &SteinerCount::count)
      .def("__repr__", [](const SteinerCount& c) { return "<SteinerCount count=" + std::to_string(c.count) + ">"; });
  py::class_<Refine3DDiagnosis>(m, "Refine3DDiagnosis", "What drove a 3D refinement and why it stopped.")
      .def_readonly("smallest_angles", &Refine3DDiagnosis::smallest_angles)
      .def_readonly("steiner_per_vertex", &Refine3DDiagnosis::per_vertex)
      .def_readonly("steiner_per_segment", &Refine3DDiagnosis::per_segment)
      .def_readonly("encroached_per_segment", &Refine3DDiagnosis::encroached_per_segment)
      .def_readonly("stop_reason", &Refine3DDiagnosis::stop_reason)
      .def("__repr__", [](const Refine3DDiagnosis& d) { return "<Refine3DDiagnosis " + d.stop_reason + ">"; });
  using Result = Refine3DResult;
  py::class_<Result>(m, "Refine3DResult",
                     "What refine_gabriel returns (read-only; a new array on each access of an array attribute).")
      .def_property_readonly("points", [](const Result& r) { return from_points3(r.points); }, "(n, 3) float64")
      .def_property_readonly("tets", [](const Result& r) { return from_index_rows<4>(r.tets); }, "(t, 4) int64")
      .def_property_readonly("boundary_faces", [](const Result& r) { return from_index_rows<3>(r.boundary_faces); },
                             "(f, 3) int64")
      .def_property_readonly(
          "face_markers",
          [](const Result& r) { return from_vector(std::vector<std::int64_t>(r.face_markers.begin(), r.face_markers.end())); },
          "(f,) int64 input facet id of each boundary face")
      .def_property_readonly("segments", [](const Result& r) { return from_index_rows<2>(r.segments); }, "(k, 2) int64")
      .def_property_readonly("tet_regions", [](const Result& r) { return from_vector(r.tet_regions); }, "(t,) float64")
      .def_property_readonly("status", [](const Result& r) { return std::string(to_string(r.status)); },
                             "'converged', 'budget_exhausted', 'min_length_reached' or 'stalled'")
      .def_readonly("max_steiner", &Result::max_steiner, "the Steiner budget used (its default resolved)")
      .def_readonly("min_length", &Result::min_length, "the minimum length used (its default resolved)")
      .def_readonly("max_work", &Result::max_work, "the work budget of each strategy pass (its default resolved)")
      .def_readonly("work", &Result::work, "the work units spent by every attempt together")
      .def_readonly("steiner_on_segments", &Result::steiner_on_segments)
      .def_readonly("greedy_splits", &Result::greedy_splits)
      .def_readonly("strategy", &Result::strategy,
                    "'shells', 'greedy', 'midpoint', 'protected', 'mirrored', or '<rule>+protected' / '<rule>+mirrored' "
                    "after a fallback")
      .def_readonly("other_attempt", &Result::other_attempt, "status and stop reason of the attempts not returned")
      .def_readonly("protecting_balls", &Result::protecting_balls, "apex vertices protected")
      .def_readonly("steiner_on_facets", &Result::steiner_on_facets)
      .def_readonly("seconds", &Result::seconds)
      .def_readonly("smallest_subsegment", &Result::smallest_subsegment)
      .def_readonly("certificate", &Result::certificate, "check_gabriel of the mesh as returned")
      .def_readonly("volume_mesh", &Result::volume_mesh, "'built', or why tets is empty")
      .def_readonly("diagnosis", &Result::diagnosis)
      .def("__repr__", [](const Result& r) {
        return std::string("<Refine3DResult status=") + to_string(r.status) +
               " points=" + std::to_string(r.points.size()) + " tets=" + std::to_string(r.tets.size()) + ">";
      });
}

}  // namespace

void bind_gabriel3d(py::module_& m) {
  bind_result_classes(m);
  m.def(
      "check_gabriel",
      [](const DoubleArray& points, const IndexArray& faces, const IndexArray& segments) {
        auto pts = to_points3(points, "points");
        auto f = to_index_rows<3>(faces, pts.size(), "faces");
        auto s = to_index_rows<2>(segments, pts.size(), "segments");
        py::gil_scoped_release release;
        return check_gabriel(pts, f, s);
      },
      py::arg("points"), py::arg("faces"), py::arg("segments"),
      "Exact diametral-sphere test of every face (f,3) and segment (k,2) against all points (n,3).\n"
      "Returns a GabrielCertificate.");
  m.def(
      "refine_gabriel",
      [](const DoubleArray& points, const IndexArray& triangles, const IndexArray& facet_ids,
         const IndexArray& segments, const DoubleArray& holes, const DoubleArray& regions, long max_steiner,
         double min_length, long max_work, double time_limit, const std::string& split, bool protected_fallback,
         bool fallback_own_limits, long progress_every,
         const std::optional<std::function<void(long, long, long, double)>>& progress) {
        PLC3 plc = to_plc3(points, triangles, facet_ids, segments, holes, regions);
        const std::map<std::string, SplitRule> rules = {
            {"shells", SplitRule::Shells},
            {"midpoint", SplitRule::Midpoint},
            {"greedy", SplitRule::Greedy},
            {"protected", SplitRule::Protected},
            {"mirrored", SplitRule::Mirrored}};
        if (!rules.count(split))
          throw InvalidInput("split must be 'shells', 'midpoint', 'greedy', 'protected' or 'mirrored', not '" + split +
                             "'");
        Refine3DOptions o;
        o.max_steiner = max_steiner;
        o.min_length = min_length;
        o.max_work = max_work;
        o.time_limit = time_limit;
        o.split = rules.at(split);
        o.protected_fallback = protected_fallback;
        o.fallback_own_limits = fallback_own_limits;
        o.progress_every = progress_every;
        if (progress && *progress)
          o.progress = [f = *progress](const Refine3DProgress& p) {
            py::gil_scoped_acquire acquire;
            f(p.steiner_points, p.encroached_segments, p.encroached_facets, p.seconds);
          };
        py::gil_scoped_release release;
        return refine_gabriel(plc, o);
      },
      py::arg("points"), py::arg("triangles"), py::arg("facet_ids"), py::arg("segments"), py::arg("holes"),
      py::arg("regions"), py::arg("max_steiner"), py::arg("min_length"), py::arg("max_work"), py::arg("time_limit"), py::arg("split"),
      py::arg("protected_fallback"), py::arg("fallback_own_limits"), py::arg("progress_every"), py::arg("progress"),
      "Gabriel refinement of a PLC. max_steiner < 0, min_length < 0, max_work < 0: the defaults of Refine3DOptions (gabriel3d.h).\n"
      "progress: None or f(steiner, encroached_segments, encroached_facets, seconds).\n"
      "Returns a Refine3DResult.");
}

}  // namespace nonobtuse::bindings
