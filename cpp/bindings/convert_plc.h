// Conversion of a PLC (numpy arrays) to the core's PLC3, shared by the PLC and Gabriel bindings.
#pragma once
#include "convert.h"
#include "nonobtuse/gabriel3d.h"

namespace nonobtuse::bindings {

// points (n, 3) float64, triangles (m, 3) and facet_ids (m,) int64, segments (k, 2) int64, holes (h, 3) and
// regions (r, 4) float64.
inline PLC3 to_plc3(const DoubleArray& points, const IndexArray& triangles, const IndexArray& facet_ids,
                    const IndexArray& segments, const DoubleArray& holes, const DoubleArray& regions) {
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
  return plc;
}

}  // namespace nonobtuse::bindings
