"""Fuzzing the 2D and 3D refinements with random valid and near-degenerate inputs (hypothesis).

Every run must end with a status (an InvalidInputError is allowed only for an input the validation refuses),
and every converged output is re-checked here, independently of the C++ certificate, in exact arithmetic:

- 2D (:func:`check_refine_2d`): no constraint side (boundary or either side of an interface) is obtuse and
  every unconstrained edge is locally Delaunay (the rational oracle of ``tests/refine_helpers.py``), and the
  mesh starts with the input points, unchanged.
- 3D (:func:`check_refine_3d`): no mesh vertex lies strictly inside the diametral sphere of any boundary
  subfacet or subsegment (:func:`gabriel_violations`, integer arithmetic on the stored doubles).
- 3D quality (:func:`check_quality_3d`, ``refine_quality3d`` with a volume bound and maybe a radius-edge
  bound, from the input boundary): the same exact re-check, the input points kept, every tet not left alone
  near small angles within the bounds (numpy), and the tets fill the volume the input encloses (exact, by the
  divergence theorem; with internal facets, the volume of ``refine_gabriel``'s mesh).

Inputs (:func:`domains`, :func:`plcs`): star-shaped polygons with near-collinear vertices, tiny angles, points
a relative 1e-3..1e-15 off a segment, interior points, a hole or radial interfaces; stacks of thin layers
(thickness down to 1e-7 of the width) with bent interfaces; each scaled by 1e-8..1e9 and shifted up to 1e9.
3D: convex hulls of 4..8 random points (flat ones included), scaled and shifted, and the termination-map
families (``plc_families.py``) at random angles.

Short mode: ``tests/test_fuzz.py`` (derandomized, a fixed number of examples). Long mode, for manual runs:
``python -m experiments.fuzz --minutes N [--seed S] [--dims 2,3]``: fresh seeds until the time is up; every
failure is printed with its falsifying input (hypothesis's shrunk example) and the run exits 1.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from fractions import Fraction
from pathlib import Path

import numpy as np
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import seed as hypothesis_seed
from hypothesis import strategies as st

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "tests"), str(ROOT)]  # the oracle; experiments.plc_families

import nonobtuse  # noqa: E402
from experiments.plc_families import FAMILIES, make_plc  # noqa: E402
from nonobtuse import Domain, InvalidInputError  # noqa: E402
from nonobtuse.io.raw3d import Facet, RawInput  # noqa: E402
from nonobtuse.mesh3d import PLC, refine_gabriel  # noqa: E402
from nonobtuse.mesh3d.load import build_plc  # noqa: E402
from nonobtuse.mesh3d.quality3d import refine_quality3d  # noqa: E402
from nonobtuse.refinement import STRATEGIES  # noqa: E402
from nonobtuse.validate import validate_domain  # noqa: E402
from refine_helpers import non_delaunay_edges, obtuse_constraint_sides  # noqa: E402

STATUSES_2D = ("converged", "budget_exhausted", "stalled")
STATUSES_3D = ("converged", "budget_exhausted", "min_length_reached", "stalled")
MAX_STEINER_2D = 3000
MAX_STEINER_3D, TIME_LIMIT_3D = 3000, 10.0
QUALITY_STATUSES_3D = ("converged", "quality_blocked", "budget_exhausted", "min_length_reached", "stalled")
MAX_POINTS_QUALITY_3D = 1000  # interior points: the exact re-check is in big integers
# A hang is a failure; one example takes milliseconds (2D) to seconds (3D), on a machine shared with others.
DEADLINE_MS = 60_000

# ---- 2D inputs ---------------------------------------------------------------------------------------------

exponents = st.integers(3, 15)


@st.composite
def star_polygon(draw) -> np.ndarray:
    """n >= 6 vertices at angles 2 pi (k + u_k) / n (u_k in [0, 1): gaps below 2 pi / 3, so the polygon is
    simple and the disk of radius r_min / 2 around the origin is inside), radii in [0.5, 1.5]; the jitter
    may put two vertices at a tiny angle apart."""
    n = draw(st.integers(6, 12))
    u = draw(st.lists(st.one_of(st.floats(0, 1, exclude_max=True), st.just(1 - 1e-9), st.just(0.0)),
                      min_size=n, max_size=n))
    r = draw(st.lists(st.floats(0.5, 1.5), min_size=n, max_size=n))
    a = 2 * math.pi * (np.arange(n) + np.array(u)) / n
    return np.c_[np.array(r) * np.cos(a), np.array(r) * np.sin(a)]


@st.composite
def near_collinear(draw, loop: np.ndarray) -> np.ndarray:
    """``loop`` with some edges bent at a point near their midpoint, 10^-e of the edge length off the line
    (outward or inward: nearly collinear triples, a reflex vertex of angle nearly 180 degrees)."""
    out = []
    for i in range(len(loop)):
        a, b = loop[i], loop[(i + 1) % len(loop)]
        out.append(a)
        if draw(st.booleans()):
            normal = np.array([b[1] - a[1], a[0] - b[0]])
            out.append((a + b) / 2 + draw(st.sampled_from((-1, 1))) * 10.0 ** -draw(exponents) * normal)
    return np.array(out)


def _loop(start: int, n: int) -> list[tuple[int, int]]:
    return [(start + i, start + (i + 1) % n) for i in range(n)]


@st.composite
def star_domain(draw) -> Domain:
    """A star polygon (maybe with near-collinear vertices), interior points (some 10^-e inside an edge) and
    either a small square hole at the centre or radial interfaces from a centre point."""
    outer = draw(near_collinear(draw(star_polygon())))
    n = len(outer)
    pts, seg, holes = [*outer], _loop(0, n), []
    inner = 0.25 * float(np.min(np.hypot(outer[:, 0], outer[:, 1])))  # well inside the kernel disk
    feature = draw(st.sampled_from(("none", "hole", "interfaces")))
    if feature == "hole":
        h = inner * draw(st.floats(1e-6, 0.3))
        pts += [(-h, -h), (h, -h), (h, h), (-h, h)]
        seg += _loop(n, 4)
        holes.append((0.0, 0.0))
    elif feature == "interfaces":
        pts.append((0.0, 0.0))
        ends = draw(st.sets(st.integers(0, n - 1), min_size=1, max_size=min(4, n)))
        seg += [(n, e) for e in sorted(ends)]
    lo = 0.5 * inner if feature == "hole" else 0.0
    for _ in range(draw(st.integers(0, 5))):
        ang, rad = draw(st.floats(0, 2 * math.pi)), draw(st.floats(lo, inner))
        pts.append((rad * math.cos(ang), rad * math.sin(ang)))
    for _ in range(draw(st.integers(0, 2))):  # a point a relative 10^-e inside the middle of an edge
        i = draw(st.integers(0, n - 1))
        a, b = outer[i], outer[(i + 1) % n]
        inward = np.array([a[1] - b[1], b[0] - a[0]])  # the polygon is counter-clockwise
        pts.append(tuple((a + b) / 2 + 10.0 ** -draw(exponents) * inward))
    return Domain(np.array(pts, dtype=np.float64), np.array(seg, dtype=np.int64).reshape(-1, 2),
                  np.array(holes, dtype=np.float64).reshape(-1, 2))


@st.composite
def thin_layers(draw) -> Domain:
    """A unit-wide stack of 1..5 layers of thickness 10^-e (e in 0..7), its interfaces polylines through a
    few breakpoints bent by under a third of the thinner neighbouring layer."""
    t = [10.0 ** -draw(st.integers(0, 7)) * draw(st.floats(0.5, 1.0)) for _ in range(draw(st.integers(1, 5)))]
    levels = np.concatenate([[0.0], np.cumsum(t)])
    pts: list[tuple[float, float]] = []
    rows = []  # per level: indices of its points, left to right
    for i, y in enumerate(levels):
        xs = sorted(set(draw(st.lists(st.floats(0.01, 0.99), max_size=3))))
        room = min(t[max(i - 1, 0)], t[min(i, len(t) - 1)]) / 3
        bends = [0.0 if i in (0, len(t)) else draw(st.floats(-1, 1)) * room for _ in xs]
        row = [(0.0, y), *((x, y + b) for x, b in zip(xs, bends)), (1.0, y)]
        rows.append(list(range(len(pts), len(pts) + len(row))))
        pts += row
    seg = [(r[j], r[j + 1]) for r in rows for j in range(len(r) - 1)]
    seg += [(lo[end], hi[end]) for lo, hi in zip(rows, rows[1:]) for end in (0, -1)]  # the sides
    return Domain(np.array(pts, dtype=np.float64), np.array(seg, dtype=np.int64))


@st.composite
def placed(draw, domain: Domain) -> Domain:
    """``domain`` scaled by 10^k (k in -8..9), maybe rotated, and shifted by up to 1e9 (rounded: the
    result may be invalid, which validation must then say)."""
    s = 10.0 ** draw(st.integers(-8, 9))
    c, sn = (1.0, 0.0) if draw(st.booleans()) else (math.cos(a := draw(st.floats(0, 6.3))), math.sin(a))
    shift = np.array([draw(st.sampled_from((0.0, 1.0, 1e3, 1e6, 1e9))) * draw(st.sampled_from((-1, 1)))
                      for _ in range(2)])
    rot = np.array([[c, -sn], [sn, c]])
    move = lambda p: (p @ rot.T) * s + shift  # noqa: E731
    holes = move(domain.holes) if len(domain.holes) else domain.holes
    return Domain(move(domain.points), domain.segments, holes)


domains = st.one_of(star_domain(), thin_layers()).flatmap(placed)


def check_refine_2d(domain: Domain, strategy: str) -> str:
    """Validate and refine ``domain``; returns ``"invalid"`` (validation refuses it, or refine finds input
    points outside the domain) or the status. Raises AssertionError when the run ends otherwise than with a
    status, or a converged mesh fails the exact re-check."""
    try:
        d = validate_domain(domain)
        result = nonobtuse.refine(d, strategy=strategy, max_steiner=MAX_STEINER_2D)
    except InvalidInputError:
        return "invalid"
    assert result.status in STATUSES_2D, result.status
    m = result.mesh
    assert np.array_equal(m.points[: len(d.points)], d.points), "the input points moved"
    if result.status == "converged":
        assert result.stats["obtuse_boundary_sides"] == 0
        assert obtuse_constraint_sides(m) == 0, "converged, but an obtuse constraint side (exact)"
        assert non_delaunay_edges(m) == 0, "converged, but an unconstrained edge is not locally Delaunay"
    return result.status


# ---- 3D inputs ---------------------------------------------------------------------------------------------


@st.composite
def hull_plc(draw) -> PLC:
    """The convex hull of 4..8 random points (flattened by 10^-e in z with some probability), outward
    triangles, scaled by 10^k (k in -6..6) and shifted by up to 1e6."""
    from scipy.spatial import ConvexHull, QhullError

    n = draw(st.integers(4, 8))
    p = np.array(draw(st.lists(st.tuples(*[st.floats(-1, 1)] * 3), min_size=n, max_size=n)))
    if draw(st.booleans()):
        p[:, 2] *= 10.0 ** -draw(st.integers(1, 6))
    p = p * 10.0 ** draw(st.integers(-6, 6)) + draw(st.sampled_from((0.0, 1.0, 1e3, 1e6)))
    try:
        hull = ConvexHull(p)
    except QhullError:
        assume(False)
    keep = np.unique(hull.simplices)
    index = np.full(n, -1)
    index[keep] = np.arange(len(keep))
    faces = []
    for s, eq in zip(hull.simplices, hull.equations):
        a, b, c = p[s]
        faces.append(s if np.dot(np.cross(b - a, c - a), eq[:3]) > 0 else s[::-1])
    raw = RawInput(p[keep], [Facet([index[f]]) for f in faces], source="hull")
    try:
        return build_plc(raw, surface=True)
    except InvalidInputError:
        assume(False)


@st.composite
def family_plc(draw) -> PLC:
    """A termination-map family member at a random angle of 5..120 degrees (k = 3..6 where used)."""
    name = draw(st.sampled_from(sorted(FAMILIES)))
    k = draw(st.integers(3, 6)) if FAMILIES[name].uses_k else None
    theta = draw(st.floats(5, 120))
    assume(FAMILIES[name].accepts(theta, k))
    return make_plc(name, theta, k)


plcs = st.one_of(hull_plc(), family_plc())


def _integer_grid(points: np.ndarray) -> list[tuple[int, int, int]]:
    """The points as exact integers: every coordinate times the common power-of-two denominator."""
    fr = [[Fraction(float(x)) for x in p] for p in points]
    den = max((f.denominator for p in fr for f in p), default=1)
    return [tuple(int(f * den) for f in p) for p in fr]


def _sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def gabriel_violations(points: np.ndarray, faces: np.ndarray, segments: np.ndarray,
                       every_point: bool = False) -> int:
    """Boundary subfacets and subsegments with a vertex of ``points`` strictly inside their diametral sphere,
    decided exactly in integers. For a triangle a, b, c (u = b - a, v = c - a, n = u x v) the sphere's centre
    is a + w / (2 |n|^2) with w = (|u|^2 v - |v|^2 u) x n, so the power of p is
    (|p - a|^2 |n|^2 - (p - a).w) / |n|^2: p is inside iff |p - a|^2 |n|^2 < (p - a).w. For a segment a, b:
    (p - a).(p - b) < 0. The points tested for each sphere are those a k-d tree finds within its
    floating-point radius plus 1e-3 of it and the coordinates' rounding (:func:`_sphere_candidates`), every
    point for a triangle with an angle below 1e-8 radians, or with ``every_point``; the decision is the
    integer test. Cost: O(n log n + (f + k) m) big-integer operations for m candidates per sphere (testing
    every point took 447 s for 2,000 points and 4,000 faces shifted to 1e3)."""
    q = _integer_grid(points)
    pts = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    faces = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
    segments = np.asarray(segments, dtype=np.int64).reshape(-1, 2)
    candidates = ([range(len(q))] * (len(faces) + len(segments)) if every_point
                  else _sphere_candidates(pts, faces, segments))
    bad = 0
    for (a, b, c), near in zip(faces.tolist(), candidates):
        u, v = _sub(q[b], q[a]), _sub(q[c], q[a])
        n = _cross(u, v)
        nn = _dot(n, n)
        w = _cross(tuple(_dot(u, u) * v[i] - _dot(v, v) * u[i] for i in range(3)), n)
        bad += any(_dot(d := _sub(q[p], q[a]), d) * nn < _dot(d, w) for p in near)
    for (a, b), near in zip(segments.tolist(), candidates[len(faces):]):
        bad += any(_dot(_sub(q[p], q[a]), _sub(q[p], q[b])) < 0 for p in near)
    return bad


def _sphere_candidates(pts: np.ndarray, faces: np.ndarray, segments: np.ndarray) -> list:
    """Per face, then per segment, the indices of the points within its diametral sphere in floating point,
    widened by 1e-3 of the radius and 8 units in the last place of the largest coordinate; every point for a
    face with an angle below 1e-8 radians (its floating-point centre is not to be trusted)."""
    from scipy.spatial import cKDTree

    if not len(pts):
        return [[] for _ in range(len(faces) + len(segments))]
    a, b, c = (pts[faces[:, i]] for i in range(3))
    u, v = b - a, c - a
    n = np.cross(u, v)
    nn = np.einsum("ij,ij->i", n, n)
    uu, vv = np.einsum("ij,ij->i", u, u), np.einsum("ij,ij->i", v, v)
    w = np.cross(uu[:, None] * v - vv[:, None] * u, n)
    with np.errstate(divide="ignore", invalid="ignore"):
        offset = w / (2 * nn[:, None])
    flat = ~(nn > 1e-16 * uu * vv) | ~np.isfinite(offset).all(axis=1)  # sin^2 of the angle at a below 1e-16
    ww = np.einsum("ij,ij->i", u - v, u - v)
    flat |= ~(nn > 1e-16 * uu * ww) | ~(nn > 1e-16 * vv * ww)
    offset[flat] = 0.0  # those test every point
    centers = np.concatenate([a + offset, (pts[segments[:, 0]] + pts[segments[:, 1]]) / 2])
    radii = np.concatenate([np.linalg.norm(offset, axis=1),
                            np.linalg.norm(pts[segments[:, 1]] - pts[segments[:, 0]], axis=1) / 2])
    near = cKDTree(pts).query_ball_point(centers, radii * (1 + 1e-3) + 8 * np.spacing(np.abs(pts).max()))
    everything = list(range(len(pts)))
    return [everything if i < len(faces) and flat[i] else near[i] for i in range(len(centers))]


def check_refine_3d(plc: PLC) -> str:
    """Refine ``plc`` with hard limits; returns the status. Raises AssertionError when the run ends otherwise
    than with a status, or a converged mesh fails the exact re-check."""
    result = refine_gabriel(plc, max_steiner=MAX_STEINER_3D, time_limit=TIME_LIMIT_3D)
    assert result.status in STATUSES_3D, result.status
    m = result.mesh
    assert np.array_equal(m.points[: len(plc.points)], plc.points), "the input points moved"
    if result.status == "converged":
        assert result.stats["encroached_facets"] == 0 and result.stats["encroached_segments"] == 0
        assert gabriel_violations(m.points, m.boundary_faces, m.segments) == 0, "converged, not Gabriel"
    return result.status


def tet_volumes_and_ratios(points: np.ndarray, tets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Each tet's volume and circumradius / shortest edge, independently of the module's measures: numpy,
    and in rationals (rounded) for the tets too flat for floating point to tell (orientation determinant
    below 1e-4 of the longest edge from the first corner cubed: sliver tets between boundary points rounded
    off a facet, whose floating-point ratio can be off by a factor 4 or more)."""
    p = points[np.asarray(tets, dtype=np.int64).reshape(-1, 4)]
    u, v, w = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0], p[:, 3] - p[:, 0]
    det = np.einsum("ij,ij->i", u, np.cross(v, w))
    edges = [np.linalg.norm(p[:, i] - p[:, j], axis=1) for i in range(4) for j in range(i + 1, 4)]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):  # a flat tet's ratio is inf or NaN
        uu, vv, ww = (np.einsum("ij,ij->i", x, x)[:, None] for x in (u, v, w))
        center = (uu * np.cross(v, w) + vv * np.cross(w, u) + ww * np.cross(u, v)) / (2 * det[:, None])
        volumes, ratios = np.abs(det) / 6, np.linalg.norm(center, axis=1) / np.min(edges, axis=0)
        longest = np.sqrt(np.max([(x * x).sum(1) for x in (u, v, w)], axis=0))
    for row in np.flatnonzero(~(np.abs(det) >= 1e-4 * longest**3)):
        volumes[row], ratios[row] = _exact_volume_and_ratio(p[row])
    return volumes, ratios


