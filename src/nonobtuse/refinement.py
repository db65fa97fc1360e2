"""Nonobtuse boundary refinement: the fewest Steiner points on constraint edges so that every triangle of the
constrained Delaunay triangulation is nonobtuse at the angle opposite each constrained edge it has (boundary,
interface or dangling segment)."""

from __future__ import annotations

import gc
from dataclasses import dataclass, field
from typing import Any, overload

import numpy as np

from nonobtuse import _core
from nonobtuse.domain import Domain, kept_triangulation
from nonobtuse.errors import InvalidInputError
from nonobtuse.mesh import Mesh
from nonobtuse.triangulation import mesh_of_core
from nonobtuse.validate import ensure_validated

STRATEGIES = ("greedy", "project-flip", "projection")
CONVERGED, BUDGET_EXHAUSTED, STALLED = "converged", "budget_exhausted", "stalled"


@dataclass
class RefineResult:
    """What :func:`refine` returns.

    mesh:   the constrained Delaunay triangulation of the refined domain (input points first, then the
            Steiner points); ``mesh.stats`` is ``stats``.
    stats:  ``status``, ``strategy``, ``steiner_points`` (int), ``lower_bound`` (int), ``optimal`` (True,
            False or None when unknown), ``seconds`` (float), ``obtuse_boundary_sides`` (int, the exact
            certificate of ``mesh``: constraint sides whose triangle is obtuse opposite them, 0 when
            converged), ``max_steiner`` (int, the budget used), ``max_steiner_offset`` (float: the largest
            distance of a Steiner point off its input segment over the segment's length; 0 when every point
            is exactly on its segment), ``edges``: one dict per input boundary edge
            ``{"edge": [a, b], "steiner_points": k, "lower_bound": l}`` (a, b input point indices, the
            domain on the left of a -> b; an interface or dangling segment, with the domain on both sides,
            once as a < b), ``diagnosis``: ``junctions`` (at most 10 dicts ``vertex, constraints,
            min_angle_degrees, steiner_points``: the input vertices where constraints meet that drew the most
            Steiner points, each point counted at the nearer end of its input edge), ``angles`` (at most 10
            dicts ``vertex, edge, neighbour, degrees, steiner_points``: the input angle between ``edge`` and
            its closest constraint ``neighbour`` at ``vertex``), ``initial_violations`` (violated subsegments
            that started a cascade), ``propagation_depth`` (the most distinct input edges one initial
            violation put Steiner points on) and ``propagation_splits`` (the most Steiner points it caused);
            propagation is tracked by the greedy strategy only.
    status: ``"converged"``, ``"budget_exhausted"`` or ``"stalled"`` (budget left, but a violated side
            admits no double split point passing the exact checks); ``mesh`` is then the partial result.
    """

    mesh: Mesh
    stats: dict[str, Any] = field(default_factory=dict)
    status: str = CONVERGED

    @property
    def converged(self) -> bool:
        return self.status == CONVERGED


def _edge_stats(rows: np.ndarray) -> list[dict[str, Any]]:
    """One dict per input edge (a, b, steiner_points, lower_bound). A polygon of a million vertices makes a
    million small containers: the cyclic collector, triggered by their allocation again and again, took four
    fifths of the time; none of them can be in a cycle, so it is paused meanwhile."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        return [{"edge": [a, b], "steiner_points": k, "lower_bound": lb} for a, b, k, lb in rows.tolist()]
    finally:
        if enabled:
            gc.enable()


def default_steiner_budget(n_points: int) -> int:
    """The Steiner budget :func:`refine` uses when ``max_steiner`` is None, for ``n_points`` input points: the
    core's rule (``default_steiner_budget`` in ``cpp/include/nonobtuse/refine2d.h``, which says why)."""
    return int(_core.default_steiner_budget(n_points))


def _diagnosis(g: _core.Refine2DDiagnosis) -> dict[str, Any]:
    """The ``stats["diagnosis"]`` dict (see :class:`RefineResult`) of the core's diagnosis."""
    return {
        "junctions": [{"vertex": j.vertex, "constraints": j.constraints,
                       "min_angle_degrees": j.min_angle_degrees, "steiner_points": j.steiner_points}
                      for j in g.junctions],
        "angles": [{"vertex": a.vertex, "edge": (a.vertex, a.a), "neighbour": (a.vertex, a.b),
                    "degrees": a.degrees, "steiner_points": a.steiner_points} for a in g.angles],
        "initial_violations": g.initial_violations,
        "propagation_depth": g.propagation_depth,
        "propagation_splits": g.propagation_splits,
    }


