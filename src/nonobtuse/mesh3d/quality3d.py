"""Interior quality and size for 3D meshes with a Gabriel boundary: TetGen's ``-q`` (radius-edge ratio) and
``-a`` (maximum volume), the boundary certificate kept.

:func:`refine_quality3d` repairs the input boundary (:func:`refine_gabriel`: every subfacet and subsegment
gets an empty diametral sphere; or, with start="tetgen", TetGen's facet splits for the bounds, then takes
TetGen's interior points on it, ``-Y``, but those in a closed diametral sphere), then inserts circumcenters
of the tets over a bound into one Delaunay tetrahedralization kept between insertions (strictly outside every
closed diametral sphere, exact); a circumcenter in a closed diametral sphere splits that subfacet or
subsegment instead, in the same tetrahedralization (Ruppert's and Shewchuk's rule), until the boundary is
Gabriel again; where that tetrahedralization cannot hold the split boundary, the boundary repair takes over
for a round. The returned mesh is a Delaunay tetrahedralization with the repaired boundary, certified by the
exact check.
"""

from __future__ import annotations

import math
import sys
import time
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from typing import Any, Callable, Literal, cast

import numpy as np

from nonobtuse.errors import InvalidInputError
from nonobtuse.mesh3d.gabriel import GabrielReport, check_gabriel, negative_couplings
from nonobtuse.mesh3d.plc import PLC, TetMesh
from nonobtuse.mesh3d.quality3d_rounds import InteriorRefiner, tet_quality

# The Steiner budget of the repair of TetGen's surface, per point of that surface (plus 1,000): the repairs
# that converge on the bench corpus add at most 2.3 per point (fandisk.off 2.26, gc_spot.ply 2.29,
# icosphere_jitter.off 2.3; anchor.off 0.51); wedge-1.smesh's had added 7.5 (88,000 on 11,675 points, 59 s
# CPU) and was still growing, towards the default 10 per point and then the protected rerun's as many: no
# result in 200 s. Deterministic, unlike the time share it replaces. The interior passes' boundary splits are
# bounded by it too (they add at most 1.1 per surface point on the converging inputs: anchor.off).
SURFACE_STEINER_PER_POINT = 3

QualityStatus = Literal["converged", "quality_blocked", "budget_exhausted", "min_length_reached", "stalled"]
Start = Literal["tetgen", "boundary"]


