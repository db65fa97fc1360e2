"""Concentric shells at a junction of dangling segments in refine(min_angle=), on clusters.poly: eight
segments radiate from input vertex 2 (index 1) inside a box, at angles down to 6.8 degrees between
neighbours. A split at the junction goes to Triangle's shell (the smallest power of two at least a third of
the subsegment, from the junction), so all eight segments are cut at the same radius and never encroach each
other there; the greedy rule is kept for small corners between two boundary edges.

By hand: each radiating segment is 482 to 853 long, and the smallest power of two at least a third of that is
256; two neighbouring segments cut at 256 make an isosceles triangle with the junction whose base angles
(81 to 87 degrees) are acute, so [0, 256] stays: on every one of the eight segments the Steiner point nearest
the junction is at 256 from it. (Before: the greedy rule cut these segments a few units from their far ends,
and 107 vertices against Triangle's 64; now 49.)"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

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
