"""nonobtuse.refine: properties on random polygons, baselines, errors. The paper's figures are C++ tests
(cpp/tests/refine2d_test.cpp); the corpus is tests/test_refine_corpus.py."""

from __future__ import annotations

import json
import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import nonobtuse
from nonobtuse import Domain, InvalidInputError, _core
from refine_helpers import non_delaunay_edges, obtuse_boundary_sides

STRATEGIES = ["greedy", "project-flip", "projection"]


def convex_point_set(seed: int, n_hull: int, n_inner: int) -> Domain:
    """Integer points: n_hull on a circle of radius 1000 (rounded), n_inner inside radius ~900; the domain is
    their convex hull."""
    rng = np.random.default_rng(seed)
    a = np.sort(rng.uniform(0, 2 * np.pi, n_hull))
    r, b = np.sqrt(rng.uniform(0, 0.8, n_inner)), rng.uniform(0, 2 * np.pi, n_inner)
    pts = np.r_[np.c_[np.cos(a), np.sin(a)], np.c_[r * np.cos(b), r * np.sin(b)]]
    return Domain(points=np.unique(np.round(1000 * pts), axis=0), convex_hull=True)


def star_with_hole(seed: int, n_outer: int, n_inner: int) -> Domain:
    """A star-shaped (generally non-convex) polygon with vertex radii in [500, 1000], a square hole
    [-100, 100]^2, and n_inner points at radius in (150, 400).

    Vertex i sits at angle (2 pi / n)(i + u_i) with u_i in [0, 1/2): consecutive angles differ by at least
    pi / n, so at radius >= 500 rounding to integers (moves < 1) cannot reorder them: the polygon is simple.
    Gaps are below 3 pi / n <= 3 pi / 8, so the polygon contains the disk of radius 500 cos(3 pi / 16) > 415:
    the inner points are inside it and outside the hole (whose corners are at radius 141.5)."""
    rng = np.random.default_rng(seed)
    a = 2 * np.pi / n_outer * (np.arange(n_outer) + rng.uniform(0, 0.5, n_outer))
    rad = rng.uniform(500, 1000, n_outer)
    outer = np.round(np.c_[rad * np.cos(a), rad * np.sin(a)])
    hole = np.array([[-100, -100], [100, -100], [100, 100], [-100, 100]], dtype=float)
    r, b = rng.uniform(150, 400, n_inner), rng.uniform(0, 2 * np.pi, n_inner)
    inner = np.unique(np.round(np.c_[r * np.cos(b), r * np.sin(b)]), axis=0)
    pts = np.r_[outer, hole, inner]
    n = len(outer)
    seg = [(i, (i + 1) % n) for i in range(n)] + [(n + i, n + (i + 1) % 4) for i in range(4)]
    return Domain(points=pts, segments=np.array(seg), holes=np.array([[0.0, 0.0]]))


def check_result(res: nonobtuse.RefineResult, domain: Domain) -> None:
    s = res.stats
    assert res.status == "converged"
    assert s["obtuse_boundary_sides"] == 0
    assert obtuse_boundary_sides(res.mesh) == 0  # exact, in rationals, independent of the C++ certificate
    assert s["steiner_points"] == len(res.mesh.points) - len(domain.points)
    assert s["steiner_points"] == sum(e["steiner_points"] for e in s["edges"])
    assert s["lower_bound"] == sum(e["lower_bound"] for e in s["edges"])
    # The bound holds per input edge, for every strategy (docstring of refine: no refinement uses fewer).
    assert all(e["steiner_points"] >= e["lower_bound"] for e in s["edges"])
    assert non_delaunay_edges(res.mesh) == 0  # the output is a constrained Delaunay triangulation (exact)
    np.testing.assert_array_equal(res.mesh.points[: len(domain.points)], domain.points)


