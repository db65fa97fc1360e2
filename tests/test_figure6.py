"""The Figure 6 families of experiments/figure6_propagation.py (thin layers, and the fan): the input is valid
except for its one designated obtuse side, the forced intervals of the lower bound hold exactly, and every
refinement we run puts a Steiner point in each of them (so has >= n points) with an exact certificate."""

from __future__ import annotations

import sys
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

import nonobtuse
from nonobtuse.certificate import check_mesh
from nonobtuse.triangulation import triangulate
from nonobtuse.validate import validate_domain
from refine_helpers import obtuse_constraint_sides

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "experiments"))
from figure6_propagation import OUTER_VERTICES, fan_forced_intervals, figure6, figure6_fan, forced_intervals  # noqa: E402

NS = (10, 40)


def layer(domain, k: int) -> tuple[tuple[Fraction, Fraction], tuple[Fraction, Fraction]]:
    """The endpoints of e_k (k = 1..n) as exact rationals."""
    a, b = domain.segments[OUTER_VERTICES + k - 1]
    return tuple((Fraction(float(x)), Fraction(float(y))) for x, y in domain.points[[a, b]])


def strictly_in_diametral_disk(q, a, b) -> bool:
    # q sees the diameter ab at an angle > 90 degrees: (q - a).(q - b) < 0, in exact rationals
    return (q[0] - a[0]) * (q[0] - b[0]) + (q[1] - a[1]) * (q[1] - b[1]) < 0


@pytest.mark.parametrize("n", NS)
def test_input_is_valid_and_its_only_violation_is_p_under_o1(n):
    d = figure6(n)
    validate_domain(d)  # raises InvalidInputError on a bad PSLG
    offenders = check_mesh(triangulate(d)).offenders
    assert obtuse_constraint_sides(triangulate(d)) == 1  # independent rational count: one obtuse side
    (o,) = offenders
    # the lower side of e_1 = o_1 (segment 24, points 24, 25), apex p (the last point), 120 degrees:
    # p lies 1/sqrt(3) below the midpoint of a segment of half-length 1, so tan(half the angle) = sqrt(3)
    assert tuple(sorted(o.edge)) == (OUTER_VERTICES, OUTER_VERTICES + 1) and o.apex == len(d.points) - 1
    assert o.degrees == pytest.approx(120.0, abs=1e-9)


@pytest.mark.parametrize("n", NS)
def test_forced_intervals_propagate_through_every_layer(n):
    d = figure6(n)
    intervals = forced_intervals(d)
    assert len(intervals) == n
    p = tuple(Fraction(float(c)) for c in d.points[-1])
    for k, (lo, hi) in enumerate(intervals, start=1):
        (ax, y), (bx, _) = layer(d, k)
        assert ax < lo < hi < bx  # inside the open segment e_k
        # worked out by hand: I_k = [-w, w] with w = (y_1 - p_y) + (y_k - y_1) = y_k - p_y
        assert lo == -(y - p[1]) and hi == y - p[1]
        if k < n:  # (a): both ends (hence the interval: the disk is convex) strictly inside e_{k+1}'s disk
            a, b = layer(d, k + 1)
            assert all(strictly_in_diametral_disk((x, y), a, b) for x in (lo, hi))
    # the first forcing point: p strictly inside e_1's disk, its interval centred at p's foot
    assert strictly_in_diametral_disk(p, *layer(d, 1))


def assert_a_steiner_point_in_every_forced_interval(d, steiner: np.ndarray) -> None:
    """steiner: (m, 2) Steiner points of a refinement of d = figure6(n), each assigned to the layer nearest to
    it (refine may leave a point a few ulps off its segment's line when no double lies on it: 1e-16 here,
    against layer spacings of 0.3 / n)."""
    heights = d.points[OUTER_VERTICES:-1:2, 1]
    nearest = np.abs(steiner[:, 1, None] - heights[None, :]).argmin(axis=1)
    assert np.all(np.abs(steiner[:, 1] - heights[nearest]) < 1e-12)
    for k, (lo, hi) in enumerate(forced_intervals(d), start=1):
        xs = [Fraction(float(x)) for x in steiner[nearest == k - 1, 0]]
        assert any(lo <= x <= hi for x in xs), f"no Steiner point of e_{k} in I_{k}"


@pytest.mark.parametrize("n", NS)
@pytest.mark.parametrize("strategy", ["greedy", "project-flip"])
def test_every_refinement_has_a_steiner_point_in_every_forced_interval(n, strategy):
    d = figure6(n)
    res = nonobtuse.refine(d, strategy=strategy)
    assert res.converged and check_mesh(res.mesh).ok and obtuse_constraint_sides(res.mesh) == 0
    assert res.stats["steiner_points"] >= n
    assert_a_steiner_point_in_every_forced_interval(d, np.asarray(res.mesh.points)[len(d.points) :])
    if strategy == "greedy":  # one initial violation whose cascade reaches every layer
        g = res.stats["diagnosis"]
        assert g["initial_violations"] == 1 and g["propagation_depth"] == n