def _exact_volume_and_ratio(corners: np.ndarray) -> tuple[float, float]:
    """A tet's volume and circumradius / shortest edge computed in rationals, then rounded (inf when flat)."""
    q = [tuple(Fraction(x) for x in row) for row in corners.tolist()]
    u, v, w = (_sub(q[k], q[0]) for k in (1, 2, 3))
    det = _dot(u, _cross(v, w))
    shortest = min(_dot(_sub(q[i], q[j]), _sub(q[i], q[j])) for i in range(4) for j in range(i + 1, 4))
    if det == 0 or shortest == 0:
        return 0.0, math.inf
    vw, wu, uv = _cross(v, w), _cross(w, u), _cross(u, v)
    offset = [(_dot(u, u) * vw[i] + _dot(v, v) * wu[i] + _dot(w, w) * uv[i]) / (2 * det) for i in range(3)]
    ratio2 = _dot(offset, offset) / shortest
    return abs(float(det / 6)), math.sqrt(float(ratio2)) if ratio2 < 2**1000 else math.inf


def enclosed_volume(plc: PLC) -> float | None:
    """The volume plc's triangles enclose, exactly (the divergence theorem in rationals, rounded), where they
    form closed consistently oriented surfaces (each directed edge once, its reverse once: the hulls, and
    families without internal facets); else None."""
    triangles = np.asarray(plc.triangles, dtype=np.int64).reshape(-1, 3)
    directed = set(map(tuple, triangles[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2).tolist()))
    if len(directed) != 3 * len(triangles) or any((b, a) not in directed for a, b in directed):
        return None
    q = [[Fraction(x) for x in row] for row in np.asarray(plc.points, dtype=np.float64).tolist()]
    total = sum((_dot(q[a], _cross(q[b], q[c])) for a, b, c in triangles.tolist()), Fraction(0))
    return abs(float(total / 6))