@overload
def refine(
    domain: Domain, strategy: str = ..., max_steiner: int | None = ..., threads: int = ...
) -> RefineResult: ...
@overload
def refine(
    domain: dict[str, Any], strategy: str = ..., max_steiner: int | None = ..., threads: int = ...
) -> dict[str, Any]: ...
def refine(
    domain: Domain | dict[str, Any],
    strategy: str = "greedy",
    max_steiner: int | None = None,
    threads: int = 2,
) -> RefineResult | dict[str, Any]:
    """Adds Steiner points on the constraint edges of ``domain`` until every triangle of its constrained
    Delaunay triangulation is nonobtuse opposite each constrained edge it has (boundary, interface or
    dangling segment).

    domain:      a :class:`~nonobtuse.domain.Domain`, validated once here unless it already is
                 (``Domain.validated``; ``domain`` is not modified): a PSLG with closed boundary loops (or
                 ``convex_hull=True`` for point sets: the hull edges are the boundary), holes, interior
                 interfaces meeting at junctions, dangling segments, isolated points, region attributes,
                 point and segment markers (carried to the mesh by Triangle's rules, see
                 :mod:`nonobtuse.markers`).
                 Or a ``triangle`` package input dict (:mod:`nonobtuse.triangle_dict`), validated here; the
                 result is then a dict in ``triangle.triangulate``'s output convention, plus ``stats``.
                 Both sides of every interior constraint are refined, each nonobtuse on its own (each side
                 carries its own conductivity); acute junctions get concentric power-of-two shells.
    strategy:    ``"greedy"`` (sensitive Greedy-Refine: the longest empty subsegment from one end, never
                 inside another subsegment's diametral disk; optimal for one edge and for convex polygons),
                 ``"project-flip"`` or ``"projection"`` (the paper's baselines).
    max_steiner: Steiner budget; None: :func:`default_steiner_budget` of the number of input points
                 (``stats["max_steiner"]`` is the budget used). When it is spent the partial mesh is
                 returned with status ``"budget_exhausted"``.
    threads:     1, or 2 and more: the passes over the whole mesh of large inputs (the lower bound, the
                 certificate) run on two threads. The result is the same for any value.

    Guarantees: Steiner points lie on constraint subsegments (exactly on the line when a double point there
    exists, else a few ulps off it); the returned mesh is checked exactly on every side of every constraint
    (``stats["obtuse_boundary_sides"]`` counts the obtuse sides: 0 whenever the status is
    ``"converged"``). ``lower_bound`` is the sum over input constraint edges of the single-edge greedy count
    against the input vertices each subsegment sees (from both sides of an interface; exact visibility, so
    a vertex hidden behind a dangling segment does not count): no refinement placing Steiner points on the
    constraints uses fewer. ``optimal`` is True when
    the count equals the bound, or for the greedy strategy on a convex polygon without interior points
    (Theorem 3), None otherwise.
    Deterministic. Cost: O(n log n) to triangulate plus, per Steiner point, the triangles meeting the
    diametral disk being refined.
    Raises InvalidInputError for an unknown strategy, a negative budget, a thread count below 1 or a domain
    that fails validation (it says what and where).
    """
    if isinstance(domain, dict):
        from nonobtuse.triangle_dict import mesh_to_dict, validated_domain

        result = refine(validated_domain(domain), strategy, max_steiner, threads)
        return {**mesh_to_dict(result.mesh, domain), "stats": result.stats}
    if strategy not in STRATEGIES:
        raise InvalidInputError(f"unknown strategy {strategy!r}; choose one of {', '.join(STRATEGIES)}")
    if max_steiner is not None and (int(max_steiner) != max_steiner or not 0 <= max_steiner < 2**62):
        raise InvalidInputError(f"max_steiner must be an integer in [0, 2^62), got {max_steiner!r}")
    if isinstance(threads, bool) or int(threads) != threads or threads < 1:
        raise InvalidInputError(f"threads must be a positive integer, got {threads!r}")
    domain = ensure_validated(domain)
    r = _core.refine(
        domain.points,
        domain.segments,
        domain.holes,
        domain.regions,
        bool(domain.convex_hull),
        strategy,
        -1 if max_steiner is None else int(max_steiner),
        min(int(threads), 2),
        kept_triangulation(domain),
    )
    stats: dict[str, Any] = {
        "status": r.status,
        "strategy": strategy,
        "steiner_points": r.steiner_points,
        "max_steiner": r.max_steiner,
        "lower_bound": r.lower_bound,
        "optimal": r.optimal,
        "seconds": r.seconds,
        "obtuse_boundary_sides": r.obtuse_boundary_sides,
        "max_steiner_offset": r.max_steiner_offset,
        "edges": _edge_stats(r.edges),
        "diagnosis": _diagnosis(r.diagnosis),
    }
    regions = r.mesh.triangle_region if len(domain.regions) else None
    mesh = mesh_of_core(r.mesh, domain, regions, stats)
    return RefineResult(mesh=mesh, stats=stats, status=r.status)