@dataclass
class Quality3DResult:
    """The outcome of refine_quality3d.

    mesh:   the TetMesh: PLC points first in input order, then the boundary Steiner points, then the interior
            points; tets of the Delaunay tetrahedralization of all of them in the PLC's regions (exact, CGAL);
            boundary_faces (subfacets) with face_facets and face_markers of their input facets; segments the
            subsegments.
    status: "converged" (the exact Gabriel check of mesh passes and every tet meets the bounds, floating
            point, but those left alone near small input angles), "quality_blocked" (certificate passes; a
            round could add nothing: the centers left lie on diametral spheres), "budget_exhausted"
            (max_points or time_limit), or the boundary repair's status when one did not converge
            ("budget_exhausted", "min_length_reached", "stalled"; "stalled" too where a pass's split
            boundary has a triangle its rounded points make degenerate, which the repair refuses): mesh is
            then the last interior pass's on the last converged repair's boundary (certified) when there was
            one; stats["last_repair"] says how the last repair ended.
    stats:  boundary_points, interior_points, steiner_points (all points not in the input), tets,
            worst_radius_edge, max_volume, min_volume, radius_edge_over_2 (see :func:`tet_quality`), and the
            same with the suffix _outside_small_angles (over the tets not left alone), bad_tets (tets over a
            bound at the end), small_angle_tets (those of them the small-angle rule left alone: a tet whose
            circumcenter lies in the closed diametral sphere of a subsegment or subfacet whose split would lie
            at a sharp feature, a segment where facets meet below 85 degrees or an apex below 60 (both below
            59.99 for a tet over the volume bound: its split is bounded below by the bound), and in its
            protecting region, or, over the radius-edge bound alone, be shorter than the tet's shortest edge;
            ``cpp/src/quality3d_boundary.h``, ``cpp/src/quality3d_small_angle.h``; a tet whose circumcenter
            lies in the closed diametral sphere of a subfacet or subsegment whose split cascaded, see
            cascades_left_alone below; and a tet with its four corners on one facet, flat but for rounding),
            bad_tets_outside_small_angles, blocked_centers (tets over a bound the last interior pass left:
            centers that no split frees), inserted_by_passes (circumcenters the interior passes inserted),
            boundary_points_by_passes / boundary_rounds / refused_splits (the passes' own boundary splits,
            their steps, and the splits refused at min_length or the budget), cascade_retries /
            cascades_left_alone (passes run again after a step's cascade, and the subfacets and subsegments
            left alone for it; see Each round below), rounds,
            surface (how the facets were split first), tetgen / tetgen_points / tetgen_points_dropped
            (TetGen's interior points, and those dropped for lying in a closed diametral sphere),
            encroached_facets / encroached_segments (the exact certificate), volume_mesh, negative_couplings,
            boundary_repair (the first refine_gabriel's stats), radius_edge / max_volume_bound (the bounds
            asked), start, warnings, seconds.
    report: the GabrielReport of mesh (exact).
    small_angle_rows: the rows of mesh.tets over a bound left alone by the small-angle rule (int64, sorted).
    """

    mesh: TetMesh
    status: QualityStatus
    stats: dict[str, Any] = field(default_factory=dict)
    report: GabrielReport | None = None
    small_angle_rows: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))


def _print_progress(round_: int, interior: int, bad: int, blocked: int, seconds: float) -> None:
    print(f"refine_quality3d: round {round_}, {interior} interior points, {bad} tets over a bound "
          f"({blocked} blocked by a boundary sphere), {seconds:.1f} s", file=sys.stderr)


