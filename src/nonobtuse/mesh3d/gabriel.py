"""Gabriel boundaries in 3D: the exact certificate (check_gabriel) and the repair (refine_gabriel).

A boundary face (triangle) or segment is Gabriel when no mesh vertex lies strictly inside its diametral sphere
(for a face: the smallest sphere through its corners; for a segment: the sphere having it as a diameter). When
every subfacet and subsegment of a PLC is Gabriel, the Delaunay tetrahedralization of the vertices conforms to
the PLC and its control volumes see nonnegative boundary coefficients.
"""

from __future__ import annotations

import math
import sys
import time
from dataclasses import dataclass, field, replace
from typing import Any, Callable, Literal, cast

import numpy as np

from nonobtuse import _core
from nonobtuse.errors import InvalidInputError
from nonobtuse.mesh3d.control_volumes3d import control_volumes3d
from nonobtuse.mesh3d.plc import PLC, TetMesh, region_attributes

Status = Literal["converged", "budget_exhausted", "min_length_reached", "stalled"]


@dataclass(frozen=True)
class GabrielReport:
    """Which boundary faces and segments of a tetrahedral mesh have a vertex strictly inside their diametral
    sphere.

    faces:            (a,) int64 rows of mesh.boundary_faces that are encroached, ascending.
    face_vertices:    (a,) int64 the deepest encroaching vertex of each.
    face_depths:      (a,) float64 1 - |vertex - center| / radius in (0, 1]; floating point, for display.
    segments, segment_vertices, segment_depths: the same for rows of mesh.segments.
    n_faces, n_segments: how many were checked.
    Every decision is exact (CGAL side_of_bounded_sphere on the stored coordinates); points on a sphere do not
    count.
    """

    faces: np.ndarray
    face_vertices: np.ndarray
    face_depths: np.ndarray
    segments: np.ndarray
    segment_vertices: np.ndarray
    segment_depths: np.ndarray
    n_faces: int
    n_segments: int

    @property
    def ok(self) -> bool:
        """True iff every checked face and segment is Gabriel."""
        return len(self.faces) == 0 and len(self.segments) == 0

    def to_dict(self, worst: int = 10) -> dict[str, Any]:
        """JSON-ready summary: counts, and the `worst` deepest encroachments of each kind."""

        def deepest(index: np.ndarray, vertex: np.ndarray, depth: np.ndarray) -> list[dict[str, Any]]:
            order = np.argsort(-depth, kind="stable")[:worst]
            return [
                {"index": int(index[i]), "vertex": int(vertex[i]), "depth": float(depth[i])} for i in order
            ]

        return {
            "ok": self.ok,
            "checked_faces": self.n_faces,
            "checked_segments": self.n_segments,
            "encroached_faces": len(self.faces),
            "encroached_segments": len(self.segments),
            "deepest_faces": deepest(self.faces, self.face_vertices, self.face_depths),
            "deepest_segments": deepest(self.segments, self.segment_vertices, self.segment_depths),
        }

    @classmethod
    def _from_core(cls, c: _core.GabrielCertificate, n_faces: int, n_segments: int) -> GabrielReport:
        return cls(
            faces=c.faces,
            face_vertices=c.face_vertices,
            face_depths=c.face_depths,
            segments=c.segments,
            segment_vertices=c.segment_vertices,
            segment_depths=c.segment_depths,
            n_faces=n_faces,
            n_segments=n_segments,
        )


@dataclass
class Gabriel3DResult:
    """The outcome of refine_gabriel.

    mesh:   the TetMesh (PLC points first in input order, then Steiner points; tets of the Delaunay
            tetrahedralization inside the PLC; boundary_faces (subfacets) with face_facets = their input
            facet ids and face_markers = those facets' markers; tet_regions = the region attribute of every
            tet when the PLC has regions; segments = the subsegments of the PLC segments and of the facets'
            boundary edges).
    status: "converged" (the exact check of mesh passes), "budget_exhausted" (max_steiner, max_work or
            time_limit),
            "min_length_reached" or "stalled" (no split could make progress).
    stats:  steiner_points, steiner_on_segments, steiner_on_facets, encroached_facets, encroached_segments
            (the certificate of mesh as returned), unchecked_faces, unchecked_segments (rows the certificate
            did not reach before time_limit; the status is then "budget_exhausted" or the earlier stop's),
            volume_mesh ("built", or why mesh.tets is empty: a stop left the Delaunay mesh not conforming to
            some facet; boundary_faces are then the subfacets, oriented like the input triangles),
            smallest_subsegment, max_steiner, min_length and max_work (the values used; max_work bounds
            each strategy pass), time_limit (as given; None: none), work (units spent by every attempt
            together), seconds (wall time from
            refine_gabriel's ``started``), diagnosis (smallest input angles with kind/degrees/vertices/facets,
            Steiner points per input vertex and per input segment, encroached_per_segment: the subsegments
            the certificate found encroached by input segment [a, b] and encroacher, where [a, b, c, d] (a
            point of input segment [c, d]), [a, b, v] (input vertex v) or [a, b] (a facet point), top few,
            stop_reason), warnings (the PLC's, from
            validation), negative_couplings (edges of mesh whose control-volume coupling is negative,
            :func:`control_volumes3d`; floating point).
    report: the GabrielReport of mesh.
    """

    mesh: TetMesh
    status: Status
    stats: dict[str, Any] = field(default_factory=dict)
    report: GabrielReport | None = None


