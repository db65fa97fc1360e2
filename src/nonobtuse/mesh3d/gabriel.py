"""Gabriel boundaries in 3D: the exact certificate (check_gabriel) and the repair (refine_gabriel).

A boundary face (triangle) or segment is Gabriel when no mesh vertex lies strictly inside its diametral sphere
(for a face: the smallest sphere through its corners; for a segment: the sphere having it as a diameter). When
every subfacet and subsegment of a PLC is Gabriel, the Delaunay tetrahedralization of the vertices conforms to
the PLC and its control volumes see nonnegative boundary coefficients.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass, field
from typing import Any, Callable, Literal

import numpy as np

from nonobtuse import _core
from nonobtuse.mesh3d.plc import PLC, TetMesh

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
    def _from_core(cls, d: dict[str, Any], n_faces: int, n_segments: int) -> GabrielReport:
        return cls(
            faces=d["faces_index"],
            face_vertices=d["faces_vertex"],
            face_depths=d["faces_depth"],
            segments=d["segments_index"],
            segment_vertices=d["segments_vertex"],
            segment_depths=d["segments_depth"],
            n_faces=n_faces,
            n_segments=n_segments,
        )


@dataclass
class Gabriel3DResult:
    """The outcome of refine_gabriel.

    mesh:   the TetMesh (PLC points first in input order, then Steiner points; tets of the Delaunay
            tetrahedralization inside the PLC; boundary_faces with face_markers = input facet ids; segments =
            the
            subsegments of the PLC segments and of the facets' boundary edges).
    status: "converged" (the exact check of mesh passes), "budget_exhausted" (max_steiner or time_limit),
            "min_length_reached" or "stalled" (no split could make progress).
    stats:  steiner_points, steiner_on_segments, steiner_on_facets, encroached_facets, encroached_segments
            (the certificate of mesh as returned), unchecked_faces, unchecked_segments (rows the certificate
            did not reach before time_limit; the status is then "budget_exhausted" or the earlier stop's),
            volume_mesh ("built", or why mesh.tets is empty: a stop left the Delaunay mesh not conforming to
            some facet; boundary_faces are then the subfacets, oriented like the input triangles),
            smallest_subsegment, min_length (the value used), seconds,
            diagnosis (smallest input angles with kind/degrees/vertices/facets, Steiner points per input
            vertex and per input segment, stop_reason).
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


def check_gabriel(mesh: TetMesh) -> GabrielReport:
    """Exact Gabriel certificate of mesh.boundary_faces (f, 3) and mesh.segments (k, 2) against mesh.points.

    Cost: O((n + f + k) log n) for well-shaped meshes (a kd-tree proposes candidates, the exact predicate
    decides): about 1e7 faces per 10 s on one core for a finely subdivided sphere.
    Raises InvalidInputError for out-of-range indices, collinear faces or zero-length segments.
    """
    faces = _index_array(mesh.boundary_faces, 3)
    segments = _index_array(mesh.segments, 2)
    points = np.ascontiguousarray(np.asarray(mesh.points, dtype=np.float64).reshape(-1, 3))
    d = _core.check_gabriel(points, faces, segments)
    return GabrielReport._from_core(d, len(faces), len(segments))


def _print_progress(steiner: int, segments: int, facets: int, seconds: float) -> None:
    print(
        f"refine_gabriel: {steiner} Steiner points, {segments} encroached subsegments, {facets} encroached "
        f"subfacets in the last scan or check, {seconds:.1f} s",
        file=sys.stderr,
    )


def default_steiner_budget(n_points: int) -> int:
    """The default Steiner budget of :func:`refine_gabriel` for a PLC of n_points vertices: 10 n + 10,000."""
    return 10 * n_points + 10_000


def default_min_length(points: np.ndarray) -> float:
    """The default min_length of :func:`refine_gabriel`: 1e-6 of the diagonal of the bounding box of `points`
    (n, 3). On the corpus the converged runs never come near it (their smallest subsegments are >= 8e-5 of the
    diagonal) and give the same meshes with it; runs caught in a small-angle cascade end at it with
    min_length_reached instead of spinning down to 1e-17 subsegments until the budget or a stall."""
    p = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    return 1e-6 * float(np.linalg.norm(p.max(axis=0) - p.min(axis=0))) if len(p) else 0.0


def refine_gabriel(
    plc: PLC,
    max_steiner: int | None = None,
    min_length: float | None = None,
    time_limit: float = 60.0,
    split: Literal["shells", "midpoint", "greedy", "protected"] = "shells",
    protected_fallback: bool = True,
    progress: Callable[[int, int, int, float], None] | bool | None = None,
    progress_every: int = 1000,
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
    split. When that pass does not converge (and time_limit has time left), the protected strategy runs from
    the input with the same budget, and its result is returned if it converged: protecting balls at every apex
    vertex (an input segment leaning over a facet through its end at less than 90 degrees; radius a power of
    two <= 1/4 of the vertex's local feature size), each segment through an apex split on its ball's sphere,
    and subfacet split points strictly inside a ball moved to its sphere, which ends the cascade down small
    segment-facet angles. split="protected" runs only that strategy; protected_fallback=False returns the
    first pass as it ended. stats["strategy"] names the strategy of the returned mesh ("shells", ..., or
    "shells+protected" after a fallback), stats["other_attempt"] the status and stop reason of the attempt not
    returned ("" when one ran), stats["protecting_balls"] the apices protected. The facets' boundary edges
    count as segments. Stops at max_steiner (default_steiner_budget(n) when None: 10 n + 10,000 for n input
    points; real CAD parts need about 2-5 n), time_limit (seconds), min_length (no split may create a shorter
    edge; default_min_length(points) when None: 1e-6 of the bounding box diagonal; 0 turns it off) or when
    stalled; the status says which. time_limit bounds the refinement and the exact check of the result (not
    the final Delaunay tetrahedralization, O(n log n)); rows the check did not reach are counted in
    stats["unchecked_faces"] / ["unchecked_segments"]. progress: True prints a line to stderr every
    progress_every insertions and after every exact check of the Delaunay mesh (once per repair round); a
    callable receives (steiner_points, encroached_subsegments, encroached_subfacets, seconds), the counts of
    the last scan or check.
    Guarantee: status == "converged" iff the exact check of the returned mesh passes. Deterministic.
    Cost: each round rescans all subsegments and subfacets (O(s log n)); meant for PLCs up to ~1e5 facets.
    Raises InvalidInputError for malformed PLCs (indices, duplicate points, degenerate or crossing facet
    edges).
    """
    callback = _print_progress if progress is True else (progress or None)
    min_length = default_min_length(plc.points) if min_length is None else float(min_length)
    d = _core.refine_gabriel(
        np.ascontiguousarray(np.asarray(plc.points, dtype=np.float64).reshape(-1, 3)),
        _index_array(plc.triangles, 3),
        np.ascontiguousarray(np.asarray(plc.facet_ids, dtype=np.int64).reshape(-1)),
        _index_array(plc.segments, 2),
        np.ascontiguousarray(np.asarray(plc.holes, dtype=np.float64).reshape(-1, 3)),
        np.ascontiguousarray(np.asarray(plc.regions, dtype=np.float64).reshape(-1, 4)),
        int(default_steiner_budget(len(plc.points)) if max_steiner is None else max_steiner),
        float(min_length),
        float(time_limit),
        split,
        bool(protected_fallback),
        int(progress_every),
        callback,
    )
    report = GabrielReport._from_core(d["certificate"], len(d["boundary_faces"]), len(d["segments"]))
    stats = {
        "backend": "cgal-gabriel",
        "status": d["status"],
        "steiner_points": d["steiner_on_segments"] + d["steiner_on_facets"],
        "steiner_on_segments": d["steiner_on_segments"],
        "greedy_splits": d["greedy_splits"],
        "strategy": d["strategy"],
        "other_attempt": d["other_attempt"],
        "protecting_balls": d["protecting_balls"],
        "steiner_on_facets": d["steiner_on_facets"],
        "encroached_facets": len(report.faces),
        "encroached_segments": len(report.segments),
        "unchecked_faces": d["certificate"]["unchecked_faces"],
        "unchecked_segments": d["certificate"]["unchecked_segments"],
        "smallest_subsegment": d["smallest_subsegment"],
        "min_length": min_length,
        "volume_mesh": d["volume_mesh"],
        "seconds": d["seconds"],
        "diagnosis": d["diagnosis"],
    }
    mesh = TetMesh(
        points=d["points"],
        tets=d["tets"],
        boundary_faces=d["boundary_faces"],
        face_markers=d["face_markers"],
        segments=d["segments"],
        tet_regions=d["tet_regions"] if len(plc.regions) else None,
        stats=stats,
    )
    return Gabriel3DResult(mesh=mesh, status=d["status"], stats=stats, report=report)
