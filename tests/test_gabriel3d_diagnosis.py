"""The stop diagnosis of the 3D Gabriel repair: where the encroached subsegments left at a stop lie."""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import numpy as np

from nonobtuse.mesh3d import load_plc, refine_gabriel

DATA = Path(__file__).parent / "data" / "3d"
TORUS = DATA / "mc_torus.off"  # needle facets: stops with encroached subsegments


def nearest_segment(plc, p: np.ndarray) -> tuple[int, float]:
    """Index of the input segment nearest to p and that distance (floating point)."""
    a, b = plc.points[plc.segments[:, 0]], plc.points[plc.segments[:, 1]]
    t = np.clip(((p - a) * (b - a)).sum(1) / ((b - a) ** 2).sum(1), 0.0, 1.0)
    d = np.linalg.norm(a + t[:, None] * (b - a) - p, axis=1)
    return int(np.argmin(d)), float(d.min())


def test_encroached_per_segment_counts_the_certificate_rows():
    plc = load_plc(TORUS)
    res = refine_gabriel(plc, max_steiner=1500, protected_fallback=False, control_volumes=False)
    assert res.status == "budget_exhausted" and len(res.report.segments)
    n, points = len(plc.points), res.mesh.points
    diagonal = float(np.linalg.norm(np.ptp(plc.points, axis=0)))
    expected: Counter[tuple[int, ...]] = Counter()
    # recomputed from the mesh: each encroached row's input segment and its deepest encroacher's
    for row, vertex in zip(res.report.segments, res.report.segment_vertices):
        u, w = res.mesh.segments[row]
        where = tuple(sorted(plc.segments[nearest_segment(plc, (points[u] + points[w]) / 2)[0]].tolist()))
        if vertex < n:
            where += (int(vertex),)
        else:
            g, distance = nearest_segment(plc, points[vertex])
            if distance < 1e-12 * diagonal:  # a split point of that segment (rounded onto it)
                where += tuple(sorted(plc.segments[g].tolist()))
        expected[where] += 1
    shown = res.stats["diagnosis"]["encroached_per_segment"]
    assert 0 < len(shown) <= 5
    got = {tuple(sorted(c["where"][:2])) + tuple(sorted(c["where"][2:])): c["count"] for c in shown}
    for where, count in got.items():
        assert expected[where] == count
    assert min(got.values()) >= max(c for w, c in expected.items() if w not in got)  # the top ones


def test_no_encroached_segments_after_convergence():
    res = refine_gabriel(load_plc(DATA / "cad_ramp_5deg.off"), control_volumes=False)
    assert res.status == "converged"
    assert res.stats["diagnosis"]["encroached_per_segment"] == []
