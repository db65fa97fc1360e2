"""Random star polygons as in ``experiments/bench_scaling`` (vertices at random angles, radii in [0.5, 1]):
spiky polygons where the disk of one edge holds many other edges, the case the disk walks' obstacle pruning
and the orientation-only shading test were made for. Every result is certified by the rational oracle of
``refine_helpers`` (independent of the C++ certificate), and the lower bound (exact sight) holds per edge."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

import nonobtuse
from nonobtuse import Domain
from refine_helpers import obtuse_boundary_sides


def spiky_star(seed: int, n: int) -> Domain:
    """n vertices at sorted random angles and radii in [0.5, 1] (bench_scaling's ``star``), no interior
    points.
    Distinct angles with a positive radius give a simple polygon (star-shaped from the origin)."""
    rng = np.random.default_rng(seed)
    a = np.unique(rng.uniform(0, 2 * np.pi, n))
    r = rng.uniform(0.5, 1.0, len(a))
    k = len(a)
    return Domain(points=np.c_[r * np.cos(a), r * np.sin(a)],
                  segments=np.c_[np.arange(k), (np.arange(k) + 1) % k])


@settings(derandomize=True, deadline=2000, max_examples=25)
@given(st.integers(0, 2**31), st.integers(10, 150))
def test_spiky_star_polygons_are_certified_exactly(seed, n):
    domain = spiky_star(seed, n)
    res = nonobtuse.refine(domain)
    assert res.status == "converged"
    assert res.stats["obtuse_boundary_sides"] == 0
    assert obtuse_boundary_sides(res.mesh) == 0  # exact, in rationals
    assert all(e["steiner_points"] >= e["lower_bound"] for e in res.stats["edges"])


def spiky_star_with_holes(seed: int, n: int, k: int) -> Domain:
    """``spiky_star`` with ``k`` small random spiky holes (star polygons of 8 vertices, radii in [0.02, 0.05])
    at radius 0.36, inside the star's kernel (every vertex has radius >= 0.5), spaced so that they do not
    meet: their edges are obstacles of the walks from the star's long edges."""
    rng = np.random.default_rng(seed)
    outer = spiky_star(seed, n)
    points, segments, holes = [outer.points], [outer.segments], []
    base = len(outer.points)
    for j in range(k):
        centre = 0.36 * np.array([np.cos(2 * np.pi * j / k), np.sin(2 * np.pi * j / k)])
        a = 2 * np.pi * (np.arange(8) + rng.uniform(0, 0.5, 8)) / 8  # gaps below pi: the centre is inside
        r = rng.uniform(0.02, 0.05, 8)
        points.append(centre + np.c_[r * np.cos(a), r * np.sin(a)])
        segments.append(base + np.c_[np.arange(8), (np.arange(8) + 1) % 8])
        holes.append(centre)
        base += 8
    return Domain(points=np.vstack(points), segments=np.vstack(segments), holes=np.array(holes))


@settings(derandomize=True, deadline=4000, max_examples=15)
@given(st.integers(0, 2**31), st.integers(20, 150), st.integers(1, 5))
def test_spiky_stars_with_holes_are_certified_exactly(seed, n, k):
    domain = spiky_star_with_holes(seed, n, k)
    res = nonobtuse.refine(domain)
    assert res.status == "converged"
    assert obtuse_boundary_sides(res.mesh) == 0  # exact, in rationals
    assert all(e["steiner_points"] >= e["lower_bound"] for e in res.stats["edges"])
    assert len(res.stats["edges"]) == len(domain.segments)