@pytest.mark.parametrize("n", NS)
def test_triangle_pD_also_has_a_steiner_point_in_every_forced_interval(n):
    # the lower bound holds for every method: Triangle's conforming Delaunay refinement too (its Steiner
    # points may also lie off the layers, in the outer region; only those on a layer are assigned to it)
    triangle = pytest.importorskip("triangle")
    d = figure6(n)
    out = triangle.triangulate({"vertices": d.points, "segments": d.segments}, "pDQ")
    steiner = out["vertices"][len(d.points) :]
    on_layers = (np.abs(steiner[:, 0]) < 1) & (steiner[:, 1] > 0) & (steiner[:, 1] <= d.points[-2, 1])
    assert_a_steiner_point_in_every_forced_interval(d, steiner[on_layers])


def test_forced_intervals_refuse_a_family_whose_chain_breaks():
    # Move p down to 0.9 below e_1: I_k = [-x_k, x_k], x_k = 0.9 + (k - 1) h with h = H / n = 0.0075 for
    # n = 40. I_14 (x = 0.9975, 0.9975^2 + h^2 < 1) is still inside e_15's disk, but its forced interval
    # would reach 0.9975 + h = 1.005 > 1, past the end of e_15: the induction must stop there.
    d = figure6(40)
    d.points[-1, 1] = d.points[OUTER_VERTICES, 1] - 0.9
    with pytest.raises(ValueError, match="an end of e_15 lies within h"):
        forced_intervals(d)


# ---- the fan: n arms 1/n radian apart at one junction ----


def arm_parameters(d, k: int, steiner: np.ndarray) -> list[Fraction]:
    """t of the Steiner points lying on arm k, c + t (end_k - c) with c the origin (a point is on the arm when
    it is within 1e-12 of its line: refine may leave points a few ulps off)."""
    e = d.points[k + 1]
    on = np.abs(steiner[:, 0] * e[1] - steiner[:, 1] * e[0]) < 1e-12
    ee = Fraction(float(e[0])) ** 2 + Fraction(float(e[1])) ** 2
    return [
        (Fraction(float(x)) * Fraction(float(e[0])) + Fraction(float(y)) * Fraction(float(e[1]))) / ee
        for x, y in steiner[on]
    ]


@pytest.mark.parametrize("n", NS)
def test_fan_input_has_only_constrained_angles_and_one_violation(n):
    d = figure6_fan(n)
    validate_domain(d)
    mesh = triangulate(d)
    # every triangle edge is a constraint, so every angle lies between two constraint edges
    segments = {tuple(sorted(s)) for s in d.segments.tolist()}
    edges = {tuple(sorted((int(t[i]), int(t[(i + 1) % 3])))) for t in mesh.triangles for i in range(3)}
    assert edges <= segments and len(mesh.triangles) == n  # (c, p, end_1) and (c, end_k, end_k+1), k < n
    (o,) = check_mesh(mesh).offenders
    assert obtuse_constraint_sides(mesh) == 1
    # arm 1 = (c, end_1) = points (0, 2), seen from p (point 1) at 120 degrees (r chosen by the law of sines)
    assert tuple(sorted(o.edge)) == (0, 2) and o.apex == 1 and o.degrees == pytest.approx(120.0, abs=1e-9)


@pytest.mark.parametrize("n", NS)
def test_fan_forced_intervals_reach_every_arm(n):
    d = figure6_fan(n)
    bounds = fan_forced_intervals(d)
    assert len(bounds) == n
    c = (Fraction(0), Fraction(0))
    r = Fraction(float(d.points[1, 0]))
    for k, t in enumerate(bounds, start=1):
        assert r <= t < 1  # the forced sets never shrink (docstring), and stop short of end_k
        if k < n:  # (a): the far end of (0, t] on arm k strictly inside arm k+1's disk (c is on its circle)
            e, u = (tuple(Fraction(float(x)) for x in d.points[i]) for i in (k + 1, k + 2))
            assert strictly_in_diametral_disk((t * e[0], t * e[1]), c, u)


@pytest.mark.parametrize(("n", "strategy"), [(10, "greedy"), (40, "greedy"), (10, "project-flip")])
def test_fan_refinements_have_a_steiner_point_in_every_forced_interval(n, strategy):
    d = figure6_fan(n)
    res = nonobtuse.refine(d, strategy=strategy, max_steiner=n * n + 1000)
    assert res.converged and check_mesh(res.mesh).ok and obtuse_constraint_sides(res.mesh) == 0
    assert res.stats["steiner_points"] >= n
    steiner = np.asarray(res.mesh.points)[len(d.points) :]
    for k, t_max in enumerate(fan_forced_intervals(d), start=1):
        assert any(0 < t <= t_max for t in arm_parameters(d, k, steiner)), f"no Steiner point of arm {k}"