def refine_quality3d(
    plc: PLC,
    max_volume: float | Mapping[float, float] | None = None,
    radius_edge: float | None = None,
    max_points: int | None = None,
    time_limit: float | None = None,
    start: Start = "boundary",
    region_volumes: bool = False,
    progress: Callable[[int, int, int, int, float], None] | bool | None = None,
    started: float | None = None,
    **gabriel_options: Any,
) -> Quality3DResult:
    """Repair the boundary of `plc` to Gabriel (refine_gabriel with ``gabriel_options``: max_steiner,
    min_length, split, protected_fallback; fallback_own_limits: True unless given for the one repair of the
    input's own boundary, False for the others) and add interior points
    until every tet has radius-edge ratio <= radius_edge and volume <= max_volume; no interior point is kept
    inside a subfacet's or subsegment's closed
    diametral sphere.

    plc: as for refine_gabriel. max_volume: a volume bound for every tet, or a mapping {region attribute:
    bound} (regions not listed are free; the attributes are those of plc.regions, or 1, 2, ... without seeds),
    or None. region_volumes: True makes the volume constraints of plc's region list hold as well (the fifth
    number of a TetGen .poly region line, :attr:`PLC.region_volumes`; TetGen's -a without a number), in the
    regions of their attributes: a tet's bound is then the smallest that applies. radius_edge: a bound > 1 on
    circumradius / shortest edge (TetGen's -q; 2 is its default), or None. max_points: interior point budget
    (None: 10^6). time_limit: seconds for everything, checked between rounds and passed on to each boundary
    repair; None (the default): no wall-clock limit, so the outcome does not depend on the machine (the
    repairs stop at their deterministic work budget, max_work, and the passes at max_points and the
    repair's max_steiner). start: "boundary" (the default) starts from the input boundary and its repair
    alone; "tetgen" lets TetGen (-pq R -a V, the 3d extra) split the facets for the bounds before the Gabriel
    repair and takes its -Y interior points on the repaired boundary as the first interior points (it falls
    back to "boundary" when TetGen is missing or fails, or when the repair of TetGen's surface does not
    converge within SURFACE_STEINER_PER_POINT Steiner points per surface point + 1,000, or half the time with
    a time_limit: :func:`_repair_tetgen_surface`). On the 3D corpus the boundary start adds about a third
    fewer points in less than half the time (experiments/README.md).
    progress: True prints a line per round to stderr; a callable gets (round, interior_points, bad_tets,
    blocked_tets, seconds). started: time.perf_counter() at which the caller's work began (time_limit counts
    from it).
    Each round: an interior pass (``_core.refine_interior``: one Delaunay tetrahedralization kept while the
    circumcenters of the tets over a bound are inserted one by one, worst radius-edge ratio first, each
    strictly outside every closed diametral sphere of a subfacet and subsegment and inside the domain, both
    exact; a circumcenter in a closed diametral sphere splits that subsegment at its midpoint or that subfacet
    at its circumcenter, or the subsegments that circumcenter encroaches, then every encroached subsegment and
    subfacet is split until the boundary is Gabriel again, and the centers are tried again, until none is left
    or no split frees one). The termination arguments are at the split rules in
    ``cpp/src/quality3d_interior.cpp`` (insertion radii, radius_edge >= 2 as Shewchuk's; boundary splits
    bounded by the repair's min_length and max_steiner, and per pass by 8 times the boundary's points plus
    2,000, which cuts the cascades down small angles short: ``InteriorRefiner.interior_pass``). Tets near
    small input angles whose centers stay in diametral spheres are left (stats["blocked_centers"], as TetGen
    counts the tets it skips). Where a pass's boundary step cascades to a refused split and the repair taking
    over stops too, the pass runs again from its last certified mesh with steps that split for half as many
    centers, down to one; when a step that splits one subfacet or subsegment fails, the tets whose centers lie
    in its closed diametral sphere are left alone too (stats["cascades_left_alone"] counts those subfacets and
    subsegments, stats["cascade_retries"] the passes run again: at most 32, and only where the first failed
    step split for at most 512 centers). A round ends with a boundary repair (refine_gabriel of the split
    boundary with the interior points) only when the pass's tetrahedralization cannot hold its split boundary
    (cospherical points, or a split refused at min_length: stats "boundary_rounds" counts the pass's own
    boundary steps); when the repaired surface is not Delaunay to begin with (e.g. a cube's squares), the
    circumcenters of an independent set of bad tets (no center in another's circumsphere) go through the
    repair (points strictly inside their tets for those in a closed sphere). The loop is bounded by
    max_points, time_limit and the boundary repair's budget, and a round that adds nothing ends it
    ("quality_blocked").
    Guarantee: report is the exact check_gabriel of the returned mesh; status "converged" needs it to pass and
    every tet within the bounds (measured in floating point). Deterministic.
    Cost: the interior pass, O(k log n) expected for k insertions, plus per boundary step O(f log n) exact
    encroachment queries per scan for f subfacets and a pass over the tetrahedralization; a boundary repair
    (refine_gabriel without its control-volume summary) only where the pass hands over; the summary once at
    the end.
    Raises InvalidInputError for a malformed PLC or bounds (radius_edge <= 1, max_volume <= 0, not finite), or
    region_volumes without a volume constraint in plc's region list.
    """
    started = time.perf_counter() if started is None else started
    callback = _print_progress if progress is True else (progress or None)
    _check_bounds(max_volume, radius_edge, max_points)
    if region_volumes:
        if not region_volume_bounds(plc):
            raise InvalidInputError(f"{plc.source}: region_volumes asked, but its region list has no volume "
                                    f"constraint > 0 (the fifth number of a .poly region line)")
        max_volume = _with_region_volumes(max_volume, region_volume_bounds(plc))
    switches = _tetgen_switches(max_volume, radius_edge)
    surface, surface_note = _tetgen_surface(plc, switches + "AQ") if start == "tetgen" else (plc, "input")
    refiner = InteriorRefiner(plc, max_volume, radius_edge, time_limit, started, gabriel_options)
    # TetGen's facet splits can start a cascade that the input's own boundary does not have (points near small
    # input angles): when that repair does not converge within its budget, the input's boundary is repaired
    tetgen_surface = surface is not plc
    # The repair of the input's own boundary, run once, takes the protected rerun's wider limits unless
    # fallback_own_limits is given (u.off converges only so); the repairs of the rounds do not
    own_limits = {"fallback_own_limits": gabriel_options.get("fallback_own_limits", True)}
    if tetgen_surface:
        g = _repair_tetgen_surface(refiner, surface)
        if g.status != "converged":
            surface_note = f"input (the repair of TetGen's surface ended {g.status})"
            surface, start = plc, "boundary"
    if surface is plc:
        g = refiner.repair(plc, np.zeros((0, 3)), **own_limits)
    stats: dict[str, Any] = {"radius_edge": radius_edge, "max_volume_bound": _jsonable_bound(max_volume),
                             "start": start, "rounds": 0, "surface": surface_note,
                             "boundary_repair": dict(g.stats)}
    tetgen_points = np.zeros((0, 3))  # placed by the first interior pass, in no closed diametral sphere
    if g.status == "converged" and start == "tetgen":
        tetgen_points = refiner.tetgen_points(refiner.split_mesh(g.mesh)[0], switches + "YAQ", stats)
    mesh, status = g.mesh, g.status
    stop = g.stats["diagnosis"]["stop_reason"]
    budget = 10**6 if max_points is None else int(max_points)
    limits, blocked = dict(g.stats), 0
    while status == "converged":
        surface, interior = refiner.split_mesh(mesh)
        grown, passed, blocked, split = refiner.interior_pass(mesh, budget - len(interior), tetgen_points,
                                                              limits)
        placed, tetgen_points = tetgen_points, tetgen_points[:0]  # placed by this pass, else by the repair
        stats["rounds"] += 1
        seconds = time.perf_counter() - started
        if callback:
            callback(stats["rounds"], len(refiner.split_mesh(grown)[1]), blocked, blocked, seconds)
        if passed in ("converged", "blocked", "budget_exhausted"):
            mesh, status = grown, {"blocked": "quality_blocked"}.get(passed, passed)
            break
        if seconds > refiner.time_limit:
            status = "budget_exhausted"
            break
        if passed == "boundary_stopped" and refiner.step_centers and refiner.retry_cascade(grown):
            mesh = grown  # bounded steps already: again with a smaller one, the repair would cascade too
            continue
        # a split boundary the pass cannot tetrahedralize by itself (cospherical points, or a split it
        # refused): the boundary repair splits what is left and tetrahedralizes the interior points with it
        surface, interior = refiner.split_mesh(grown if split is None else split)
        if grown is mesh:  # not Delaunay to begin with: bad tets' centers (or stand-ins) through the repair
            added = np.concatenate([placed, refiner.centers_for_repair(mesh, surface)])
            if not len(added):
                status = "quality_blocked"
                break
            interior = np.concatenate([interior, added])
        try:
            repaired = refiner.repair(surface, interior)
        except InvalidInputError as e:  # the pass's split boundary, not the input: a split rounded degenerate
            status, stop, mesh = "stalled", f"the split boundary cannot be repaired: {e}", grown
            break
        if grown is mesh and len(repaired.mesh.points) == len(surface.points) + len(interior):
            status = "quality_blocked"  # nothing added: the centers left lie on spheres, which split nothing
            break
        status, stop = repaired.status, repaired.stats["diagnosis"]["stop_reason"]
        if status != "converged" and passed == "boundary_stopped" and refiner.retry_cascade(grown):
            # the pass again from its last certified mesh, its steps smaller
            mesh, status = grown, "converged"
            stop = f"a boundary step cascaded and its repair stopped too ({stop}): passes ran again, smaller"
            continue
        # else the last certified mesh: the pass's before the boundary step it could not finish
        g, mesh = (repaired, repaired.mesh) if status == "converged" else (g, grown)
    bad = refiner.bad_tets(mesh)[0]
    small_angle = refiner.small_angle_rows(mesh)
    outside = np.setdiff1d(bad, small_angle)
    if status == "converged" and len(outside):  # the pass's measure and numpy's differ in the last ulp
        status = "quality_blocked"
    # mesh is the last interior pass's, on the last converged repair's boundary, when a later repair stopped
    # (its status is returned with that mesh)
    report = check_gabriel(mesh)
    if status == "converged" and not report.ok:  # the repair converged, so this cannot happen; checked anyway
        status = "stalled"
    interior_points = len(mesh.points) - len(refiner.split_mesh(mesh)[0].points)
    stats = {"status": status, "steiner_points": len(mesh.points) - len(plc.points),
             "boundary_points": len(mesh.points) - interior_points, "interior_points": interior_points,
             **tet_quality(mesh), **tet_quality(mesh, small_angle, "_outside_small_angles"),
             "bad_tets": int(bad.size), "small_angle_tets": int(small_angle.size),
             "bad_tets_outside_small_angles": int(outside.size), "blocked_centers": blocked,
             "inserted_by_passes": refiner.inserted, "boundary_points_by_passes": refiner.boundary_points,
             "boundary_rounds": refiner.boundary_rounds, "refused_splits": refiner.refused_splits,
             "cascade_retries": refiner.retries, "cascades_left_alone": len(refiner.cascades),
             "encroached_facets": len(report.faces), "encroached_segments": len(report.segments),
             "volume_mesh": g.stats.get("volume_mesh"), "last_repair": stop,
             "negative_couplings": negative_couplings(mesh), **stats,
             "warnings": list(plc.warnings), "seconds": time.perf_counter() - started}
    mesh.stats = stats
    return Quality3DResult(mesh, cast(QualityStatus, status), stats, report, small_angle)