def _index_array(a: np.ndarray | None, cols: int) -> np.ndarray:
    if a is None:
        return np.zeros((0, cols), dtype=np.int64)
    return np.ascontiguousarray(np.asarray(a, dtype=np.int64).reshape(-1, cols))


SAFE_MAGNITUDE = 2.0**64  # coordinates within [2^-64, 2^64] in absolute value go to the core as they are


def power_of_two_exponent(points: np.ndarray) -> int:
    """The exponent e by which the 3D core's inputs are scaled (times 2^-e) and its outputs scaled back:
    0 when the largest absolute coordinate of ``points`` (n, 3) lies within [2^-64, 2^64] (or all are 0),
    else the one bringing it into [1/2, 1). Scaling by a power of two is exact (no under- or overflow is
    allowed: that is checked) and the exact predicates decide the same on scaled points, so the results are
    those of the input, while the core's rounded constructions (circumcentres, projections) stay far from
    float64's overflow and underflow. Raises InvalidInputError when the coordinates span more magnitudes
    than float64 can scale exactly (a coordinate would round)."""
    p = np.asarray(points, dtype=np.float64)
    largest = float(np.abs(p).max()) if p.size else 0.0
    if largest == 0.0 or 1.0 / SAFE_MAGNITUDE <= largest <= SAFE_MAGNITUDE:
        return 0
    e = int(np.frexp(largest)[1])
    if not np.array_equal(np.ldexp(np.ldexp(p, -e), e), p):
        raise InvalidInputError(
            f"the coordinates span too many magnitudes for float64 (largest {largest!r}, smallest nonzero "
            f"{float(np.abs(p[p != 0]).min())!r}): scaling them into a safe range would round some")
    return e


def check_gabriel(mesh: TetMesh) -> GabrielReport:
    """Exact Gabriel certificate of mesh.boundary_faces (f, 3) and mesh.segments (k, 2) against mesh.points.

    Cost: O((n + f + k) log n) for well-shaped meshes (a kd-tree proposes candidates, the exact predicate
    decides): about 1e7 faces per 10 s on one core for a finely subdivided sphere.
    Raises InvalidInputError for out-of-range indices, collinear faces or zero-length segments.
    """
    faces = _index_array(mesh.boundary_faces, 3)
    segments = _index_array(mesh.segments, 2)
    points = np.ascontiguousarray(np.asarray(mesh.points, dtype=np.float64).reshape(-1, 3))
    d = _core.check_gabriel(np.ldexp(points, -power_of_two_exponent(points)), faces, segments)
    return GabrielReport._from_core(d, len(faces), len(segments))


def boundary_certificate(mesh: TetMesh, report: GabrielReport | None = None) -> dict[str, Any]:
    """What ``nonobtuse check3d`` reports of a tetrahedral mesh, JSON-ready: points, tets, boundary_faces
    (counts), steiner_points (from mesh.stats; None when the mesh does not say), encroached_facets,
    encroached_segments (the exact :func:`check_gabriel`, or ``report`` when given: it must be that check of
    this mesh, e.g. to draw the same offenders without checking twice), gabriel (its ``to_dict()``) and
    control_volumes (:func:`control_volume_summary`) and warnings (from mesh.stats, e.g. orientation). The
    mesh is Gabriel iff both encroached counts are 0. Cost: check_gabriel plus the control volumes,
    near-linear."""
    report = check_gabriel(mesh) if report is None else report
    return {"points": len(mesh.points), "tets": len(mesh.tets), "boundary_faces": len(mesh.boundary_faces),
            "steiner_points": mesh.stats.get("steiner_points"), "encroached_facets": len(report.faces),
            "encroached_segments": len(report.segments), "gabriel": report.to_dict(),
            "control_volumes": control_volume_summary(mesh), "warnings": list(mesh.stats.get("warnings", []))}