@settings(derandomize=True, deadline=None, max_examples=40)
@given(st.integers(0, 2**31), st.integers(3, 12), st.integers(0, 30))
def test_convex_point_sets_reach_the_bound_or_theorem_3(seed, n_hull, n_inner):
    domain = convex_point_set(seed, n_hull, n_inner)
    res = nonobtuse.refine(domain)
    check_result(res, domain)
    s = res.stats
    # optimal is True exactly when the bound is attained, or, without interior points, by Theorem 3.
    no_inner = all(e["edge"][0] < len(domain.points) for e in s["edges"]) and len(s["edges"]) == len(
        domain.points
    )
    assert s["optimal"] == (True if s["steiner_points"] == s["lower_bound"] or no_inner else None)


@settings(derandomize=True, deadline=None, max_examples=30)
@given(st.integers(0, 2**31), st.integers(8, 30), st.integers(0, 40), st.sampled_from(STRATEGIES))
def test_nonconvex_polygons_with_holes_verify_exactly(seed, n_outer, n_inner, strategy):
    domain = star_with_hole(seed, n_outer, n_inner)
    res = nonobtuse.refine(domain, strategy=strategy)
    check_result(res, domain)


@pytest.mark.parametrize("strategy", STRATEGIES)
def test_every_strategy_verifies_on_a_point_set(strategy):
    domain = convex_point_set(7, 10, 60)
    check_result(nonobtuse.refine(domain, strategy=strategy), domain)


def test_budget_exhausted_is_a_status():
    domain = convex_point_set(3, 8, 40)
    full = nonobtuse.refine(domain)
    assert full.stats["steiner_points"] >= 2  # so that a budget of 1 cannot suffice
    res = nonobtuse.refine(domain, max_steiner=1)
    assert res.status == "budget_exhausted" and not res.converged
    assert res.stats["steiner_points"] == 1 and res.stats["obtuse_boundary_sides"] > 0
    assert obtuse_boundary_sides(res.mesh) == res.stats["obtuse_boundary_sides"]


def test_deterministic():
    domain = star_with_hole(11, 20, 30)
    a, b = nonobtuse.refine(domain), nonobtuse.refine(domain)
    np.testing.assert_array_equal(a.mesh.points, b.mesh.points)
    np.testing.assert_array_equal(a.mesh.triangles, b.mesh.triangles)


@pytest.mark.parametrize(
    "kwargs",
    [{"strategy": "midpoint"}, {"max_steiner": -1}, {"max_steiner": 1.5}, {"max_steiner": 10**20},
     {"threads": 0}, {"threads": 1.5}, {"threads": True}],
)
def test_bad_options_are_invalid_input(kwargs):
    with pytest.raises(InvalidInputError):
        nonobtuse.refine(convex_point_set(1, 5, 5), **kwargs)


def thin_layer(seed: int, k: int, n_inner: int) -> Domain:
    """A 100 m x 1 m layer (mm): k vertices on a wavy bottom and top each, n_inner integer points between."""
    rng = np.random.default_rng(seed)
    x = np.linspace(0, 1e5, k)
    bottom, top = np.round(100 * np.sin(x / 5e3)), np.round(1000 + 100 * np.sin(x / 7e3))
    outline = np.r_[np.c_[x, bottom], np.c_[x, top][::-1]]
    px = np.round(rng.uniform(500, 1e5 - 500, n_inner))
    lo, hi = 100 * np.sin(px / 5e3) + 150, 1000 + 100 * np.sin(px / 7e3) - 150
    inner = np.unique(np.c_[px, np.round(lo + rng.uniform(0, 1, n_inner) * (hi - lo))], axis=0)
    loop = np.c_[np.arange(2 * k), (np.arange(2 * k) + 1) % (2 * k)]
    return Domain(points=np.r_[outline, inner], segments=loop)


@pytest.mark.parametrize("domain", [convex_point_set(3, 200, 40_000), thin_layer(3, 150, 40_000)],
                         ids=["convex", "thin_layer"])