def check_quality_3d(plc: PLC, volume_fraction: float, radius_edge: float | None) -> str:
    """refine_quality3d of ``plc`` (the default start, the input boundary) with the volume bound
    ``volume_fraction`` times its bounding box's volume and ``radius_edge``, with hard limits; returns the
    status. Raises AssertionError when the run ends otherwise than with a status, or a converged mesh fails
    the exact re-check, moved an input point, leaves a tet over a bound that the small-angle rule did not
    leave (1e-9 relative slack for the two measures' roundings), or fills another volume than the input
    encloses (:func:`enclosed_volume`; with internal facets, refine_gabriel's certified mesh of the same
    input) beyond 1e-9 relative and the roundings of boundary points off their facets."""
    bound = volume_fraction * float(np.prod(np.ptp(plc.points, axis=0)))  # > 0: each PLC made has a volume
    result = refine_quality3d(plc, max_volume=bound, radius_edge=radius_edge,
                              max_points=MAX_POINTS_QUALITY_3D, time_limit=TIME_LIMIT_3D,
                              max_steiner=MAX_STEINER_3D)
    assert result.status in QUALITY_STATUSES_3D, result.status
    m = result.mesh
    assert np.array_equal(m.points[: len(plc.points)], plc.points), "the input points moved"
    if result.status != "converged":
        return result.status
    assert gabriel_violations(m.points, m.boundary_faces, m.segments) == 0, "converged, not Gabriel"
    volumes, ratios = tet_volumes_and_ratios(m.points, m.tets)
    kept = np.setdiff1d(np.arange(len(volumes)), result.small_angle_rows)
    assert (volumes[kept] <= bound * (1 + 1e-9)).all(), "converged, a tet over the volume bound"
    if radius_edge is not None:
        assert (ratios[kept] <= radius_edge * (1 + 1e-9)).all(), "converged, a tet over the radius-edge bound"
    reference = enclosed_volume(plc)
    if reference is None:  # internal facets: refine_gabriel's certified mesh, when it converges
        repaired = refine_gabriel(plc, max_steiner=MAX_STEINER_3D, time_limit=TIME_LIMIT_3D)
        if repaired.status == "converged":
            reference = tet_volumes_and_ratios(repaired.mesh.points, repaired.mesh.tets)[0].sum()
    if reference is not None:
        # a boundary point rounded to doubles lies up to half a unit in the last place off its facet: the
        # volumes may differ by the surface's area times that
        p = plc.points[plc.triangles]
        area = np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1).sum() / 2
        slack = 1e-9 * reference + 4 * area * np.spacing(np.abs(plc.points).max())
        assert abs(volumes.sum() - reference) <= slack, \
            f"the tets fill another volume: {volumes.sum()!r} against {reference!r} (slack {slack:.3g})"
    return result.status


