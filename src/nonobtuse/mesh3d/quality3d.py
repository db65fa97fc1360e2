"""Interior quality and size for 3D meshes with a Gabriel boundary: TetGen's ``-q`` (radius-edge ratio) and ``-a``
(maximum volume) without touching the boundary certificate.

:func:`refine_quality3d` first repairs the boundary (:func:`refine_gabriel`: every subfacet and subsegment gets an
empty diametral sphere), then adds interior points only, each outside every subfacet's and subsegment's closed
diametral sphere (exact predicate), so no boundary simplex becomes encroached or cospherical with a new point, and
the Delaunay tetrahedralization of all points still conforms to the PLC. The interior points come from TetGen
(``-pq R -a V -Y`` on the repaired boundary; the points it puts inside a diametral sphere are dropped) and then
from circumcenters of the tets that still break a bound, inserted in rounds over CGAL's exact Delaunay
tetrahedralization. A bad tet whose circumcenter falls in a closed diametral sphere is left as it is (splitting the
boundary there is the boundary repair's business): the status says so and the stats count such tets.
"""

from __future__ import annotations

import math
import sys
import time
from dataclasses import dataclass, field
from typing import Any, Callable, Literal, Mapping

import numpy as np
from scipy.spatial import cKDTree

from nonobtuse import _core
from nonobtuse.errors import InvalidInputError
from nonobtuse.mesh3d.gabriel import GabrielReport, check_gabriel, control_volume_summary, refine_gabriel
from nonobtuse.mesh3d.plc import PLC, TetMesh, region_attributes

QualityStatus = Literal["converged", "quality_blocked", "budget_exhausted", "min_length_reached", "stalled"]
Start = Literal["tetgen", "boundary"]


@dataclass
class Quality3DResult:
    """The outcome of refine_quality3d.

    mesh:   the TetMesh: PLC points first in input order, then the boundary Steiner points (as refine_gabriel
            returned them), then the interior points; tets of the Delaunay tetrahedralization of all of them in
            the PLC's regions (exact, CGAL); boundary_faces, face_markers, face_facets and segments are the
            repaired boundary's subfacets and subsegments, unchanged by the interior points.
    status: "converged" (the exact Gabriel check of mesh passes and every tet meets the bounds, floating point),
            "quality_blocked" (certificate passes; the tets still over a bound all have their circumcenter in a
            closed boundary diametral sphere), "budget_exhausted" (max_points or time_limit), or the boundary
            repair's status when it did not converge (then no interior point is added).
    stats:  the boundary repair's stats (steiner_points, ...) plus boundary_points, interior_points, tets,
            worst_radius_edge, max_volume (the largest tet volume), bad_tets (tets over a bound), blocked_tets
            (those whose circumcenter lies in a closed diametral sphere), rounds, tetgen_points_dropped (TetGen
            points inside a closed diametral sphere), radius_edge / max_volume_bound (the bounds asked), start,
            quality_seconds, seconds.
    report: the GabrielReport of mesh (exact).
    """

    mesh: TetMesh
    status: QualityStatus
    stats: dict[str, Any] = field(default_factory=dict)
    report: GabrielReport | None = None


