"""refine's ``quality_boundary``: Triangle's midpoints and shells, the paper's minimal boundary first, or the
better of the two ("best", the default), which never has more boundary Steiner points than the midpoints run,
nor, when it differs, more vertices; the certificate checked exactly on every result."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import nonobtuse
from nonobtuse import Domain, InvalidInputError
from refine_helpers import SHARED, obtuse_constraint_sides, star


def channel(seed: int, k: int) -> Domain:
    """cdt_ditch's shape: two walls of k + 1 vertices (x about -15 and 16, y from -36 to 40, jittered) joined
    at the bottom and the top through the ends of an interface at x = 1 (the minimal boundary often wins
    here)."""
    rng = np.random.default_rng(seed)
    y = np.linspace(-36, 40, k + 1)
    walls = [np.c_[x + rng.uniform(-1.5, 1.5, k + 1), y + np.r_[0, rng.uniform(-3, 3, k - 1), 0]]
             for x in (16, -15)]
    n = k + 1
    bottom, top = 2 * n, 2 * n + 1
    segments = [(i, i + 1) for i in range(k)] + [(n + i, n + i + 1) for i in range(k)]
    segments += [(0, bottom), (bottom, n), (k, top), (top, n + k), (bottom, top)]
    return Domain(points=np.r_[walls[0], walls[1], [[1.0, -36.0], [1.0, 40.0]]], segments=segments)


def boundary_points(res: nonobtuse.RefineResult, n_input: int) -> int:
    """Output vertices beyond the input's on output segments (as bench_quality2d counts them)."""
    count = int(np.count_nonzero(np.unique(res.mesh.segments) >= n_input))
    assert count == res.stats["steiner_points"]
    return count


@settings(max_examples=30, deadline=20000, derandomize=True)
@given(seed=st.integers(0, 2**32 - 1), k=st.integers(2, 5), family=st.sampled_from(["star", "channel"]),
       min_angle=st.sampled_from([20.0, 25.0, 30.0]))
def test_best_is_never_worse_than_midpoints(seed: int, k: int, family: str, min_angle: float) -> None:
    d = star(seed, 3 * k) if family == "star" else channel(seed, k)
    n = len(d.points)
    best = nonobtuse.refine(d, min_angle=min_angle)
    mid = nonobtuse.refine(d, min_angle=min_angle, quality_boundary="midpoints")
    assert mid.stats["quality"]["boundary"] == "midpoints"
    for res in (best, mid):
        assert obtuse_constraint_sides(res.mesh) == 0 or not res.converged
    if mid.converged:
        assert best.converged
        assert boundary_points(best, n) <= boundary_points(mid, n)
    if best.stats["quality"]["boundary"] == "minimal":
        minimal = nonobtuse.refine(d, min_angle=min_angle, quality_boundary="minimal")
        assert len(best.mesh.points) == len(minimal.mesh.points)
        assert boundary_points(best, n) < boundary_points(mid, n) or not mid.converged
        assert len(best.mesh.points) <= len(mid.mesh.points) or not mid.converged
    else:
        assert np.array_equal(best.mesh.points, mid.mesh.points)


def test_unknown_quality_boundary_is_refused() -> None:
    with pytest.raises(InvalidInputError, match="unknown quality_boundary 'shells'"):
        nonobtuse.refine(star(1, 6), min_angle=25, quality_boundary="shells")


@pytest.mark.skipif(not (SHARED / "2d" / "cdt_ditch.poly").exists(), reason="../shared/data/2d is absent")
@pytest.mark.parametrize("degrees", [25.0, 30.0])
def test_cdt_ditch_takes_the_minimal_boundary(degrees: float) -> None:
    """cdt_ditch's interface (x = 1.27, y from -36.1 to 40.6) needs 2 points for the certificate alone
    (its lower bound); the midpoints put 3 there (as Triangle -pq25D does), the minimal boundary 2 and then no
    interior point breaks them: 13 vertices against 14."""
    from nonobtuse.io import load_domain

    d = load_domain(SHARED / "2d" / "cdt_ditch.poly")
    best = nonobtuse.refine(d, min_angle=degrees)
    mid = nonobtuse.refine(d, min_angle=degrees, quality_boundary="midpoints")
    assert best.converged and best.stats["quality"]["boundary"] == "minimal"
    assert obtuse_constraint_sides(best.mesh) == 0
    assert best.stats["quality"]["min_angle_outside_small_angles_degrees"] >= degrees - 1e-9
    assert boundary_points(best, len(d.points)) == best.stats["lower_bound"] == 2
    assert boundary_points(mid, len(d.points)) == 3 and len(best.mesh.points) < len(mid.mesh.points)