# ---- runners -----------------------------------------------------------------------------------------------


def run_2d(examples: int, seed: int | None = None, outcomes: dict | None = None) -> None:
    """``examples`` random domains, each refined by a random strategy; derandomized when ``seed`` is None.
    Counts the outcomes (status or "invalid") in ``outcomes``. Raises the first failure, shrunk."""
    outcomes = {} if outcomes is None else outcomes

    @_settings(examples, seed)
    @given(domains, st.sampled_from(STRATEGIES))
    def prop(domain, strategy):
        status = check_refine_2d(domain, strategy)
        outcomes[status] = outcomes.get(status, 0) + 1

    (prop if seed is None else hypothesis_seed(seed)(prop))()


def run_3d(examples: int, seed: int | None = None, outcomes: dict | None = None) -> None:
    """``examples`` random small PLCs, refined with hard limits; as :func:`run_2d`."""
    outcomes = {} if outcomes is None else outcomes

    @_settings(examples, seed)
    @given(plcs)
    def prop(plc):
        status = check_refine_3d(plc)
        outcomes[status] = outcomes.get(status, 0) + 1

    (prop if seed is None else hypothesis_seed(seed)(prop))()


def run_quality_3d(examples: int, seed: int | None = None, outcomes: dict | None = None) -> None:
    """``examples`` random small PLCs through the 3D quality pass (a volume bound of 1/5..1/50 of the
    bounding box, with or without R = 2); as :func:`run_2d`."""
    outcomes = {} if outcomes is None else outcomes

    @_settings(examples, seed)
    @given(plcs, st.sampled_from((0.2, 0.05, 0.02)), st.sampled_from((None, 2.0)))
    def prop(plc, volume_fraction, radius_edge):
        status = check_quality_3d(plc, volume_fraction, radius_edge)
        outcomes[status] = outcomes.get(status, 0) + 1

    (prop if seed is None else hypothesis_seed(seed)(prop))()