def _ldexp_or_none(x: float | None, k: int) -> float | None:
    """x * 2^k, or None when x is None, not finite, or the product over- or underflows."""
    if x is None or not math.isfinite(x):
        return None
    try:
        y = math.ldexp(x, k)
    except OverflowError:
        return None
    return y if y != 0 or x == 0 else None


def control_volume_summary(mesh: TetMesh) -> dict[str, Any]:
    """The control-volume summary of ``mesh`` (:meth:`ControlVolumes3D.to_dict`), computed on the points
    scaled exactly by a power of two into a safe range and scaled back (None where the value overflows
    float64). ``flat_in_floating_point``: tets whose volume is positive (exact orientation) but 0 in floating
    point; their circumcentres are computed exactly and rounded."""
    e = power_of_two_exponent(mesh.points)
    scaled = replace(mesh, points=np.ldexp(np.asarray(mesh.points, dtype=np.float64), -e))
    cv = control_volumes3d(scaled)
    with np.errstate(all="ignore"):  # flat tets give NaN, counted below
        summary = cv.to_dict()
    summary["flat_in_floating_point"] = cv.flat_in_floating_point
    summary["min_coupling"] = _ldexp_or_none(summary["min_coupling"], e)
    summary["total_volume"] = _ldexp_or_none(summary["total_volume"], 3 * e)
    return summary


def negative_couplings(mesh: TetMesh) -> int:
    """The number of edges of ``mesh`` whose coupling coefficient is negative: the ``negative_couplings`` of
    :func:`control_volume_summary` (exact signs, the points scaled the same way) without the floating-point
    magnitudes and volumes (``_core.dual_area_signs``)."""
    points = np.asarray(mesh.points, dtype=np.float64).reshape(-1, 3)
    points = np.ldexp(points, -power_of_two_exponent(points))
    tets = np.ascontiguousarray(mesh.tets, dtype=np.int64).reshape(-1, 4)
    signs = _core.dual_area_signs(points, tets)["sign"]
    return int((signs < 0).sum())


def _print_progress(steiner: int, segments: int, facets: int, seconds: float) -> None:
    print(
        f"refine_gabriel: {steiner} Steiner points, {segments} encroached subsegments, {facets} encroached "
        f"subfacets in the last scan or check, {seconds:.1f} s",
        file=sys.stderr,
    )


def _diagnosis(g: _core.Refine3DDiagnosis) -> dict[str, Any]:
    """The ``stats["diagnosis"]`` dict (see :class:`Gabriel3DResult`) of the core's diagnosis."""
    return {
        "smallest_angles": [{"kind": a.kind, "degrees": a.degrees, "vertices": a.vertices, "facets": a.facets}
                            for a in g.smallest_angles],
        "steiner_per_vertex": [{"where": c.where, "count": c.count} for c in g.steiner_per_vertex],
        "steiner_per_segment": [{"where": c.where, "count": c.count} for c in g.steiner_per_segment],
        "encroached_per_segment": [{"where": c.where, "count": c.count} for c in g.encroached_per_segment],
        "stop_reason": g.stop_reason,
    }


