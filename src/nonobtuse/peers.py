"""Peer meshers, for comparison only: how many Steiner points they add to the same domain.

Triangle (Shewchuk; the ``triangle`` package, a development dependency) with ``-pD``: conforming Delaunay by
splitting encroached subsegments at their midpoints (concentric shells near acute input angles).
"""

from __future__ import annotations

import time

from nonobtuse.domain import Domain


def triangle_pd(domain: Domain) -> tuple[int, float]:
    """Steiner points and wall seconds of Triangle ``-pD`` on ``domain`` (``-cD`` for a point set: its convex
    hull). Raises ImportError when the ``triangle`` package is not installed."""
    import triangle

    data = {"vertices": domain.points}
    if len(domain.segments):
        data["segments"] = domain.segments
    if len(domain.holes):
        data["holes"] = domain.holes
    t0 = time.perf_counter()
    out = triangle.triangulate(data, "pDQ" if len(domain.segments) and not domain.convex_hull else "pcDQ")
    return len(out["vertices"]) - len(domain.points), time.perf_counter() - t0
