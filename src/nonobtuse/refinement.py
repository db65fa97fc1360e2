"""Nonobtuse boundary refinement: the fewest Steiner points on constraint edges so that every triangle of the
constrained Delaunay triangulation is nonobtuse at the angle opposite each constrained edge it has (boundary,
interface or dangling segment)."""

from __future__ import annotations

import gc
import math
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, Union, overload

import numpy as np

from nonobtuse import _core
from nonobtuse.domain import Domain, kept_triangulation
from nonobtuse.errors import InvalidInputError
from nonobtuse.mesh import Mesh
from nonobtuse.triangulation import mesh_of_core
from nonobtuse.validate import ensure_validated, require_points_in_domain

STRATEGIES = ("greedy", "project-flip", "projection")
CONVERGED, BUDGET_EXHAUSTED, STALLED = "converged", "budget_exhausted", "stalled"
QUALITY_BOUNDARIES = ("best", "midpoints", "minimal")  # refine's quality_boundary
MAX_MIN_ANGLE = 40.0  # degrees: off-centers terminate up to about 34; above 40 it would run to the budget

# size=: a callable (x, y) -> the largest area at that point, {region attribute: largest area}, or "regions"
Size = Union[Callable[[float, float], float], Mapping[float, float], str]


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
            is exactly on its segment), ``edges``: one dict per input boundary edge (an :class:`EdgeStats`
            sequence, each dict made on access)
            ``{"edge": [a, b], "steiner_points": k, "lower_bound": l}`` (a, b input point indices, the
            domain on the left of a -> b; an interface or dangling segment, with the domain on both sides,
            once as a < b), ``diagnosis``: ``junctions`` (at most 10 dicts ``vertex, constraints,
            min_angle_degrees, steiner_points``: the input vertices where constraints meet that drew the most
            Steiner points, each point counted at the nearer end of its input edge), ``angles`` (at most 10
            dicts ``vertex, edge, neighbour, degrees, steiner_points``: the input angle between ``edge`` and
            its closest constraint ``neighbour`` at ``vertex``), ``initial_violations`` (violated subsegments
            that started a cascade), ``propagation_depth`` (the most distinct input edges one initial
            violation put Steiner points on) and ``propagation_splits`` (the most Steiner points it caused);
            propagation is tracked by the greedy strategy only; ``stop_reason`` (str: why it stopped, in
            :func:`~nonobtuse.mesh3d.refine_gabriel`'s words: ``"every boundary side has a nonobtuse apex"``
            (with a quality option ``"... and every triangle meets the quality bounds outside small input
            angles"``), ``"max_steiner (N) reached"``, ``"max_interior (N) reached"``, or what is left that no
            split fixes when stalled). ``interior_points`` (int: Steiner points
            inside the domain, 0 unless a quality option is given; ``steiner_points`` counts those on
            constraints), ``quality``: None, or with a quality option the dict of :func:`_quality_stats`.
    status: ``"converged"``, ``"budget_exhausted"`` or ``"stalled"`` (budget left, but a violated side
            admits no double split point passing the exact checks); ``mesh`` is then the partial result.
            With a quality option, ``"converged"`` also needs every triangle good outside small-input-angle
            regions (``budget_exhausted`` when a budget stopped it, ``stalled`` otherwise).
    """

    mesh: Mesh
    stats: dict[str, Any] = field(default_factory=dict)
    status: str = CONVERGED

    @property
    def converged(self) -> bool:
        return self.status == CONVERGED


class EdgeStats(Sequence[dict[str, Any]]):
    """``stats["edges"]``: per input edge ``{"edge": [a, b], "steiner_points": k, "lower_bound": l}``, made on
    access from the (m, 4) int64 rows the core returns, so that only a caller who reads them pays for them (a
    polygon of a million vertices makes a million small containers: 1.5 s and 380 MB, half the time and memory
    of the whole refinement when no Steiner point is needed). A read-only sequence that compares equal to the
    list of the same dicts; ``list()`` or JSON (``json.dumps(..., default=list)``) gives them all."""

    def __init__(self, rows: np.ndarray) -> None:
        self._rows = rows

    def __len__(self) -> int:
        return len(self._rows)

    @overload
    def __getitem__(self, i: int) -> dict[str, Any]: ...
    @overload
    def __getitem__(self, i: slice) -> list[dict[str, Any]]: ...
    def __getitem__(self, i: int | slice) -> dict[str, Any] | list[dict[str, Any]]:
        if isinstance(i, slice):
            return _edge_dicts(self._rows[i])
        a, b, k, lb = self._rows[i].tolist()
        return {"edge": [a, b], "steiner_points": k, "lower_bound": lb}

    def __iter__(self) -> Iterator[dict[str, Any]]:
        return iter(_edge_dicts(self._rows))

    def __eq__(self, other: object) -> bool:
        if isinstance(other, EdgeStats):
            return np.array_equal(self._rows, other._rows)
        return isinstance(other, Sequence) and list(self) == list(other)

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        return f"EdgeStats({len(self)} edges)"


def _edge_dicts(rows: np.ndarray) -> list[dict[str, Any]]:
    """One dict per row (a, b, steiner_points, lower_bound). A million small containers: the cyclic collector,
    triggered by their allocation again and again, took four fifths of the time; none of them can be in a
    cycle, so it is paused meanwhile."""
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
        "stop_reason": g.stop_reason,
    }


def _quality_stats(q: _core.Quality2DStats, min_angle: float | None) -> dict[str, Any]:
    """``stats["quality"]``: ``min_angle`` (the bound asked, degrees, or None), ``interior_points``,
    ``interior_budget``, ``boundary_splits`` (boundary Steiner points the quality refinement placed: with the
    greedy strategy all of them, since it then also refines the boundary), ``boundary_points_removed``
    (boundary Steiner points taken back after convergence, where the mesh keeps the certificate and the bounds
    without them; ``steiner_points`` counts what is left),
    ``triangles``, ``bad_triangles`` (left bad outside small-input-angle regions: 0 when converged),
    ``small_angle_triangles`` (skinny triangles left alone near input angles below 60 degrees),
    ``min_angle_degrees`` (every triangle) and ``min_angle_outside_small_angles_degrees`` (floats, computed in
    floating point; 180 when there is no triangle), ``max_area`` (float, the largest triangle's);
    :func:`refine` adds ``boundary`` (``"midpoints"`` or ``"minimal"``: see its ``quality_boundary``)."""
    return {
        "min_angle": min_angle,
        "interior_points": q.interior_points,
        "interior_budget": q.interior_budget,
        "boundary_splits": q.boundary_splits,
        "boundary_points_removed": q.boundary_points_removed,
        "triangles": q.triangles,
        "bad_triangles": q.bad_triangles,
        "small_angle_triangles": q.small_angle_triangles,
        "min_angle_degrees": q.min_angle_degrees,
        "min_angle_outside_small_angles_degrees": q.min_angle_outside_small_angles_degrees,
        "max_area": q.max_area,
    }


def _fewer_boundary_points(other: _core.Refine2DResult, first: _core.Refine2DResult) -> bool:
    """Whether the run with the minimal boundary first (``other``) is kept instead of the first (Triangle's
    midpoints and shells): it converged where the first did not, or both converged and it has strictly fewer
    boundary Steiner points and no more vertices (so the first's vertex count, within 1.1x Triangle's on
    bench_quality2d, stays a bound). Measured on bench_quality2d (2026-12-03): kept on cdt_ditch (2 boundary
    points against 3, Triangle 3; 13 vertices against 14) at 25 and 30 degrees; on spiral.node at 25 it ties
    now that unneeded boundary points are taken back (4 both; it was kept at 4 against 5 before); elsewhere
    its short pieces drew more points (the demo section: 1680 against 1228)."""
    if other.status != CONVERGED or first.status != CONVERGED:
        return other.status == CONVERGED and first.status != CONVERGED
    return (other.steiner_points < first.steiner_points
            and len(other.mesh.points) <= len(first.mesh.points))


def _run_core(domain: Domain, strategy: str, max_steiner: int, threads: int, quality: _core.Quality2DOptions,
              quality_boundary: str) -> tuple[_core.Refine2DResult, float, str]:
    """The core's refinement of the validated ``domain``, with :func:`refine`'s ``quality_boundary`` rule (one
    run, or two and the one :func:`_fewer_boundary_points` prefers): the result, the seconds of every run, and
    the boundary mode of the result (``"midpoints"`` or ``"minimal"``). After a converged first run the second
    gets budgets just above what it could be kept with (fewer boundary points than the first's, at most its
    vertices), so it stops early where its short pieces draw a cascade (the demo section at 30 degrees: 6,038
    vertices unbounded); a budget it reaches makes it ``budget_exhausted``, never kept."""
    def run(triangulation: Any, steiner_budget: int) -> _core.Refine2DResult:
        d = domain
        return _core.refine(d.points, d.segments, d.holes, d.regions, bool(d.convex_hull), strategy,
                            steiner_budget, threads, quality, triangulation)

    quality.minimal_boundary_first = quality_boundary == "minimal"
    r = run(kept_triangulation(domain), max_steiner)
    seconds, boundary = r.seconds, "minimal" if quality_boundary == "minimal" else "midpoints"
    if quality.enabled() and strategy == "greedy" and quality_boundary == "best" and r.steiner_points > 0:
        quality.minimal_boundary_first = True
        steiner_budget = max_steiner
        if r.status == CONVERGED:  # kept only with at most r.steiner_points - 1 and r's vertices
            steiner_budget = r.steiner_points
            limit = r.quality.interior_points + r.steiner_points + 1
            quality.max_interior = min(r.quality.interior_budget, limit)
        other = run(None, steiner_budget)
        seconds += other.seconds
        if _fewer_boundary_points(other, r):
            r, boundary = other, "minimal"
    return r, seconds, boundary


def _positive(value: Any, name: str) -> float:
    """``value`` as a positive finite float, else InvalidInputError naming ``name``."""
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise InvalidInputError(f"{name} must be a positive number, got {value!r}") from None
    if not (v > 0 and math.isfinite(v)):
        raise InvalidInputError(f"{name} must be a positive finite number, got {value!r}")
    return v


def region_sizes(domain: Domain) -> dict[float, float]:
    """``{attribute: largest area}`` of the domain's regions that give one (``Domain.region_max_areas``: a
    .poly region's fourth number, a triangle dict's ``regions`` fourth column; Triangle's ``-a`` without a
    number).
    Areas <= 0 or NaN mean none, as in Triangle; regions sharing an attribute get the smallest of their areas.
    Raises InvalidInputError when no region gives an area."""
    out: dict[float, float] = {}
    areas = domain.region_max_areas if domain.region_max_areas is not None else np.zeros(0)
    for (_, _, attribute), area in zip(domain.regions.tolist(), areas.tolist()):
        if area > 0 and math.isfinite(area):
            out[attribute] = min(area, out.get(attribute, math.inf))
    if not out:
        raise InvalidInputError(f"{domain.source}: size='regions', but no region of the domain gives a "
                                "maximum area (a .poly region line's fourth number)")
    return out


def quality_options(
    min_angle: float | None = None,
    max_area: float | None = None,
    size: Size | None = None,
    max_interior: int | None = None,
) -> _core.Quality2DOptions:
    """The core's interior-quality options of :func:`refine`'s arguments (see there), checked: min_angle in
    (0, 40] degrees, max_area positive, size a callable or a mapping of region attributes to positive areas,
    max_interior an integer in [0, 2^62). Raises InvalidInputError naming the option."""
    o = _core.Quality2DOptions()
    if min_angle is not None:
        v = _positive(min_angle, "min_angle")
        if v > MAX_MIN_ANGLE:
            raise InvalidInputError(f"min_angle must be at most {MAX_MIN_ANGLE:g} degrees (Delaunay "
                                    f"refinement does not terminate much above 34), got {min_angle!r}")
        o.min_angle_degrees = v
    if max_area is not None:
        o.max_area = _positive(max_area, "max_area")
    if callable(size):
        o.set_max_area_at(size)
    elif isinstance(size, Mapping):
        o.region_max_area = [(float(a), _positive(v, f"size[{a!r}]")) for a, v in size.items()]
    elif size is not None:
        raise InvalidInputError(f"size must be a callable (x, y) -> area or a mapping region attribute -> "
                                f"area, got {type(size).__name__}")
    if max_interior is not None:
        n = max_interior
        if isinstance(n, bool) or int(n) != n or not 0 <= n < 2**62:
            raise InvalidInputError(f"max_interior must be an integer in [0, 2^62), got {max_interior!r}")
        o.max_interior = int(max_interior)
    return o


@overload
def refine(
    domain: Domain, strategy: str = ..., max_steiner: int | None = ..., threads: int = ..., *,
    min_angle: float | None = ..., max_area: float | None = ..., size: Size | None = ...,
    max_interior: int | None = ..., quality_boundary: str = ...,
) -> RefineResult: ...
@overload
def refine(
    domain: dict[str, Any], strategy: str = ..., max_steiner: int | None = ..., threads: int = ..., *,
    min_angle: float | None = ..., max_area: float | None = ..., size: Size | None = ...,
    max_interior: int | None = ..., quality_boundary: str = ...,
) -> dict[str, Any]: ...
def refine(
    domain: Domain | dict[str, Any],
    strategy: str = "greedy",
    max_steiner: int | None = None,
    threads: int = 2,
    *,
    min_angle: float | None = None,
    max_area: float | None = None,
    size: Size | None = None,
    max_interior: int | None = None,
    quality_boundary: str = "best",
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
    min_angle, max_area, size, max_interior: interior quality, off by default (Triangle's ``-q``/``-a``).
                 With the greedy strategy the boundary is then refined as Triangle does rather than
                 minimally: every side with an obtuse apex split at its midpoint (a power-of-two shell at an
                 acute input angle; the greedy rule only where no such point passes the exact checks), since
                 the minimal boundary's short pieces would force the interior to match them (the other
                 strategies refine the boundary their way first). Then Delaunay refinement (Ruppert, Chew;
                 Triangle's off-centers)
                 inserts interior points into triangles with an angle below ``min_angle`` degrees (at most
                 40; Ruppert's proof covers 20.7, off-centers terminate in practice up to about 34) or an area
                 above ``max_area``, above ``size[attribute]`` in a region (``size`` a mapping: region
                 attribute -> largest area; ``"regions"``: the areas the domain's regions give, see
                 :func:`region_sizes`) or above ``size(x, y)`` at the centroid (``size`` a callable
                 returning a positive float). A point inside a constraint subsegment's closed diametral disk
                 is never inserted: the subsegment is split (midpoint, or a power-of-two shell at an acute
                 input angle), and so is every boundary side a split leaves obtuse, so the certificate still
                 holds.
                 Near input angles below 60 degrees skinny triangles are left alone, as Triangle does
                 (counted in ``stats["quality"]["small_angle_triangles"]``). ``max_interior`` caps the
                 interior points (None: ``10 n + 100000 + 4 area / smallest fixed area limit``).
    quality_boundary: with a quality option and the greedy strategy, how the boundary is refined:
                 ``"midpoints"`` (Triangle's midpoints and shells, above), ``"minimal"`` (the paper's minimal
                 greedy boundary first, then the quality refinement splits what the interior encroaches), or
                 ``"best"`` (default): midpoints, then, when that placed any boundary point, minimal too, and
                 the minimal run is kept when it converged with strictly fewer boundary points and no more
                 vertices (or converged where the other did not). Its second run is capped by the
                 first's counts; measured CPU time against ``"midpoints"``: 2.0x to 2.4x (la.poly,
                 10,000-vertex polygon and star), 3.8x on the small demo section (0.040 s against 0.011 s).
                 ``stats["quality"]["boundary"]`` says which was returned.

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
    With a quality option the cost adds, per interior point, its Delaunay cavity and the walk to it.
    Raises InvalidInputError for an unknown strategy, a negative budget, a thread count below 1, a quality
    option out of range (or a size function returning a value that is not a positive finite number), a
    domain that fails validation, or input points outside the domain (in the exterior or a hole; it says what
    and where).
    """
    if isinstance(domain, dict):
        from nonobtuse.triangle_dict import mesh_to_dict, validated_domain

        result = refine(validated_domain(domain), strategy, max_steiner, threads, min_angle=min_angle,
                        max_area=max_area, size=size, max_interior=max_interior,
                        quality_boundary=quality_boundary)
        return {**mesh_to_dict(result.mesh, domain), "stats": result.stats}
    if strategy not in STRATEGIES:
        raise InvalidInputError(f"unknown strategy {strategy!r}; choose one of {', '.join(STRATEGIES)}")
    if max_steiner is not None and (int(max_steiner) != max_steiner or not 0 <= max_steiner < 2**62):
        raise InvalidInputError(f"max_steiner must be an integer in [0, 2^62), got {max_steiner!r}")
    if isinstance(threads, bool) or int(threads) != threads or threads < 1:
        raise InvalidInputError(f"threads must be a positive integer, got {threads!r}")
    if quality_boundary not in QUALITY_BOUNDARIES:
        raise InvalidInputError(f"unknown quality_boundary {quality_boundary!r}; choose one of "
                                f"{', '.join(QUALITY_BOUNDARIES)}")
    if isinstance(size, str) and size != "regions":
        raise InvalidInputError(f"size must be a callable, a mapping or 'regions', got {size!r}")
    quality = quality_options(min_angle, max_area, None if isinstance(size, str) else size, max_interior)
    domain = ensure_validated(domain)
    if size == "regions":
        quality.region_max_area = list(region_sizes(domain).items())
    r, seconds, boundary = _run_core(domain, strategy, -1 if max_steiner is None else int(max_steiner),
                                     min(int(threads), 2), quality, quality_boundary)
    require_points_in_domain(domain, r.mesh.triangles)
    stats: dict[str, Any] = {
        "status": r.status,
        "strategy": strategy,
        "steiner_points": r.steiner_points,
        "max_steiner": r.max_steiner,
        "lower_bound": r.lower_bound,
        "optimal": r.optimal,
        "seconds": seconds,
        "obtuse_boundary_sides": r.obtuse_boundary_sides,
        "max_steiner_offset": r.max_steiner_offset,
        "edges": EdgeStats(r.edges),
        "diagnosis": _diagnosis(r.diagnosis),
        "interior_points": r.quality.interior_points,
        "quality": ({**_quality_stats(r.quality, min_angle), "boundary": boundary} if quality.enabled()
                    else None),
    }
    regions = r.mesh.triangle_region if len(domain.regions) else None
    mesh = mesh_of_core(r.mesh, domain, regions, stats)
    return RefineResult(mesh=mesh, stats=stats, status=r.status)