def _repair_tetgen_surface(refiner: InteriorRefiner, surface: PLC) -> Any:
    """refine_gabriel of TetGen's `surface` within SURFACE_STEINER_PER_POINT Steiner points per surface point
    (+ 1,000) and half the time left (with a time_limit): the first strategy pass alone, then, unless that
    pass converged or ran out of its budget, the protected strategy on the surface with the same limits, as
    refine_gabriel's own fallback runs it (mc_gyroid.off converges so). A pass that used up its Steiner budget
    is a cascade the protected rerun does not stop either (wedge-1.smesh: 47,700 points each, 26 s CPU each);
    the caller then repairs the input's own boundary."""
    cap = SURFACE_STEINER_PER_POINT * len(surface.points) + 1000
    options = refiner.gabriel_options
    first = refiner.repair(surface, np.zeros((0, 3)), share=0.5, max_steiner=cap, protected_fallback=False)
    protect = options.get("protected_fallback", True) and options.get("split") not in ("protected",
                                                                                        "mirrored")
    if first.status in ("converged", "budget_exhausted") or not protect:
        return first
    return refiner.repair(surface, np.zeros((0, 3)), share=0.5, max_steiner=cap, split="protected")


def _tetgen_switches(max_volume: Any, radius_edge: float | None) -> str:
    """TetGen's -p -q [-a] switches for the bounds (the bounds of regions are left to the rounds)."""
    switches = "pq" + (repr(float(radius_edge)) if radius_edge else "")
    everywhere = max_volume.get(None) if isinstance(max_volume, Mapping) else max_volume
    return switches + (f"a{float(everywhere)!r}" if everywhere is not None else "")


