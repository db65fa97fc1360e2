// Boundary refinement: refine.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bind_mesh2d.h"
#include "nonobtuse/refine2d.h"

namespace nonobtuse::bindings {
namespace {

RefineStrategy strategy_from(const std::string& name) {
  for (auto s : {RefineStrategy::Greedy, RefineStrategy::ProjectFlip, RefineStrategy::Projection})
    if (to_string(s) == name) return s;
  throw InvalidInput("unknown refinement strategy '" + name + "' (greedy, project-flip, projection)");
}

py::dict diagnosis_to_dict(const Refine2DDiagnosis& g) {
  py::list junctions, angles;
  for (const auto& j : g.junctions)
    junctions.append(py::dict(py::arg("vertex") = j.vertex, py::arg("constraints") = j.constraints,
                              py::arg("min_angle_degrees") = j.min_angle_degrees,
                              py::arg("steiner_points") = j.steiner_points));
  for (const auto& a : g.angles)
    angles.append(py::dict(py::arg("vertex") = a.vertex, py::arg("edge") = py::make_tuple(a.vertex, a.a),
                           py::arg("neighbour") = py::make_tuple(a.vertex, a.b), py::arg("degrees") = a.degrees,
                           py::arg("steiner_points") = a.steiner_points));
  py::dict d;
  d["junctions"] = junctions;
  d["angles"] = angles;
  d["initial_violations"] = g.initial_violations;
  d["propagation_depth"] = g.propagation_depth;
  d["propagation_splits"] = g.propagation_splits;
  return d;
}

py::dict result_to_dict(const Refine2DResult& r) {
  py::dict d;
  d["mesh"] = mesh_to_dict(r.mesh);
  d["status"] = to_string(r.status);
  d["steiner_points"] = r.steiner_points;
  d["max_steiner"] = r.max_steiner;
  d["lower_bound"] = r.lower_bound;
  d["optimal"] = r.optimal < 0 ? py::object(py::none()) : py::object(py::bool_(r.optimal == 1));
  d["obtuse_boundary_sides"] = r.obtuse_boundary_sides;
  d["max_steiner_offset"] = r.max_steiner_offset;
  d["seconds"] = r.seconds;
  std::vector<std::array<int, 4>> rows;
  for (const auto& e : r.edges) rows.push_back({e.edge[0], e.edge[1], e.steiner_points, e.lower_bound});
  d["edges"] = from_index_rows<4>(rows);
  d["diagnosis"] = diagnosis_to_dict(r.diagnosis);
  return d;
}

}  // namespace

void bind_refine2d(py::module_& m) {
  m.def(
      "refine",
      [](const DoubleArray& points, const IndexArray& segments, const DoubleArray& holes, const DoubleArray& regions,
         bool convex_hull_boundary, const std::string& strategy, long long max_steiner, int threads) {
        Domain2 d = domain_from_arrays(points, segments, holes, regions, convex_hull_boundary);
        Refine2DOptions options;
        options.strategy = strategy_from(strategy);
        options.max_steiner = max_steiner;
        options.threads = threads;
        Refine2DResult r;
        {
          py::gil_scoped_release release;
          r = refine(d, options);
        }
        return result_to_dict(r);
      },
      py::arg("points"), py::arg("segments"), py::arg("holes"), py::arg("regions"), py::arg("convex_hull_boundary"),
      py::arg("strategy") = "greedy", py::arg("max_steiner") = -1, py::arg("threads") = 2,
      "Nonobtuse boundary refinement of a validated domain (see nonobtuse.refine). max_steiner < 0:\n"
      "default_steiner_budget(n). Returns a dict: mesh (as triangulate), status ('converged' |\n"
      "'budget_exhausted' | 'stalled'), steiner_points, max_steiner (the budget used), lower_bound, optimal\n"
      "(True | None), obtuse_boundary_sides (exact certificate), max_steiner_offset (float), edges (k, 4) int64\n"
      "rows a, b, steiner_points, lower_bound per input boundary edge, seconds, diagnosis.");
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