def _settings(examples: int, seed: int | None) -> settings:
    return settings(max_examples=examples, deadline=DEADLINE_MS, derandomize=seed is None, database=None,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--minutes", type=float, default=5.0, help="run time (default 5)")
    parser.add_argument("--seed", type=int, default=0, help="first seed; each round takes the next")
    parser.add_argument("--dims", default="2,3", help="2, 3 (the Gabriel repair), 3q (the 3D quality pass) "
                        "or a comma-separated list (default 2,3)")
    parser.add_argument("--examples", type=int, default=200, help="examples per round (default 200)")
    args = parser.parse_args(argv)
    np.set_printoptions(precision=17)  # the falsifying examples' arrays as they are, to reproduce them
    runners = {"2": run_2d, "3": run_3d, "3q": run_quality_3d}
    dims = args.dims.split(",")
    end = time.monotonic() + 60 * args.minutes
    failures, seed = 0, args.seed
    outcomes: dict[str, dict[str, int]] = {d: {} for d in dims}
    while time.monotonic() < end:
        for d in dims:
            examples = args.examples if d == "2" else max(1, args.examples // 10)
            try:
                runners[d](examples, seed, outcomes[d])
            except Exception as e:  # a failure: hypothesis printed the shrunk input; keep fuzzing
                failures += 1
                print(f"FAILURE {d}D seed {seed}: {type(e).__name__}: {e}", flush=True)
                # hypothesis's falsifying example(s): several distinct failures come as an exception group
                for one in getattr(e, "exceptions", [e]):
                    if one is not e:
                        print(f"  {type(one).__name__}: {one}", flush=True)
                    for note in getattr(one, "__notes__", []):
                        print(note, flush=True)
            print(f"{d}D seed {seed}: outcomes so far {outcomes[d]}", flush=True)
        seed += 1
    print(f"{failures} failure(s) in {seed - args.seed} round(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
