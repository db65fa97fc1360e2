// 2D domain validation: exact segment intersections and domain coverage (conversion only).
#include <pybind11/pybind11.h>

#include "bind_mesh2d.h"
#include "nonobtuse/validate2d.h"

namespace nonobtuse::bindings {

namespace {

py::array_t<std::int8_t> seed_places(const std::vector<SeedPlace>& places) {
  std::vector<std::int8_t> v(places.size());
  std::transform(places.begin(), places.end(), v.begin(), [](SeedPlace p) { return static_cast<std::int8_t>(p); });
  return from_vector(v);
}

}  // namespace

void bind_validate2d(py::module_& m) {
  m.def(
      "find_segment_intersections",
      [](const DoubleArray& points, const IndexArray& segments) {
        std::vector<Point2> pts = to_points2(points);
        std::vector<Segment> segs = to_index_rows<2>(segments, pts.size(), "segments");
        SegmentIntersections r;
        {
          py::gil_scoped_release release;
          r = find_segment_intersections(pts, segs);
        }
        py::dict d;
        d["crossings"] = from_index_rows<2>(r.crossings);
        d["points_on_segments"] = from_index_rows<2>(r.points_on_segments);
        d["overlaps"] = from_index_rows<2>(r.overlaps);
        return d;
      },
      py::arg("points"), py::arg("segments"),
      "Exact segment intersections. points (n,2) float64 finite and pairwise distinct; segments (m,2) int64 of\n"
      "distinct points. Returns a dict of sorted int64 (k,2) arrays: crossings (s,t) proper crossings,\n"
      "points_on_segments (p,s) point strictly inside segment, overlaps (s,t) collinear with a common piece.");
  m.def(
      "inspect_domain",
      [](const DoubleArray& points, const IndexArray& segments, const DoubleArray& holes,
         const DoubleArray& regions, bool convex_hull_boundary) {
        Domain2 dom = domain_from_arrays(points, segments, holes, regions, convex_hull_boundary);
        DomainCoverage c;
        {
          py::gil_scoped_release release;
          c = inspect_domain(dom);
        }
        py::dict d;
        d["encloses_area"] = c.encloses_area;
        d["domain_triangles"] = c.domain_triangles;
        d["segments_outside"] = from_vector(c.segments_outside);
        d["holes"] = seed_places(c.holes);
        d["regions"] = seed_places(c.regions);
        return d;
      },
      py::arg("points"), py::arg("segments"), py::arg("holes"), py::arg("regions"),
      py::arg("convex_hull_boundary"),
      "What the domain covers (its constrained Delaunay triangulation). Inputs as for triangulate, validated\n"
      "(no crossings, no points inside segments). Returns a dict: encloses_area (bool: some triangle enclosed by\n"
      "segments, holes ignored), domain_triangles (int), segments_outside (int32 array: segments with no domain\n"
      "triangle on either side), holes, regions (int8 arrays per seed: 0 inside, 1 outside, 2 on a point or segment).");
}

}  // namespace nonobtuse::bindings
