"""Steiner points far from the origin: coordinates near 1e9, where doubles are 2^-23 apart, a good fraction of
a short edge. Every Steiner point stays within one such ulp of its input segment (``max_steiner_offset``, the
distance over the segment's length, recomputed here in exact rationals) and the certificate stays exact."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

import nonobtuse
from nonobtuse import Domain
from refine_helpers import obtuse_constraint_sides

ULP = 2.0**-23  # the spacing of doubles in [2^29, 2^30), around 1e9
# Convex, counter-clockwise; (7, 3) is inside the diametral disk of (0, 0)-(9, 2) (centre (4.5, 1), r^2 21.25:
# 6.25 + 4 < 21.25), whose only lattice points are its ends (gcd(9, 2) = 1).
QUAD = np.array([(0, 0), (9, 2), (7, 3), (0, 6)], dtype=np.float64)
LOOP = np.array([(0, 1), (1, 2), (2, 3), (3, 0)], dtype=np.int64)


def steiner_offsets(mesh, domain) -> list[tuple[Fraction, Fraction]]:
    """(squared distance off its input segment, squared segment length) of every Steiner point, exactly: each
    input segment's chain of subsegments is followed from one end through Steiner points to the other."""
    n = len(domain.points)
    around: dict[int, set[int]] = {}
    for a, b in np.asarray(mesh.segments).tolist():
        around.setdefault(a, set()).add(b)
        around.setdefault(b, set()).add(a)
    p = [(Fraction(x), Fraction(y)) for x, y in np.asarray(mesh.points).tolist()]
    out = []
    for a, b in domain.segments.tolist():
        stack, seen = [(a, [])], {a}
        while stack:
            v, path = stack.pop()
            if v == b:
                break
            for w in around.get(v, ()):
                if w not in seen and (w >= n or w == b):
                    seen.add(w)
                    stack.append((w, path + [w] if w >= n else path))
        else:
            raise AssertionError(f"no chain of subsegments from {a} to {b}")
        (ax, ay), (bx, by) = p[a], p[b]
        length2 = (bx - ax) ** 2 + (by - ay) ** 2
        for k in path:
            cross = (bx - ax) * (p[k][1] - ay) - (by - ay) * (p[k][0] - ax)
            out.append((cross * cross / length2, length2))
    return out


@pytest.mark.parametrize("scale", [1.0, ULP], ids=["translated", "1e-6 edges"])
@pytest.mark.parametrize("strategy", ["greedy", "project-flip", "projection"])
def test_steiner_points_stay_within_an_ulp_of_their_segment(scale, strategy):
    # translated: the quadrilateral (edges 6 to 9) moved to 1e9; 1e-6 edges: the same in units of one ulp
    # there (edges of 6 to 9.2 ulps, 0.7e-6 to 1.1e-6). Both are exactly representable.
    domain = Domain(points=1e9 + QUAD * scale, segments=LOOP)
    assert np.array_equal((domain.points - 1e9) / scale, QUAD)
    res = nonobtuse.refine(domain, strategy=strategy)
    assert res.status == "converged"
    assert obtuse_constraint_sides(res.mesh) == 0
    assert res.stats["steiner_points"] >= 1
    offsets = steiner_offsets(res.mesh, domain)
    assert len(offsets) == res.stats["steiner_points"]
    worst = max(d2 / l2 for d2, l2 in offsets)
    assert all(d2 <= Fraction(ULP) ** 2 for d2, _ in offsets)  # within one ulp of the line
    assert res.stats["max_steiner_offset"] == pytest.approx(float(worst) ** 0.5, rel=1e-6, abs=1e-300)