def _tetgen_surface(plc: PLC, switches: str) -> tuple[PLC, str]:
    """The PLC whose facets are TetGen's boundary triangles of `plc` (``switches``: TetGen splits the facets
    for the bounds): the input points first, then TetGen's boundary Steiner points; facet ids and markers
    those of `plc`; segments the facets' boundary edges. `plc` itself, and why, when TetGen is missing or
    fails."""
    from nonobtuse.mesh3d.load import facet_boundary_segments
    from nonobtuse.mesh3d.tetrahedralize import tetrahedralize

    try:
        tm = tetrahedralize(plc, "tetgen", switches=switches)
    except (ModuleNotFoundError, InvalidInputError) as e:
        return plc, f"input (TetGen not used: {e})"
    keep = np.union1d(np.arange(len(plc.points)), np.asarray(tm.boundary_faces).ravel())
    renumber = np.full(len(tm.points), -1, dtype=np.int64)
    renumber[keep] = np.arange(len(keep))
    faces = renumber[tm.boundary_faces]
    facets = np.asarray(tm.face_facets, dtype=np.int64)
    surface = replace(plc, points=tm.points[keep], triangles=faces, facet_ids=facets,
                      segments=facet_boundary_segments(faces, facets))
    return surface, f"TetGen -{switches}: {len(keep) - len(plc.points)} boundary Steiner points"