def refine_gabriel(
    plc: PLC,
    max_steiner: int | None = None,
    min_length: float | None = None,
    time_limit: float | None = None,
    split: Literal["shells", "midpoint", "greedy", "protected", "mirrored"] = "shells",
    protected_fallback: bool = True,
    fallback_own_limits: bool = True,
    progress: Callable[[int, int, int, float], None] | bool | None = None,
    progress_every: int = 1000,
    started: float | None = None,
    max_work: int | None = None,
    control_volumes: bool = True,
) -> Gabriel3DResult:
    """Add Steiner points on the PLC's segments and facets until every subfacet and subsegment is Gabriel.

    plc: points (n, 3) float64; triangles (m, 3) int64 with facet_ids (m,) (triangles of one planar facet
    share an id); segments (k, 2); holes (h, 3) volume-hole seeds; regions (r, 4) x, y, z, attribute.
    Encroached subsegments are split first (midpoint, or split="shells": at a power-of-two distance from an
    input vertex end, or split="greedy": the 2D paper's Greedy-Refine along the subsegment, the end of the
    longest piece from one end whose diametral sphere holds none of its current encroachers, checked exactly
    after rounding; the shells rule where an end is an input vertex with an acute angle between input
    segments, or where the greedy piece or the rest would be under 1/4 of the subsegment;
    stats["greedy_splits"] counts the greedy points), then encroached subfacets at their circumcenter, unless
    it encroaches a subsegment of the facet or lies outside the facet, in which case that subsegment is
    split. At facet corners below 3 degrees (every rule), a point split onto one of the two segments at
    distance r from the corner also goes on the other at cos(angle / 2) r, checked exactly, so that the two
    never encroach each other (needle facets of marching-cubes surfaces). Where the protected rerun below
    follows with its own limits and min_length is left to the default, that pass stops once a split leaves a
    subsegment shorter than 1/1000 of the input's smallest scale (the distance between its two closest
    points or the smallest altitude of its triangles, whichever is smaller): a cascade, which the rerun from
    the input replaces anyway. When that pass does not converge
    (and time_limit has time left), the protected strategy runs from
    the input, and its result is returned if it converged (where max_steiner and min_length are left to the
    defaults, this rerun gets 4 times the Steiner budget and 1/1000 of the min_length: its split
    rules bound the sizes by the input's features, and small angles need points in proportion to 1 / angle;
    fallback_own_limits=False gives it the shared defaults, as the 3D quality pass's repairs do):
    protecting balls at every apex vertex (an input segment leaning over a facet through its end at less
    than 90 degrees; radius a power of two <= 1/4 of the vertex's local feature size), each segment through
    an apex split on its ball's sphere, and subfacet split points strictly inside a ball moved to its sphere,
    which ends the cascade down small segment-facet angles. Where the input has near-parallel close
    segments (ends pairwise within 1e-5 of their length: a thin strip, a needle facet's long sides), the
    rerun places stations instead (gabriel3d_stations.h): a point split onto one goes on the others too, at
    equal distance from a shared end or at the foot of the perpendicular, its rounding checked exactly, and
    its foot in a facet the segment leans over; no balls at their ends, mirrored facet meshes elsewhere
    (step.off). split="mirrored" runs the protected strategy
    plus mirrored facet meshes (a point placed on a facet whose foot lies on a segment where it meets another
    facet below 90 degrees also goes to its image on that facet, verified exactly: gabriel3d_mirror.h); it
    runs from the input, with the protected rerun's limits, when the protected rerun does not converge either
    (the spike at 80 degrees), and its result is returned if it converged (not with
    fallback_own_limits=False).
    split="protected" or "mirrored" runs only that strategy; protected_fallback=False returns the first pass
    as it ended. stats["strategy"] names the strategy of the returned mesh ("shells", ..., or
    "shells+protected" / "shells+mirrored" after a fallback), stats["other_attempt"] the status and stop
    reason of the attempts not returned ("" when one ran), stats["protecting_balls"] the apices protected.
    The facets' boundary edges count as segments. Stops at max_steiner (None: the core's default,
    ``Refine3DOptions::max_steiner`` in
    ``gabriel3d.h``, linear in the number of input points), max_work (a deterministic work budget of each
    strategy pass, the first and each rerun one each: exact encroachment queries plus rows of the
    exact checks plus points of the Delaunay rebuilds; None: the core's default, linear in the input size),
    time_limit (seconds; None, the default: no wall-clock limit, so the outcome does not depend on the
    machine), min_length (no split may
    create a shorter edge; None: the core's default, a small fraction of the bounding box diagonal; 0 turns it
    off) or when stalled; the status says which, stats["max_steiner"] / ["min_length"] / ["max_work"] /
    ["time_limit"] the limits used and stats["work"] the work units spent by every attempt together.
    time_limit bounds the refinement and the exact check of the result (not the final Delaunay
    tetrahedralization, O(n log n)); rows the check did not reach are counted in
    stats["unchecked_faces"] / ["unchecked_segments"].
    started: the time.perf_counter() at which the caller's work began (e.g. before loading the PLC):
    time_limit and stats["seconds"] count from it. None: from this call.
    progress: True prints a line to stderr every progress_every insertions and after every exact check of the
    Delaunay mesh (once per repair round); a callable receives (steiner_points, encroached_subsegments,
    encroached_subfacets, seconds), the counts of the last scan or check.
    control_volumes: False skips the control-volume summary (stats["negative_couplings"] is then None), for
    callers that repair again before using the mesh.
    Guarantee: status == "converged" iff the exact check of the returned mesh passes. Deterministic.
    Cost: each round rescans all subsegments and subfacets (O(s log n)); meant for PLCs up to ~1e5 facets.
    From 1,024 points a second thread builds each round's Delaunay tetrahedralization while the points are
    made and takes half of the exact check; the result does not depend on it.
    Raises InvalidInputError for malformed PLCs (indices, duplicate points, degenerate or crossing facet
    edges).
    """
    started = time.perf_counter() if started is None else started
    callback = _print_progress if progress is True else (progress or None)
    _check_limits(max_steiner, min_length, time_limit, max_work)
    points = np.ascontiguousarray(np.asarray(plc.points, dtype=np.float64).reshape(-1, 3))
    e = power_of_two_exponent(points)  # the core works on points * 2^-e, exactly
    regions = np.ascontiguousarray(np.asarray(plc.regions, dtype=np.float64).reshape(-1, 4))
    regions = np.column_stack([np.ldexp(regions[:, :3], -e), regions[:, 3]])
    r = _core.refine_gabriel(
        np.ldexp(points, -e),
        _index_array(plc.triangles, 3),
        np.ascontiguousarray(np.asarray(plc.facet_ids, dtype=np.int64).reshape(-1)),
        _index_array(plc.segments, 2),
        np.ldexp(np.ascontiguousarray(np.asarray(plc.holes, dtype=np.float64).reshape(-1, 3)), -e),
        regions,
        -1 if max_steiner is None else int(max_steiner),
        -1.0 if min_length is None else float(np.ldexp(min_length, -e)),
        -1 if max_work is None else int(max_work),
        math.inf if time_limit is None else max(0.0, float(time_limit) - (time.perf_counter() - started)),
        split,
        bool(protected_fallback),
        bool(fallback_own_limits),
        int(progress_every),
        callback,
    )
    faces, segments, certificate = r.boundary_faces, r.segments, r.certificate
    report = GabrielReport._from_core(certificate, len(faces), len(segments))
    status = r.status
    core_points = r.points
    steiner = np.ldexp(core_points[len(points):], e)
    all_points = np.concatenate([points, steiner])
    stats: dict[str, Any] = {
        "backend": "cgal-gabriel",
        "status": status,
        "steiner_points": r.steiner_on_segments + r.steiner_on_facets,
        "steiner_on_segments": r.steiner_on_segments,
        "greedy_splits": r.greedy_splits,
        "strategy": r.strategy,
        "other_attempt": r.other_attempt,
        "protecting_balls": r.protecting_balls,
        "steiner_on_facets": r.steiner_on_facets,
        "encroached_facets": len(report.faces),
        "encroached_segments": len(report.segments),
        "unchecked_faces": certificate.unchecked_faces,
        "unchecked_segments": certificate.unchecked_segments,
        "smallest_subsegment": float(np.ldexp(r.smallest_subsegment, e)),
        "max_steiner": r.max_steiner,
        "min_length": float(np.ldexp(r.min_length, e)),
        "max_work": r.max_work,
        "work": r.work,
        "time_limit": time_limit,
        "volume_mesh": r.volume_mesh,
        "seconds": None,  # set last, below
        "diagnosis": _diagnosis(r.diagnosis),
        "warnings": list(plc.warnings),
    }
    mesh = TetMesh(
        points=all_points,
        tets=r.tets,
        boundary_faces=faces,
        face_markers=plc.markers_of_facets(r.face_markers),  # the core reports facet ids
        segments=segments,
        tet_regions=region_attributes(r.tet_regions, plc, conforming=status == "converged"),
        stats=stats,
        face_facets=np.asarray(r.face_markers, dtype=np.int64),
    )
    if e and not np.array_equal(np.ldexp(steiner, -e), core_points[len(points):]):
        # Scaled back, a Steiner point rounded (it is subnormal): certify the points as returned.
        report = check_gabriel(mesh)
        status = "stalled" if status == "converged" and not report.ok else status
        stats.update(status=status, encroached_facets=len(report.faces),
                     encroached_segments=len(report.segments))
    stats["negative_couplings"] = negative_couplings(mesh) if control_volumes else None
    stats["seconds"] = time.perf_counter() - started
    return Gabriel3DResult(mesh=mesh, status=cast(Status, status), stats=stats, report=report)


def _check_limits(max_steiner: Any, min_length: Any, time_limit: Any, max_work: Any = None) -> None:
    """InvalidInputError unless max_steiner and max_work are None or integers in [0, 2^62), and min_length and
    time_limit are None or finite and >= 0 (negative values would select the core's defaults)."""
    for name, count in (("max_steiner", max_steiner), ("max_work", max_work)):
        if count is not None and (
            isinstance(count, bool) or not isinstance(count, (int, np.integer)) or not 0 <= count < 2**62
        ):
            raise InvalidInputError(f"{name} must be an integer in [0, 2^62), got {count!r}")
    for name, value in (("min_length", min_length), ("time_limit", time_limit)):
        if value is None:
            continue
        if isinstance(value, bool) or not isinstance(value, (int, float, np.number)) or not (
            math.isfinite(value) and value >= 0
        ):
            raise InvalidInputError(f"{name} must be a finite number >= 0, got {value!r}")
