"""The rounds of :func:`~nonobtuse.mesh3d.quality3d.refine_quality3d`: tet shape measures, the interior
pass (``_core.refine_interior``), the boundary repair (:func:`refine_gabriel`) with interior points, and the
points that stand for circumcenters blocked by a diametral sphere."""

from __future__ import annotations

import math
import time
from collections.abc import Mapping
from dataclasses import replace
from typing import Any

import numpy as np
from scipy.spatial import cKDTree

from nonobtuse import _core
from nonobtuse.errors import InvalidInputError
from nonobtuse.mesh3d.control_volumes3d import exact_circumspheres, tet_circumcenters
from nonobtuse.mesh3d.gabriel import refine_gabriel
from nonobtuse.mesh3d.plc import PLC, TetMesh


def tet_circumspheres(points: np.ndarray, tets: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Circumcenters (t, 3) (:func:`~nonobtuse.mesh3d.control_volumes3d.tet_circumcenters`), circumradii (t,)
    and volumes (t,) of tets (t, 4) int64 over points (n, 3) float64 (positively oriented tets give positive
    volumes). Floating point where the orientation determinant is at least 2^-20 L^3 (L the longest edge from
    the first corner: its rounding error is then below 2^-30 of it), else exact
    (``control_volumes3d.exact_circumspheres``), rounded: a tet flat in floating point gets its true ratio,
    never NaN (the rule of ``tet_shape`` in cpp/src/quality3d_shape.cpp, so both measures agree)."""
    p = points[tets]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):  # those rows are recomputed below
        centers = tet_circumcenters(p[:, 0], p[:, 1], p[:, 2], p[:, 3])
        radius = np.sqrt(((centers - p[:, 0]) ** 2).sum(1))
    edges = p[:, 1:] - p[:, :1]
    det = np.einsum("ij,ij->i", edges[:, 0], np.cross(edges[:, 1], edges[:, 2]))
    volume = det / 6.0  # as signed_tet_volumes
    longest = np.sqrt((edges**2).sum(2).max(1))
    rows = np.flatnonzero(~(np.abs(det) >= 2.0**-20 * (longest * longest * longest)))
    centers[rows], radius[rows], volume[rows] = exact_circumspheres(points, tets[rows])
    return centers, radius, volume


def shortest_edges(points: np.ndarray, tets: np.ndarray) -> np.ndarray:
    """The shortest edge length (t,) of each tet (t, 4) over points (n, 3)."""
    pairs = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)]
    d2 = np.stack([((points[tets[:, i]] - points[tets[:, j]]) ** 2).sum(1) for i, j in pairs])
    return np.sqrt(d2.min(0))


def tet_quality(mesh: TetMesh, leave_out: np.ndarray | None = None, suffix: str = "") -> dict[str, Any]:
    """Shape and size of mesh.tets but the rows `leave_out`, floating point: tets, worst_radius_edge
    (circumradius over shortest edge; a regular tet has 0.612), max_volume, min_volume, and
    radius_edge_over_2 (the fraction of tets above 2); each key ends with `suffix`."""
    tets = np.asarray(mesh.tets, dtype=np.int64).reshape(-1, 4)
    if leave_out is not None:
        tets = np.delete(tets, np.asarray(leave_out, dtype=np.int64), axis=0)
    keys = ["tets", "worst_radius_edge", "max_volume", "min_volume", "radius_edge_over_2"]
    if not len(tets):
        return {k + suffix: v for k, v in zip(keys, [0, None, None, None, None])}
    _, radius, volume = tet_circumspheres(np.asarray(mesh.points, dtype=np.float64), tets)
    ratio = radius / shortest_edges(np.asarray(mesh.points, dtype=np.float64), tets)
    values = [len(tets), float(ratio.max()), float(volume.max()), float(volume.min()),
              float((ratio > 2.0).mean())]
    return {k + suffix: v for k, v in zip(keys, values)}


# Passes run again after boundary steps whose cascades nothing finished (InteriorRefiner.retry_cascade): each
# halves the step or leaves one subfacet or subsegment alone, so log2(blocked centers) + those left alone;
# only where the first failed step split for at most MAX_CASCADE_CENTERS centers (step.off's 4,164: its 21
# single steps within the 32 retries left 21 alone, for 18 s instead of 1.4, and it still stopped at
# min_length).
MAX_CASCADE_RETRIES = 32
MAX_CASCADE_CENTERS = 512


class InteriorRefiner:
    """The input PLC, the bounds and the limits shared by the rounds of refine_quality3d."""

    def __init__(self, plc: PLC, max_volume: Any, radius_edge: float | None, time_limit: float | None,
                 started: float, gabriel_options: dict[str, Any]) -> None:
        self.plc, self.max_volume, self.radius_edge = plc, max_volume, radius_edge
        # None: no wall-clock limit (the repairs' work budgets and the passes' point budgets stop them)
        self.wall_clock = time_limit is not None
        self.time_limit = math.inf if time_limit is None else float(time_limit)
        self.started, self.gabriel_options = started, gabriel_options
        self.inserted = 0  # circumcenters the interior passes inserted
        # the last pass's mesh and its rows of tets left alone near small input angles (the small-angle rule)
        self.small_angle: tuple[TetMesh | None, np.ndarray] = (None, np.zeros(0, dtype=np.int64))
        self.boundary_points = self.boundary_rounds = self.refused_splits = 0  # the passes' boundary splits
        self.lazy_tried = False  # the first pass tried without the small-angle rule's angle clauses
        # After a boundary step whose cascade nothing could finish (retry_cascade): the blocked centers a step
        # splits for at most (0: all), the subfacets and subsegments whose splits cascaded (each as its
        # corners' coordinates, sorted), the retries spent, and the last pass's failed step: its mesh, how
        # many centers it split for and what it split (rows (a, b, c) / (a, b, -1)).
        self.step_centers = 0
        self.cascades: set[tuple[tuple[float, ...], ...]] = set()
        self.retries = 0
        self.last_step: tuple[TetMesh | None, int, np.ndarray] = (None, 0, np.zeros((0, 3), dtype=np.int64))

    def retry_cascade(self, grown: TetMesh) -> bool:
        """After a pass's boundary step failed (a split refused: min_length, the pass's cap) and nothing took
        over: whether to run the pass again from its last certified mesh `grown`, its steps splitting for
        half as many blocked centers (worst first) as the failed one did, or, when that step split one
        subfacet or subsegment, with the tets whose centers lie in its closed diametral sphere left alone as
        the small-angle rule leaves tets (near small input angles a split can cascade where no rule of the
        pass catches it). At most MAX_CASCADE_RETRIES times in a run."""
        mesh, centers, elements = self.last_step
        if mesh is not grown or not centers or self.retries >= MAX_CASCADE_RETRIES or (
                not self.step_centers and centers > MAX_CASCADE_CENTERS):
            return False
        self.retries += 1
        if len(elements) == 1:
            points = np.asarray(grown.points, dtype=np.float64)
            self.cascades.add(tuple(sorted(tuple(points[i].tolist()) for i in elements[0] if i >= 0)))
        else:
            self.step_centers = max(1, centers // 2)
        return True

    def left_alone_rows(self, mesh: TetMesh) -> np.ndarray:
        """self.cascades as rows (a, 3) of indices into mesh.points, -1 third for a subsegment (those whose
        corners are all points of mesh)."""
        if not self.cascades:  # no dict of every point for every pass
            return np.zeros((0, 3), dtype=np.int64)
        index = {tuple(p): i for i, p in enumerate(np.asarray(mesh.points, dtype=np.float64).tolist())}
        rows = [[index[c] for c in key] + [-1] * (3 - len(key)) for key in sorted(self.cascades)
                if all(c in index for c in key)]
        return np.asarray(rows, dtype=np.int64).reshape(-1, 3)

    def repair(self, surface: PLC, interior: np.ndarray, share: float = 1.0, max_steiner: int | None = None,
               **overrides: Any) -> Any:
        """refine_gabriel of `surface` with `interior` (k, 3) as isolated points (after surface's points),
        within `share` of the time left (without a time limit: within its own work budget) and within
        `max_steiner` Steiner points when given (or the caller's max_steiner, if smaller); `overrides` replace
        the caller's refine_gabriel options."""
        points = np.concatenate([surface.points, np.asarray(interior, dtype=np.float64).reshape(-1, 3)])
        plc = replace(self.plc, points=points, triangles=surface.triangles, facet_ids=surface.facet_ids,
                      segments=surface.segments)
        left = self.time_limit - (time.perf_counter() - self.started)
        # the shared limits for the fallback too (unless given): a pass repairs again and again, and the
        # fallback's own wider limits let each failing repair run to its work budget (cad_knife_2deg: over
        # 200 s instead of 10 s, for the same 6-point result)
        options = {"fallback_own_limits": False, **self.gabriel_options, **overrides}
        if max_steiner is not None:
            options["max_steiner"] = min(max_steiner, options.get("max_steiner") or max_steiner)
        return refine_gabriel(plc, time_limit=max(0.0, share * left) if self.wall_clock else None,
                              control_volumes=False, **options)

    def split_mesh(self, mesh: TetMesh) -> tuple[PLC, np.ndarray]:
        """The surface PLC of `mesh` (the input points, then the other vertices of its subfacets and
        subsegments, in mesh order; its subfacets as triangles with their facet ids; its subsegments) and its
        other points (k, 3), the interior points, in mesh order."""
        on = np.zeros(len(mesh.points), dtype=bool)
        on[: len(self.plc.points)] = True
        on[np.asarray(mesh.boundary_faces, dtype=np.int64).ravel()] = True
        on[np.asarray(mesh.segments, dtype=np.int64).ravel()] = True
        renumber = np.cumsum(on) - 1
        faces = renumber[np.asarray(mesh.boundary_faces, dtype=np.int64)]
        segments = renumber[np.asarray(mesh.segments, dtype=np.int64).reshape(-1, 2)]
        surface = replace(self.plc, points=mesh.points[on], triangles=faces,
                          facet_ids=np.asarray(mesh.face_facets, dtype=np.int64), segments=segments)
        return surface, mesh.points[~on]

    @staticmethod
    def closed_hits(surface: PLC, candidates: np.ndarray) -> np.ndarray:
        """True for each candidate (k, 3) in a closed diametral sphere of a subfacet or subsegment (exact)."""
        face, segment = _core.closed_diametral_sphere_hits(
            np.ascontiguousarray(surface.points, dtype=np.float64),
            np.ascontiguousarray(surface.triangles, dtype=np.int64),
            np.ascontiguousarray(surface.segments, dtype=np.int64).reshape(-1, 2),
            np.ascontiguousarray(candidates, dtype=np.float64).reshape(-1, 3))
        return (face >= 0) | (segment >= 0)

    def tetgen_points(self, surface: PLC, switches: str, stats: dict[str, Any]) -> np.ndarray:
        """TetGen's interior points (``switches`` with -Y: the boundary is kept) on `surface`, without those
        in a closed diametral sphere; none when TetGen is not installed or fails (stats["tetgen"] says
        why)."""
        from nonobtuse.mesh3d.tetrahedralize import tetrahedralize

        try:
            tm = tetrahedralize(surface, "tetgen", switches=switches)
        except (ModuleNotFoundError, InvalidInputError) as e:
            stats["tetgen"] = f"not used: {e}"
            return np.zeros((0, 3))
        extra = np.asarray(tm.points[len(surface.points):], dtype=np.float64)
        keep = ~self.closed_hits(surface, extra)
        stats.update(tetgen=switches, tetgen_points=len(extra), tetgen_points_dropped=int((~keep).sum()))
        return extra[keep]

    @staticmethod
    def region_labels(mesh: TetMesh) -> tuple[np.ndarray, np.ndarray]:
        """The region attributes (a,) of mesh (1.0 for every tet without regions) and each tet's index (t,)
        among them."""
        regions = np.ones(len(mesh.tets)) if mesh.tet_regions is None else np.asarray(mesh.tet_regions)
        attrs, labels = np.unique(np.asarray(regions, dtype=np.float64), return_inverse=True)
        return attrs, labels.ravel().astype(np.int64)

    def volume_bounds_of(self, attrs: np.ndarray) -> np.ndarray:
        """The volume bound (a,) of each region attribute: inf where none. A mapping's key None is the bound
        everywhere."""
        if self.max_volume is None:
            return np.full(len(attrs), np.inf)
        if not isinstance(self.max_volume, Mapping):
            return np.full(len(attrs), float(self.max_volume))
        everywhere = self.max_volume.get(None, math.inf)
        return np.array([min(everywhere, self.max_volume.get(a, math.inf)) for a in attrs.tolist()],
                        dtype=np.float64).reshape(-1)

    def volume_bounds(self, mesh: TetMesh) -> np.ndarray:
        """The volume bound (t,) of each tet: inf where none."""
        attrs, labels = self.region_labels(mesh)
        return self.volume_bounds_of(attrs)[labels]

    def interior_pass(self, mesh: TetMesh, budget: int, insert: np.ndarray | None = None,
                      limits: dict[str, Any] | None = None) -> tuple[TetMesh, str, int, TetMesh | None]:
        """Delaunay refinement of `mesh` (a Gabriel boundary) in one tetrahedralization
        (``_core.refine_interior``): the points `insert` (k, 3) placed first (each strictly outside every
        closed diametral sphere and in the domain, exact, else dropped), then the circumcenters of the tets
        over a bound, worst radius-edge ratio first, each strictly outside every closed diametral sphere, in
        the domain (exact), at most `budget` of them within the time left; a center in a closed diametral
        sphere splits that subsegment or subfacet (Ruppert's and Shewchuk's rule) and the boundary is split
        until Gabriel again, in the same tetrahedralization, and so on until no center is left that a split
        frees; a tet whose split would lie at a small input angle (or, over the radius-edge bound alone, be
        shorter than its shortest edge) is left alone (the small-angle rule, ``quality3d.h``; its rows in
        :attr:`small_angle`; the first pass tries without its angle clauses first). limits: the boundary
        repair's stats (its min_length and max_steiner bound the splits). Returns the mesh (points: the
        input's, then the new ones in order; boundary_faces, face_facets and segments the split boundary),
        the pass's status ("converged", "blocked", "budget_exhausted"; "not_conforming"
        with `mesh` itself returned: it was not Delaunay to begin with; "not_conforming" or
        "boundary_stopped" after a boundary step: the mesh is the pass's state before that step, Gabriel and
        conforming), the number of tets left over a bound, and, after such a step, the split boundary over
        all the points (no tets) for the repair to tetrahedralize, else None."""
        limits = limits or {}
        max_steiner = int(limits.get("max_steiner", 10**6))
        # Lazily, in the first pass only: first without the angle clauses of the small-angle rule, its
        # boundary splits bounded by the boundary's own size (at most 2,000). When that does not converge, the
        # pass runs again from `mesh` with them (going on from that try's state instead left slit-2.smesh's
        # cascade in place: no convergence in 280 s). Inputs that converge without them (layered_box.poly,
        # icosphere_jitter.off) keep every tet within the bounds; the others pay a second pass. Deterministic.
        boundary = int(np.count_nonzero(np.bincount(np.asarray(mesh.boundary_faces, dtype=np.int64).ravel())))
        # With the rule, a pass's boundary splits are bounded by 8 times the boundary's points plus 2,000:
        # the converging corpus inputs add at most 3.3 times (anchor.off: 15,190 on 4,583) or, on small
        # boundaries, 284 (two_cubes_face.poly on 12); the cascades that end at min_length on the Schonhardt
        # prism and cad_ramp_5deg.off added 40,240 and 10,080 on 161 and 54 (19 s and 3 s) for the same
        # result.
        cap = min(max_steiner, 8 * boundary + 2000)
        rule, self.lazy_tried = self.lazy_tried, True
        first = self._refine_interior(mesh, budget, insert, limits, rule,
                                      cap if rule else min(max_steiner, boundary, 2000))
        grown, status, _, _, r = first
        if rule or status in ("converged", "budget_exhausted") or grown is mesh:
            return first[:4]
        self.inserted -= r.inserted  # that try's points are dropped
        self.boundary_points -= r.boundary_points
        self.boundary_rounds -= r.boundary_rounds
        self.refused_splits -= r.refused_splits
        return self._refine_interior(mesh, budget, insert, limits, True, cap)[:4]

    def _refine_interior(self, mesh: TetMesh, budget: int, insert: np.ndarray | None, limits: dict[str, Any],
                         rule: bool, boundary_budget: int) -> tuple[TetMesh, str, int, TetMesh | None, Any]:
        """One ``_core.refine_interior`` call for :meth:`interior_pass` (rule: with the small-angle rule's
        angle clauses; boundary_budget: boundary points to add at most); its returns and the core's result."""
        attrs, labels = self.region_labels(mesh)
        left = self.time_limit - (time.perf_counter() - self.started)
        angles = {} if rule else {"sharp_dihedral_degrees": 0.0, "small_apex_degrees": 0.0}
        r = _core.refine_interior(
            np.ascontiguousarray(mesh.points, dtype=np.float64),
            np.ascontiguousarray(mesh.tets, dtype=np.int64), labels,
            np.ascontiguousarray(mesh.boundary_faces, dtype=np.int64),
            np.ascontiguousarray(mesh.segments, dtype=np.int64).reshape(-1, 2),
            float(self.radius_edge or 0.0), self.volume_bounds_of(attrs), max(0, int(budget)), max(0.0, left),
            np.zeros((0, 3)) if insert is None else np.ascontiguousarray(insert, dtype=np.float64),
            np.ascontiguousarray(mesh.face_facets, dtype=np.int64), max(0, int(boundary_budget)),
            float(limits.get("min_length", 0.0)), **angles, left_alone=self.left_alone_rows(mesh),
            max_step_centers=self.step_centers)
        self.inserted += r.inserted
        self.boundary_points += r.boundary_points
        self.boundary_rounds += r.boundary_rounds
        self.refused_splits += r.refused_splits
        if r.status == "not_conforming" and not r.boundary_rounds:
            return mesh, r.status, 0, None, r
        regions = None if mesh.tet_regions is None else attrs[r.tet_labels]
        grown = self._with_boundary(replace(mesh, points=r.points[: r.certified_points],
                                            tets=np.asarray(r.tets, dtype=np.int64), tet_regions=regions),
                                    r.faces, r.face_facets, r.segments)
        self.small_angle = (grown, np.asarray(r.small_angle_rows, dtype=np.int64))
        elements = np.asarray(r.step_elements, dtype=np.int64).reshape(-1, 3)
        self.last_step = (grown, int(r.step_centers), elements)
        split = None
        if r.certified_points < len(r.points):
            split = self._with_boundary(replace(mesh, points=r.points, tets=np.zeros((0, 4), dtype=np.int64),
                                                tet_regions=None), r.split_faces, r.split_face_facets,
                                        r.split_segments)
        return grown, r.status, len(r.blocked_rows), split, r

    def _with_boundary(self, mesh: TetMesh, faces: Any, face_facets: Any, segments: Any) -> TetMesh:
        facets = np.asarray(face_facets, dtype=np.int64)
        return replace(mesh, boundary_faces=np.asarray(faces, dtype=np.int64), face_facets=facets,
                       face_markers=self.plc.markers_of_facets(facets),
                       segments=np.asarray(segments, dtype=np.int64).reshape(-1, 2))

    def small_angle_rows(self, mesh: TetMesh) -> np.ndarray:
        """The rows of mesh.tets the last interior pass left alone near small input angles, when mesh is
        that pass's mesh; else none."""
        grown, rows = self.small_angle
        return rows if grown is mesh else np.zeros(0, dtype=np.int64)

    def bad_tets(self, mesh: TetMesh) -> tuple[np.ndarray, np.ndarray]:
        """Rows of mesh.tets over a bound, most skewed first, and their circumcenters (floating point)."""
        tets = np.asarray(mesh.tets, dtype=np.int64).reshape(-1, 4)
        centers, radius, volume = tet_circumspheres(mesh.points, tets)
        ratio = radius / shortest_edges(mesh.points, tets)
        over = volume > self.volume_bounds(mesh)
        if self.radius_edge is not None:
            over |= ratio > self.radius_edge
        bad = np.flatnonzero(over)
        bad = bad[np.argsort(-ratio[bad], kind="stable")]
        return bad, centers[bad]

    def centers_for_repair(self, mesh: TetMesh, surface: PLC) -> np.ndarray:
        """Points (k, 3) for the boundary repair to add where the mesh's own Delaunay tetrahedralization does
        not hold its boundary (cospherical points, e.g. a cube's squares): the circumcenters of an independent
        set of the tets over a bound (:meth:`independent_centers`) that lie in no closed diametral sphere, and
        for the others a point strictly inside the tet (:meth:`stand_ins`), which the repair sees as an
        encroaching point when it lies in a closed diametral sphere (it splits what that point encroaches)."""
        rows, centers = self.independent_centers(mesh, *self.bad_tets(mesh))
        on = self.closed_hits(surface, centers)
        triggers, free = self.stand_ins(mesh, rows[on], centers[on], surface)
        return np.concatenate([centers[~on], free, triggers])

    @staticmethod
    def independent_centers(mesh: TetMesh, tets: np.ndarray,
                            centers: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The rows (k,) and circumcenters (k, 3) of rows `tets` (in order) taken one by one as Bowyer-Watson
        would still see their tets: a center is skipped when a center taken before it lies inside its tet's
        circumsphere. Each kept center is then at least its tet's circumradius from every point: the spacing
        the termination argument of refine_quality3d needs."""
        if not len(tets):
            return tets, np.zeros((0, 3))
        radius = tet_circumspheres(mesh.points, np.asarray(mesh.tets, dtype=np.int64)[tets])[1]
        tree = cKDTree(centers)
        taken = np.zeros(len(centers), dtype=bool)
        for i in range(len(centers)):
            if not taken[tree.query_ball_point(centers[i], radius[i])].any():
                taken[i] = True
        return tets[taken], centers[taken]

    def stand_ins(self, mesh: TetMesh, tets: np.ndarray, centers: np.ndarray,
                  surface: PLC) -> tuple[np.ndarray, np.ndarray]:
        """For the rows `tets` whose circumcenters (`centers`) lie in a closed diametral sphere: points that
        stand for them, strictly inside the tet (exact orient3d; so in the domain and on no facet or segment,
        where a circumcenter can lie): the first of centroid + (center - centroid) 2^-k, k = 1..8, inside the
        tet. Returns (triggers: those in a closed diametral sphere, for the boundary repair to split what they
        encroach; free: those in none, inserted instead of the center). Floating-point points, exact tests."""
        tets = np.asarray(mesh.tets, dtype=np.int64)[tets]
        centroid = mesh.points[tets].mean(axis=1)
        centers = np.where(np.isfinite(centers).all(axis=1)[:, None], centers, centroid)  # a sliver's is inf
        found = np.zeros(len(tets), dtype=bool)
        out = np.zeros((len(tets), 3))
        faces = np.array([[1, 2, 3], [0, 3, 2], [0, 1, 3], [0, 2, 1]])  # outward faces of a positive tet
        for k in range(1, 9):
            p = centroid + (centers - centroid) * 2.0**-k
            points = np.concatenate([mesh.points, p])
            quads = np.column_stack([tets[:, faces].reshape(-1, 3),
                                     np.repeat(len(mesh.points) + np.arange(len(p)), 4)])
            # p is strictly inside iff it is strictly on the inner side of every face
            new = ~found & (_core.plc_orient3d(points, quads).reshape(-1, 4) < 0).all(axis=1)
            out[new], found[new] = p[new], True
        out = out[found]
        hit = self.closed_hits(surface, out)
        return out[hit], out[~hit]
