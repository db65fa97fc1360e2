// One Gabriel pass: refine, restrict the Delaunay tetrahedralization, check it exactly, repair, until clean or a stop.
#include <algorithm>

#include "gabriel3d_refiner.h"

namespace nonobtuse::gabriel3d {

// From this many points (the state's, at the start of a round) a second thread inserts them into the Delaunay
// tetrahedralization as the refiner makes them (DelaunayRounds::insert_while); below, a pass takes milliseconds.
constexpr std::size_t kOverlapFrom = 1024;

Refine3DResult refine_once(const PLC3& plc, const Refine3DOptions& options, bool ignore_frame_artifacts,
                          bool protect, bool mirror, bool stations, const CascadeFloor& cascade_floor) {
  PlcState s = build_plc_state(plc);
  Refine3DResult out;
  out.diagnosis.smallest_angles = smallest_input_angles(s);
  std::optional<Stations> groups;
  if (stations) groups.emplace(s);
  if (groups && groups->empty()) groups.reset();
  std::optional<Protection> protection;
  if (protect) {
    std::vector<ProtectingBall> balls = protecting_balls(s, plc);
    if (groups)  // the stations take over at the ends of grouped segments (a ball's sphere points there cannot be
                 // matched in doubles: experiments/README.md, step.off)
      balls.erase(std::remove_if(balls.begin(), balls.end(),
                                 [&](const ProtectingBall& b) { return groups->at_end(b.apex); }),
                  balls.end());
    protection.emplace(s, std::move(balls));
  }
  // With groups, the mirrored facet meshes too (along the small dihedral edges elsewhere; Refiner leaves the grouped
  // segments to the stations).
  Refiner refiner(s, options, ignore_frame_artifacts, protection ? &*protection : nullptr, mirror || groups,
                  groups ? &*groups : nullptr, cascade_floor);
  // Refine the subfacets, restrict the Delaunay tetrahedralization, check it exactly; where its boundary faces
  // differ from the subfacets (cospherical points) and are encroached, split those too and start over. After a
  // stop, the mesh is rebuilt once more so that it shows every point inserted (repair() may stop half-way).
  std::optional<Stop> stop;
  if (protection) {
    out.protecting_balls = static_cast<long>(protection->balls().size());
    stop = refiner.place_protecting_points();
  }
  if (groups) stop = refiner.place_apex_stations();
  Restricted mesh;
  std::vector<Key> segments;
  bool clean = false;
  CheckMemo check_memo;  // what the exact checks of the rounds found clean
  DelaunayRounds delaunay;  // each round inserts the new points only
  refiner.feed(&delaunay);
  for (;;) {
    if (!stop) delaunay.insert_while(s.points.size() >= kOverlapFrom, [&] { stop = refiner.run(); });
    mesh = delaunay.restrict(s, plc);
    refiner.add_work(s.points.size());
    out.points.clear();
    for (const auto& p : s.points) out.points.push_back(from_cgal(p));
    segments.clear();
    out.segments.clear();
    for (const auto& [sub, parent] : s.subsegments) {
      segments.push_back(sub);
      out.segments.push_back({sub.first, sub.second});
    }
    if (stop) {
      // A stop can leave encroached subfacets that are no Delaunay faces: the flood fill of restrict_delaunay
      // then leaks through them and leaves facets without faces (often no tets at all). Return the subfacets.
      std::vector<bool> has_face(s.facets.size(), false);
      for (int f : mesh.face_facets) has_face[f] = true;
      long bare = std::count(has_face.begin(), has_face.end(), false);
      if (bare > 0) {
        long collinear = 0;
        mesh = subfacet_boundary(s, &collinear);
        out.volume_mesh = "not built: the Delaunay tetrahedralization does not conform to " + std::to_string(bare) +
                          " of " + std::to_string(s.facets.size()) + " facets; boundary_faces are the subfacets";
        if (collinear > 0)
          out.volume_mesh += " (" + std::to_string(collinear) + " collinear after rounding left out)";
      }
    }
    // The check stops at time_limit too: a certificate with unchecked rows is never clean.
    out.certificate = check_gabriel_until(s.points, mesh.boundary_faces, out.segments,
                                          [&] { return refiner.out_of_time(); }, &check_memo);
    refiner.add_work(mesh.boundary_faces.size() + out.segments.size());
    if (options.progress)  // each round rebuilds the Delaunay mesh and checks it: seconds on big inputs
      options.progress({refiner.steiner_on_segments + refiner.steiner_on_facets,
                        static_cast<long>(out.certificate.segments.size()),
                        static_cast<long>(out.certificate.faces.size()), refiner.seconds()});
    bool complete = out.certificate.unchecked_faces == 0 && out.certificate.unchecked_segments == 0;
    clean = complete && out.certificate.faces.empty() && out.certificate.segments.empty();
    if (!complete && !stop)
      stop = Stop{RefineStatus::BudgetExhausted, "time_limit (" + std::to_string(options.time_limit) +
                                                      " s) reached during the exact check of the result"};
    if (clean && !stop) {
      // Points on a subsegment's diametral sphere and none inside pass the check, but the tetrahedralization of
      // cospherical points is CGAL's symbolic perturbation's choice, which can cross the subsegment: on
      // window_box_fin.poly's boundary split by the quality pass (start="boundary"), the edge between the top
      // facet and its coplanar window had one point of each facet on its sphere, the Delaunay edge between those
      // two crossed it, the flood fill leaked through, and the mesh came out with no tets, its (empty) boundary
      // certified. Such subsegments are split; the rounds go on.
      if (const std::vector<Key> missing = delaunay.missing_edges(segments); !missing.empty()) {
        bool progress = false;
        stop = refiner.split_missing(missing, &progress);
        if (!stop && !progress)
          stop = Stop{RefineStatus::Stalled, "subsegments the Delaunay tetrahedralization lacks could not be split"};
        continue;
      }
    }
    if (stop || clean) break;
    bool progress = false;
    stop = refiner.repair(mesh, segments, out.certificate, &progress);
    if (!stop && !progress)
      stop = Stop{RefineStatus::Stalled, "encroached faces of the Delaunay mesh remain but none could be split"};
  }
  out.tets = std::move(mesh.tets);
  out.boundary_faces = std::move(mesh.boundary_faces);
  out.face_markers = std::move(mesh.face_markers);
  out.tet_regions = std::move(mesh.tet_regions);
  out.steiner_on_segments = refiner.steiner_on_segments;
  out.greedy_splits = refiner.greedy_splits;
  out.steiner_on_facets = refiner.steiner_on_facets;
  out.smallest_subsegment = smallest_subsegment(s);
  count_steiner(s, out.certificate, out.diagnosis);
  if (clean) {
    out.status = RefineStatus::Converged;
    out.diagnosis.stop_reason = "every boundary face and subsegment has an empty diametral sphere";
  } else {
    out.status = stop->status;
    out.diagnosis.stop_reason = stop->reason;
  }
  out.seconds = refiner.seconds();
  out.work = refiner.work();
  return out;
}

}  // namespace nonobtuse::gabriel3d