def test_two_threads_give_the_same_result(domain):
    # Over 65,536 triangles the lower bound and the certificate run on two threads (threads=2, the default).
    one, two = nonobtuse.refine(domain, threads=1), nonobtuse.refine(domain)
    assert len(two.mesh.triangles) > 70_000 and two.converged and two.stats["lower_bound"] > 0
    np.testing.assert_array_equal(one.mesh.points, two.mesh.points)
    np.testing.assert_array_equal(one.mesh.triangles, two.mesh.triangles)
    assert {**one.stats, "seconds": 0} == {**two.stats, "seconds": 0}


def test_exact_checkers_detect_violations():
    # Rhombus a(0,0) b(2,-1) c(4,0) d(2,1) split by the long diagonal a-c: the angles at b and d are
    # obtuse (cos = (-2*2 + 1*1) / 5 = -0.6), so a-c is not locally Delaunay (127 + 127 > 180 degrees);
    # with a-c as the boundary segment of triangle (a, b, c) alone, b sees it at an obtuse angle.
    from nonobtuse import Mesh

    pts = np.array([[0, 0], [2, -1], [4, 0], [2, 1]], dtype=float)
    no_segments = np.zeros((0, 2), np.int64)
    both = Mesh(pts, np.array([[0, 1, 2], [0, 2, 3]]), no_segments, pts, no_segments)
    assert non_delaunay_edges(both) == 1
    one = Mesh(pts, np.array([[0, 1, 2]]), np.array([[0, 2]]), pts, no_segments)
    assert obtuse_boundary_sides(one) == 1


UNIT_SQUARE = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
SQUARE_LOOP = [(0, 1), (1, 2), (2, 3), (3, 0)]


@pytest.mark.parametrize(
    ("points", "segments", "message"),
    [
        (UNIT_SQUARE, [*SQUARE_LOOP, (2, 2)], "segment 4 (2, 2) has zero length"),  # crashed the process
        ([*UNIT_SQUARE, (np.nan, 0.5)], SQUARE_LOOP, "point 4 has a coordinate that is not finite"),
        ([*UNIT_SQUARE, (0.5, np.inf)], SQUARE_LOOP, "point 4 has a coordinate that is not finite"),
        ([*UNIT_SQUARE, (1.0, 0.0)], SQUARE_LOOP, "duplicate points"),
        (UNIT_SQUARE, [*SQUARE_LOOP, (0, 2), (1, 3)], "crosses another segment"),
    ],
)
@pytest.mark.parametrize("strategy", ["greedy", "project-flip", "projection"])
def test_unvalidated_bad_domains_raise_instead_of_crashing(points, segments, message, strategy):
    # nonobtuse.refine validates first; the C++ core, given what validation would refuse, still refuses what
    # would corrupt its triangulation.
    d = Domain(points=np.array(points, dtype=float), segments=np.array(segments))
    with pytest.raises(InvalidInputError, match=re.escape(message)):
        _core.refine(d.points, d.segments, d.holes, d.regions, False, strategy, -1, 2)
    with pytest.raises(InvalidInputError):
        nonobtuse.refine(d, strategy=strategy)


def test_edge_stats_are_made_on_access_and_read_as_a_list():
    domain = star_with_hole(3, 12, 5)
    edges = nonobtuse.refine(domain).stats["edges"]
    dicts = list(edges)
    assert len(edges) == len(dicts) == len(domain.segments)
    assert edges == dicts and edges[-1] == dicts[-1] and edges[2:5] == dicts[2:5]
    assert edges != dicts[:-1]
    assert {tuple(sorted(e["edge"])) for e in edges} == {tuple(sorted(s)) for s in domain.segments.tolist()}
    assert json.loads(json.dumps(edges, default=list)) == dicts


def test_refine_leaves_the_garbage_collector_as_it_found_it():
    import gc

    domain = convex_point_set(1, 5, 5)
    for enabled in (True, False):
        (gc.enable if enabled else gc.disable)()
        try:
            list(nonobtuse.refine(domain).stats["edges"])  # the dicts are made under a paused collector
            assert gc.isenabled() is enabled
        finally:
            gc.enable()