def region_volume_bounds(plc: PLC) -> dict[float, float]:
    """{region attribute: volume constraint} from plc's region list (:attr:`PLC.region_volumes`): the rows
    with a constraint > 0 (TetGen ignores the others), the smallest when seeds with one attribute differ."""
    bounds: dict[float, float] = {}
    volumes = np.asarray(plc.region_volumes, dtype=np.float64)
    for row, volume in zip(np.asarray(plc.regions).reshape(-1, 4)[: len(volumes)], volumes.tolist()):
        if volume > 0:
            attr = float(row[3])
            bounds[attr] = min(volume, bounds.get(attr, math.inf))
    return bounds


def _with_region_volumes(max_volume: Any, regions: dict[float, float]) -> Any:
    """One mapping {region attribute or None: bound} for ``max_volume`` (None, a number or a mapping) and the
    region list's bounds: the smaller bound where both give one; a number becomes the key None (every tet)."""
    merged: dict[float | None, float] = {} if max_volume is None else (
        dict(max_volume) if isinstance(max_volume, Mapping) else {None: float(max_volume)})
    for attr, volume in regions.items():
        merged[attr] = min(volume, merged.get(attr, math.inf))
    return merged


def _jsonable_bound(max_volume: Any) -> Any:
    if isinstance(max_volume, Mapping):
        return {("every tet" if k is None else str(k)): float(v) for k, v in max_volume.items()}
    return max_volume


def _check_bounds(max_volume: Any, radius_edge: Any, max_points: Any) -> None:
    """InvalidInputError unless radius_edge is None or finite > 1, max_volume None, finite > 0 or a mapping to
    such values, and max_points None or an integer >= 0."""
    def positive(x: Any) -> bool:
        number = not isinstance(x, bool) and isinstance(x, (int, float, np.number))
        return number and math.isfinite(x) and x > 0

    if radius_edge is not None and not (positive(radius_edge) and radius_edge > 1):
        raise InvalidInputError(f"radius_edge must be a finite number > 1 (TetGen's -q; 2 is usual), got "
                                f"{radius_edge!r}")
    volumes = max_volume.values() if isinstance(max_volume, Mapping) else [max_volume]
    if max_volume is not None and not all(positive(v) for v in volumes):
        raise InvalidInputError(f"max_volume must be a finite number > 0 or a mapping region -> such a "
                                f"number, got {max_volume!r}")
    integer = not isinstance(max_points, bool) and isinstance(max_points, (int, np.integer))
    if max_points is not None and not (integer and max_points >= 0):
        raise InvalidInputError(f"max_points must be an integer >= 0, got {max_points!r}")