def tet_circumspheres(points: np.ndarray, tets: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Circumcenters (t, 3), circumradii (t,) and volumes (t,) of tets (t, 4) int64 over points (n, 3) float64
    (positively oriented tets give positive volumes). Floating point; a flat tet gives inf or NaN."""
    a = points[tets[:, 0]]
    b, c, d = (points[tets[:, k]] - a for k in (1, 2, 3))
    cd, db, bc = np.cross(c, d), np.cross(d, b), np.cross(b, c)
    six_volume = np.einsum("ij,ij->i", b, cd)
    offset = ((b * b).sum(1)[:, None] * cd + (c * c).sum(1)[:, None] * db + (d * d).sum(1)[:, None] * bc)
    with np.errstate(divide="ignore", invalid="ignore"):
        offset = offset / (2.0 * six_volume)[:, None]
    return a + offset, np.sqrt((offset * offset).sum(1)), six_volume / 6.0


def shortest_edges(points: np.ndarray, tets: np.ndarray) -> np.ndarray:
    """The shortest edge length (t,) of each tet (t, 4) over points (n, 3)."""
    pairs = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)]
    d2 = np.stack([((points[tets[:, i]] - points[tets[:, j]]) ** 2).sum(1) for i, j in pairs])
    return np.sqrt(d2.min(0))


def tet_quality(mesh: TetMesh) -> dict[str, Any]:
    """Shape and size of mesh.tets, floating point: tets, worst_radius_edge (circumradius over shortest edge; a
    regular tet has 0.612), max_volume, min_volume, and the fraction of tets with radius-edge above 2."""
    tets = np.asarray(mesh.tets, dtype=np.int64).reshape(-1, 4)
    if not len(tets):
        return {"tets": 0, "worst_radius_edge": None, "max_volume": None, "min_volume": None,
                "radius_edge_over_2": None}
    _, radius, volume = tet_circumspheres(np.asarray(mesh.points, dtype=np.float64), tets)
    ratio = radius / shortest_edges(np.asarray(mesh.points, dtype=np.float64), tets)
    return {"tets": len(tets), "worst_radius_edge": float(ratio.max()), "max_volume": float(volume.max()),
            "min_volume": float(volume.min()), "radius_edge_over_2": float((ratio > 2.0).mean())}


def _print_progress(round_: int, interior: int, bad: int, blocked: int, seconds: float) -> None:
    print(f"refine_quality3d: round {round_}, {interior} interior points, {bad} tets over a bound "
          f"({blocked} blocked by a boundary sphere), {seconds:.1f} s", file=sys.stderr)


def refine_quality3d(
    plc: PLC,
    max_volume: float | Mapping[float, float] | None = None,
    radius_edge: float | None = None,
    max_points: int | None = None,
    time_limit: float = 120.0,
    start: Start = "tetgen",
    progress: Callable[[int, int, int, int, float], None] | bool | None = None,
    started: float | None = None,
    **gabriel_options: Any,
) -> Quality3DResult:
    """Repair the boundary of `plc` to Gabriel (refine_gabriel with ``gabriel_options``: max_steiner,
    min_length, split, protected_fallback), then add interior points until every tet has radius-edge ratio
    <= radius_edge and volume <= max_volume, never inside a subfacet's or subsegment's closed diametral sphere.

    plc: as for refine_gabriel. max_volume: a volume bound for every tet, or a mapping {region attribute:
    bound} (regions not listed are free; the attributes are those of plc.regions, or 1, 2, ... without seeds),
    or None. radius_edge: a bound > 1 on circumradius / shortest edge (TetGen's -q; 2 is its default), or None.
    max_points: interior point budget (None: 10^6). time_limit: seconds for everything (boundary repair
    included), checked between rounds. start: "tetgen" takes TetGen's -pq/-a -Y points on the repaired boundary
    as the first interior points (needs the 3d extra; falls back to "boundary" without it), "boundary" starts
    from the boundary points alone. progress: True prints a line per round to stderr; a callable gets (round,
    interior_points, bad_tets, blocked_tets, seconds). started: time.perf_counter() at which the caller's work
    began (time_limit counts from it).
    Split rule and termination: a tet over a bound gets its circumcenter, in rounds; within a round a circumcenter
    is taken only when no point taken before it in the round lies inside its tet's circumsphere (floating point),
    as if inserted one by one (Bowyer-Watson), so each new point is at least its tet's circumradius r from every
    other point. A tet over the radius-edge bound has r > radius_edge * (its shortest edge) >= the smallest
    distance between points so far (radius_edge > 1); a tet over the volume bound V has r >= (3V / 4 pi)^(1/3)
    (a tet lies in its circumsphere). No boundary point is added, so the distance between points never drops below
    min(smallest boundary edge, (3V / 4 pi)^(1/3)) and the points pack a bounded domain: the loop ends. A
    circumcenter in a closed diametral sphere is not inserted (its tet stays); with none in any (the lemma of
    Ruppert and Shewchuk), circumcenters lie in the domain: one that lands outside (rounding) is dropped.
    Guarantee: the returned mesh's boundary certificate is the exact check_gabriel of it (report); status
    "converged" needs it to pass. The bounds themselves are measured in floating point. Deterministic.
    Cost: the boundary repair, one TetGen run, then per round a Delaunay tetrahedralization, O(n log n).
    Raises InvalidInputError for a malformed PLC or bounds (radius_edge <= 1, max_volume <= 0, not finite).
    """
    started = time.perf_counter() if started is None else started
    callback = _print_progress if progress is True else (progress or None)
    _check_bounds(max_volume, radius_edge, max_points)
    switches = _tetgen_switches(max_volume, radius_edge)
    surface, surface_note = _tetgen_surface(plc, switches + "AQ") if start == "tetgen" else (plc, "input")
    boundary = refine_gabriel(surface, time_limit=time_limit, started=started, **gabriel_options)
    stats: dict[str, Any] = dict(boundary.stats)
    stats.update(boundary_points=len(boundary.mesh.points), interior_points=0, radius_edge=radius_edge,
                 max_volume_bound=_jsonable_bound(max_volume), start=start, rounds=0, surface=surface_note)
    if boundary.status != "converged":
        stats.update(tet_quality(boundary.mesh), quality="not attempted: the boundary is not certified")
        return Quality3DResult(boundary.mesh, boundary.status, stats, boundary.report)
    t0 = time.perf_counter()
    refiner = _InteriorRefiner(plc, boundary.mesh, max_volume, radius_edge)
    interior = refiner.tetgen_points(switches + "YAQ", stats) if start == "tetgen" else np.zeros((0, 3))
    budget = 10**6 if max_points is None else int(max_points)
    status: QualityStatus = "converged"
    while True:
        interior = interior[:budget]
        mesh, interior = refiner.delaunay(interior)
        bad, blocked, centers = refiner.bad_tets(mesh)
        stats["rounds"] += 1
        seconds = time.perf_counter() - started
        if callback:
            callback(stats["rounds"], len(interior), int(bad.size), int(blocked.sum()), seconds)
        free = bad[~blocked]
        if not bad.size:
            break
        if not free.size:
            status = "quality_blocked"
            break
        if len(interior) >= budget or seconds > time_limit:
            status = "budget_exhausted"
            break
        interior = np.concatenate([interior, refiner.independent_centers(mesh, free, centers[~blocked])])
    report = check_gabriel(mesh)
    if not report.ok:  # cannot happen: no point is in a closed diametral sphere; the check decides all the same
        status = "stalled"
    stats.update(tet_quality(mesh), interior_points=len(interior), bad_tets=int(bad.size),
                 blocked_tets=int(blocked.sum()), encroached_facets=len(report.faces),
                 encroached_segments=len(report.segments), status=status,
                 steiner_points=len(mesh.points) - len(plc.points),
                 negative_couplings=control_volume_summary(mesh)["negative_couplings"],
                 quality_seconds=time.perf_counter() - t0, seconds=time.perf_counter() - started)
    mesh.stats = stats
    return Quality3DResult(mesh, status, stats, report)


class _InteriorRefiner:
    """The repaired boundary (fixed) and the bounds; interior points come and go as (k, 3) arrays."""

    def __init__(self, plc: PLC, boundary: TetMesh, max_volume: Any, radius_edge: float | None) -> None:
        self.plc, self.boundary = plc, boundary
        self.points = np.ascontiguousarray(boundary.points, dtype=np.float64)
        self.faces = np.ascontiguousarray(boundary.boundary_faces, dtype=np.int64).reshape(-1, 3)
        self.segments = np.ascontiguousarray(boundary.segments, dtype=np.int64).reshape(-1, 2)
        self.max_volume, self.radius_edge = max_volume, radius_edge

    def closed_hits(self, candidates: np.ndarray) -> np.ndarray:
        """True for each candidate (k, 3) in some subfacet's or subsegment's closed diametral sphere (exact)."""
        face, segment = _core.closed_diametral_sphere_hits(self.points, self.faces, self.segments,
                                                           np.ascontiguousarray(candidates, dtype=np.float64))
        return (face >= 0) | (segment >= 0)

    def tetgen_points(self, switches: str, stats: dict[str, Any]) -> np.ndarray:
        """TetGen's interior points (``switches`` with -Y: the boundary is kept) on the repaired boundary, without
        those in a closed diametral sphere; none when TetGen is not installed or fails (stats["tetgen"] says
        why)."""
        from nonobtuse.mesh3d.tetrahedralize import tetrahedralize

        try:
            tm = tetrahedralize(self._boundary_plc(), "tetgen", switches=switches)
        except (ModuleNotFoundError, InvalidInputError) as e:
            stats["tetgen"] = f"not used: {e}"
            return np.zeros((0, 3))
        extra = np.asarray(tm.points[len(self.points):], dtype=np.float64)
        keep = ~self.closed_hits(extra)
        stats.update(tetgen=switches, tetgen_points=len(extra), tetgen_points_dropped=int((~keep).sum()))
        return extra[keep]

    def _boundary_plc(self) -> PLC:
        regions = np.asarray(self.plc.regions, dtype=np.float64).reshape(-1, 4)
        return PLC(self.points, self.faces, np.asarray(self.boundary.face_facets, dtype=np.int64), self.segments,
                   self.plc.holes, regions, self.plc.source, facet_markers=self.plc.facet_markers)

    def delaunay(self, interior: np.ndarray) -> tuple[TetMesh, np.ndarray]:
        """The Delaunay tetrahedralization (exact) of the boundary points and `interior` in the PLC's regions,
        and the interior points it uses (a point outside the regions, from a rounded circumcenter, is dropped)."""
        from nonobtuse.mesh3d.tetrahedralize import _plc_arrays

        while True:
            plc = self._boundary_plc()
            points = np.concatenate([self.points, interior])
            arrays = _plc_arrays(PLC(points, plc.triangles, plc.facet_ids, plc.segments, plc.holes, plc.regions))
            d = _core.delaunay_restricted_to_plc(*arrays)
            if len(d["uncovered_facets"]):
                raise RuntimeError("internal: the Delaunay tetrahedralization of a Gabriel boundary with no point "
                                   "in a closed diametral sphere does not conform to its facets")
            used = np.zeros(len(points), dtype=bool)
            used[np.asarray(d["tets"]).ravel()] = True
            if used[len(self.points):].all():
                break
            interior = interior[used[len(self.points):]]
        b = self.boundary
        mesh = TetMesh(points, np.asarray(d["tets"], dtype=np.int64), b.boundary_faces, b.face_markers,
                       b.segments, region_attributes(d["tet_regions"], self.plc, True), {},
                       face_facets=b.face_facets)
        return mesh, interior

    def volume_bounds(self, mesh: TetMesh) -> np.ndarray:
        """The volume bound (t,) of each tet: inf where none."""
        t = len(mesh.tets)
        if self.max_volume is None:
            return np.full(t, np.inf)
        if isinstance(self.max_volume, (int, float)):
            return np.full(t, float(self.max_volume))
        regions = np.ones(t) if mesh.tet_regions is None else np.asarray(mesh.tet_regions, dtype=np.float64)
        return np.array([self.max_volume.get(r, math.inf) for r in regions.tolist()], dtype=np.float64)

    def bad_tets(self, mesh: TetMesh) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Rows of mesh.tets over a bound (most skewed first), whether each one's circumcenter lies in a closed
        diametral sphere, and their circumcenters."""
        tets = np.asarray(mesh.tets, dtype=np.int64)
        centers, radius, volume = tet_circumspheres(mesh.points, tets)
        ratio = radius / shortest_edges(mesh.points, tets)
        over = volume > self.volume_bounds(mesh)
        if self.radius_edge is not None:
            over |= ratio > self.radius_edge
        bad = np.flatnonzero(over)
        bad = bad[np.argsort(-ratio[bad], kind="stable")]
        if not bad.size:
            return bad, np.zeros(0, dtype=bool), np.zeros((0, 3))
        return bad, self.closed_hits(centers[bad]), centers[bad]

    def independent_centers(self, mesh: TetMesh, tets: np.ndarray, centers: np.ndarray) -> np.ndarray:
        """The circumcenters (k, 3) of rows `tets` (in order) taken one by one as Bowyer-Watson would still see
        their tets: a center is skipped when a center taken before it lies inside its tet's circumsphere."""
        radius = tet_circumspheres(mesh.points, np.asarray(mesh.tets, dtype=np.int64)[tets])[1]
        tree = cKDTree(centers)
        taken = np.zeros(len(centers), dtype=bool)
        for i in range(len(centers)):
            near = tree.query_ball_point(centers[i], radius[i])
            if not taken[near].any():
                taken[i] = True
        return centers[taken]


def _tetgen_switches(max_volume: Any, radius_edge: float | None) -> str:
    """TetGen's -p -q [-a] switches for the bounds (a mapping of region bounds is left to the rounds)."""
    switches = "pq" + (repr(float(radius_edge)) if radius_edge else "")
    return switches + (f"a{float(max_volume)!r}" if isinstance(max_volume, (int, float)) else "")


def _tetgen_surface(plc: PLC, switches: str) -> tuple[PLC, str]:
    """The PLC whose facets are TetGen's boundary triangles of `plc` (``switches``: TetGen splits the facets for
    the bounds): the input points first, then TetGen's boundary Steiner points; facet ids and markers those of
    `plc`; segments the facets' boundary edges. `plc` itself, and why, when TetGen is missing or fails."""
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
    surface = PLC(tm.points[keep], faces, facets, facet_boundary_segments(faces, facets), plc.holes, plc.regions,
                  plc.source, plc.warnings, plc.facet_markers)
    return surface, f"TetGen -{switches}: {len(keep) - len(plc.points)} boundary Steiner points"


def _jsonable_bound(max_volume: Any) -> Any:
    if isinstance(max_volume, Mapping):
        return {str(k): float(v) for k, v in max_volume.items()}
    return max_volume


def _check_bounds(max_volume: Any, radius_edge: Any, max_points: Any) -> None:
    """InvalidInputError unless radius_edge is None or finite > 1, max_volume None, finite > 0 or a mapping to
    such values, and max_points None or an integer >= 0."""
    def positive(x: Any) -> bool:
        return not isinstance(x, bool) and isinstance(x, (int, float, np.number)) and math.isfinite(x) and x > 0

    if radius_edge is not None and not (positive(radius_edge) and radius_edge > 1):
        raise InvalidInputError(f"radius_edge must be a finite number > 1 (TetGen's -q; 2 is usual), got "
                                f"{radius_edge!r}")
    volumes = max_volume.values() if isinstance(max_volume, Mapping) else [max_volume]
    if max_volume is not None and not all(positive(v) for v in volumes):
        raise InvalidInputError(f"max_volume must be a finite number > 0 or a mapping region -> such a number, "
                                f"got {max_volume!r}")
    if max_points is not None and (isinstance(max_points, bool) or not isinstance(max_points, (int, np.integer))
                                   or max_points < 0):
        raise InvalidInputError(f"max_points must be an integer >= 0, got {max_points!r}")
