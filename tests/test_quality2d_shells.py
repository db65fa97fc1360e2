"""Concentric shells at a junction of dangling segments in refine(min_angle=), on seeded random fans and on
clusters.poly, where eight segments radiate from input vertex 2 (index 1) inside a box, at angles down to 6.8
degrees between neighbours. A split at the junction goes to Triangle's shell (the smallest power of two at
least a third of the subsegment, from the junction), so all segments are cut at the same radii and never
encroach each other there; the greedy rule is kept for small corners between two boundary edges.

By hand: each radiating segment is 482 to 853 long, and the smallest power of two at least a third of that is
256; two neighbouring segments cut at 256 make an isosceles triangle with the junction whose base angles
(81 to 87 degrees) are acute, so [0, 256] stays: on every one of the eight segments the Steiner point nearest
the junction is at 256 from it. (Before: the greedy rule cut these segments a few units from their far ends,
and 107 vertices against Triangle's 64; now 49.)"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import nonobtuse
from nonobtuse.io import load_domain

SHARED = Path(__file__).resolve().parents[1] / ".." / "shared" / "data"
JUNCTION = 1


def clusters() -> nonobtuse.Domain:
    path = SHARED / "2d" / "clusters.poly"
    if not path.is_file():
        pytest.skip(f"{path} not present (../shared/data is the shared corpus)")
    return load_domain(path)


def distances_along(points: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Distances from a of the points strictly inside the segment a-b (off its line by at most 1e-9 of its
    length)."""
    u = (b - a) / np.linalg.norm(b - a)
    rel = points - a
    along, across = rel @ u, rel[:, 0] * u[1] - rel[:, 1] * u[0]
    inside = (np.abs(across) <= 1e-9 * np.linalg.norm(b - a)) & (along > 0) & (along < np.linalg.norm(b - a))
    return along[inside]


def test_the_radiating_segments_are_cut_at_the_same_shell() -> None:
    d = clusters()
    r = nonobtuse.refine(d, min_angle=25)
    assert r.converged and r.stats["obtuse_boundary_sides"] == 0
    added = r.mesh.points[len(d.points):]
    radiating = [s for s in d.segments.tolist() if JUNCTION in s]
    assert len(radiating) == 8
    for s in radiating:
        far = s[0] + s[1] - JUNCTION
        along = distances_along(added, d.points[JUNCTION], d.points[far])
        assert len(along) > 0, s
        np.testing.assert_allclose(along.min(), 256.0, rtol=1e-12)


def fan(seed: int, k: int) -> tuple[nonobtuse.Domain, np.ndarray]:
    """A 20 x 20 box with k dangling segments of length 2 to 5 from a junction within 4 of its centre, at
    directions at least 3 degrees apart (neighbours 3 to 60 degrees apart are likely); the far ends as
    (k, 2)."""
    rng = np.random.default_rng(seed)
    junction = rng.uniform(-4, 4, 2)
    while True:
        a = np.sort(rng.uniform(0, 2 * np.pi, k))
        if np.all(np.diff(np.r_[a, a[0] + 2 * np.pi]) > np.radians(3)):
            break
    ends = junction + rng.uniform(2, 5, k)[:, None] * np.c_[np.cos(a), np.sin(a)]
    box = [[-10, -10], [10, -10], [10, 10], [-10, 10]]
    segments = [[i, (i + 1) % 4] for i in range(4)] + [[4, 5 + i] for i in range(k)]
    return nonobtuse.Domain(points=np.r_[box, [junction], ends], segments=segments), ends


@settings(max_examples=20, deadline=20000, derandomize=True)
@given(seed=st.integers(0, 2**32 - 1), k=st.integers(2, 6))
def test_a_fan_of_dangling_segments_is_cut_at_shells(seed: int, k: int) -> None:
    """On a segment with another one at an acute angle at the junction, every split at the junction lands on a
    power of two from it: the Steiner point nearest the junction is at 2^j (to rounding). (A segment with no
    acute neighbour is halved, as Triangle does when no other segment is near.) The run converges with the
    certificate clean and every triangle outside the small angles at the bound."""
    d, ends = fan(seed, k)
    r = nonobtuse.refine(d, min_angle=25, quality_boundary="midpoints")
    assert r.converged and r.stats["obtuse_boundary_sides"] == 0
    assert r.stats["quality"]["min_angle_outside_small_angles_degrees"] >= 25 - 1e-9
    added = r.mesh.points[len(d.points):]
    toward = (ends - d.points[4]) / np.linalg.norm(ends - d.points[4], axis=1)[:, None]
    cosines = toward @ toward.T
    np.fill_diagonal(cosines, -1.0)
    for end, c in zip(ends, cosines):
        along = distances_along(added, d.points[4], end)
        if len(along) and c.max() > 1e-9:  # an acute neighbour (clear of right angles, where float could err)
            nearest = along.min()
            np.testing.assert_allclose(nearest, 2.0 ** np.round(np.log2(nearest)), rtol=1e-9)
