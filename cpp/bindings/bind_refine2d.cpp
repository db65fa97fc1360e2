// Boundary refinement: the result classes (Refine2DResult, its diagnosis), refine.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>

#include "bind_mesh2d.h"
#include "nonobtuse/refine2d.h"

namespace nonobtuse::bindings {
namespace {

RefineStrategy strategy_from(const std::string& name) {
  for (auto s : {RefineStrategy::Greedy, RefineStrategy::ProjectFlip, RefineStrategy::Projection})
    if (to_string(s) == name) return s;
  throw InvalidInput("unknown refinement strategy '" + name + "' (greedy, project-flip, projection)");
}

void bind_result_classes(py::module_& m) {
  py::class_<JunctionStats>(m, "Junction", "An input vertex where at least two input constraints meet.")
      .def_readonly("vertex", &JunctionStats::vertex, "input point index")
      .def_readonly("constraints", &JunctionStats::constraints, "input constraints meeting there")
      .def_readonly("min_angle_degrees", &JunctionStats::min_angle_degrees,
                    "smallest angle between two of them (float, for reporting only)")
      .def_readonly("steiner_points", &JunctionStats::steiner_points,
                    "Steiner points whose nearest end on their input edge is this vertex")
      .def("__repr__", [](const JunctionStats& j) {
        return "<Junction vertex=" + std::to_string(j.vertex) + " steiner_points=" + std::to_string(j.steiner_points) +
               ">";
      });
  py::class_<InputAngleStats>(m, "InputAngle2D",
                              "The angle at vertex between input constraints (vertex, a) and (vertex, b).")
      .def_readonly("vertex", &InputAngleStats::vertex)
      .def_readonly("a", &InputAngleStats::a)
      .def_readonly("b", &InputAngleStats::b, "the constraint closest in angle to (vertex, a)")
      .def_readonly("degrees", &InputAngleStats::degrees)
      .def_readonly("steiner_points", &InputAngleStats::steiner_points,
                    "Steiner points on (vertex, a) nearest to vertex")
      .def("__repr__", [](const InputAngleStats& a) {
        return "<InputAngle2D vertex=" + std::to_string(a.vertex) + " degrees=" + std::to_string(a.degrees) + ">";
      });
  py::class_<Refine2DDiagnosis>(m, "Refine2DDiagnosis", "Where the Steiner points of a 2D refinement went.")
      .def_readonly("junctions", &Refine2DDiagnosis::junctions, "at most 10, by decreasing Steiner count")
      .def_readonly("angles", &Refine2DDiagnosis::angles, "at most 10, likewise")
      .def_readonly("initial_violations", &Refine2DDiagnosis::initial_violations)
      .def_readonly("propagation_depth", &Refine2DDiagnosis::propagation_depth)
      .def_readonly("propagation_splits", &Refine2DDiagnosis::propagation_splits)
      .def_readonly("stop_reason", &Refine2DDiagnosis::stop_reason,
                    "why the refinement stopped, in refine_gabriel's words (a budget by its option's name)")
      .def("__repr__", [](const Refine2DDiagnosis& g) {
        return "<Refine2DDiagnosis initial_violations=" + std::to_string(g.initial_violations) +
               " propagation_depth=" + std::to_string(g.propagation_depth) + ">";
      });
  py::class_<Refine2DResult>(m, "Refine2DResult", "What refine returns (read-only; see nonobtuse.refine).")
      .def_readonly("mesh", &Refine2DResult::mesh, "the constrained Delaunay triangulation of the refined domain")
      .def_property_readonly("status", [](const Refine2DResult& r) { return to_string(r.status); },
                             "'converged', 'budget_exhausted' or 'stalled'")
      .def_readonly("steiner_points", &Refine2DResult::steiner_points)
      .def_readonly("max_steiner", &Refine2DResult::max_steiner, "the Steiner budget used (its default resolved)")
      .def_readonly("max_steiner_offset", &Refine2DResult::max_steiner_offset,
                    "largest distance of a Steiner point off its input segment over the segment's length")
      .def_readonly("lower_bound", &Refine2DResult::lower_bound)
      .def_property_readonly(
          "optimal",
          [](const Refine2DResult& r) { return r.optimal < 0 ? std::nullopt : std::optional<bool>(r.optimal == 1); },
          "True when certainly optimal, None when unknown")
      .def_readonly("obtuse_boundary_sides", &Refine2DResult::obtuse_boundary_sides,
                    "exact certificate of mesh: obtuse boundary sides (0 when converged)")
      .def_property_readonly(
          "edges",
          [](const Refine2DResult& r) {
            std::vector<std::array<int, 4>> rows;
            rows.reserve(r.edges.size());
            for (const auto& e : r.edges) rows.push_back({e.edge[0], e.edge[1], e.steiner_points, e.lower_bound});
            return from_index_rows<4>(rows);
          },
          "(k, 4) int64 rows a, b, steiner_points, lower_bound per input boundary edge (a new array on each access)")
      .def_readonly("diagnosis", &Refine2DResult::diagnosis)
      .def_readonly("quality", &Refine2DResult::quality, "the interior refinement (Quality2DStats)")
      .def_readonly("seconds", &Refine2DResult::seconds)
      .def("__repr__", [](const Refine2DResult& r) {
        return std::string("<Refine2DResult status=") + to_string(r.status) + " steiner_points=" + std::to_string(r.steiner_points) +
               " lower_bound=" + std::to_string(r.lower_bound) + ">";
      });
}

}  // namespace

void bind_refine2d(py::module_& m) {
  bind_result_classes(m);
  m.def(
      "refine",
      [](const DoubleArray& points, const IndexArray& segments, const DoubleArray& holes, const DoubleArray& regions,
         bool convex_hull_boundary, const std::string& strategy, long long max_steiner, int threads,
         const Quality2DOptions& quality, const std::optional<std::shared_ptr<Triangulation2>>& triangulation) {
        Domain2 d = domain_from_arrays(points, segments, holes, regions, convex_hull_boundary);
        Refine2DOptions options{strategy_from(strategy), max_steiner, threads};
        options.quality = quality;
        Triangulation2 taken =  // under the GIL: taken once
            triangulation && *triangulation ? (*triangulation)->take() : Triangulation2();
        py::gil_scoped_release release;
        return refine(d, options, &taken);
      },
      py::arg("points"), py::arg("segments"), py::arg("holes"), py::arg("regions"), py::arg("convex_hull_boundary"),
      py::arg("strategy") = "greedy", py::arg("max_steiner") = -1, py::arg("threads") = 2,
      py::arg_v("quality", Quality2DOptions{}, "Quality2DOptions()"), py::arg("triangulation") = py::none(),
      "Nonobtuse boundary refinement of a validated domain (see nonobtuse.refine). max_steiner < 0:\n"
      "default_steiner_budget(n); quality: interior refinement (off by default). triangulation: inspect_domain's\n"
      "(DomainCoverage.triangulation), taken over when it triangulates this domain, empty afterwards. Returns a\n"
      "Refine2DResult.");
  m.def(
      "conforming_gabriel_steiner_points",
      [](const DoubleArray& points, const IndexArray& segments, const DoubleArray& holes, const DoubleArray& regions,
         bool convex_hull_boundary) {
        Domain2 d = domain_from_arrays(points, segments, holes, regions, convex_hull_boundary);
        py::gil_scoped_release release;
        return conforming_gabriel_steiner_points(d);
      },
      py::arg("points"), py::arg("segments"), py::arg("holes"), py::arg("regions"), py::arg("convex_hull_boundary"),
      "Benchmark peer: Steiner points added by CGAL::make_conforming_Gabriel_2 to the domain's CDT.");
  m.def("default_steiner_budget", &default_steiner_budget, py::arg("n_points"),
        "The Steiner budget refine uses for n input points when max_steiner < 0 (refine2d.h).");
}

}  // namespace nonobtuse::bindings
