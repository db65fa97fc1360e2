"""Peer meshers, for comparison only: how many Steiner points they add to the same domain.

Triangle (Shewchuk; the ``triangle`` package, a development dependency) with ``-pD``: conforming Delaunay by
splitting encroached subsegments at their midpoints (concentric shells near acute input angles); with
``-pqXD`` its quality refinement as well (:func:`triangle_quality`).
"""

from __future__ import annotations

import time
from typing import Any

import numpy as np

from nonobtuse.domain import Domain


def _triangulate(domain: Domain, switches: str) -> tuple[dict[str, Any], float]:
    """Triangle's output dict for ``domain`` with ``p`` (``pc`` for a point set), ``switches`` and ``Q``, and
    its wall seconds. Raises ImportError when the ``triangle`` package is not installed."""
    import triangle

    data = {"vertices": domain.points}
    if len(domain.segments):
        data["segments"] = domain.segments
    if len(domain.holes):
        data["holes"] = domain.holes
    hull = "c" if domain.convex_hull or not len(domain.segments) else ""
    t0 = time.perf_counter()
    out = triangle.triangulate(data, f"p{hull}{switches}Q")
    return out, time.perf_counter() - t0


def triangle_pd(domain: Domain) -> tuple[int, float]:
    """Steiner points and wall seconds of Triangle ``-pD`` on ``domain`` (``-cD`` for a point set: its convex
    hull). Raises ImportError when the ``triangle`` package is not installed."""
    out, seconds = _triangulate(domain, "D")
    return len(out["vertices"]) - len(domain.points), seconds


def smallest_angle(points: np.ndarray, triangles: np.ndarray) -> float:
    """The smallest angle (degrees, floating point) of the triangles (m, 3) int of points (n, 2) float64; 180
    when there is none."""
    p = points[triangles]
    best = 180.0
    for i in range(3):
        u, w = p[:, (i + 1) % 3] - p[:, i], p[:, (i + 2) % 3] - p[:, i]
        cross = np.abs(u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0])
        best = min(best, float(np.degrees(np.arctan2(cross, np.einsum("ij,ij->i", u, w))).min(initial=180.0)))
    return best


def triangle_quality(domain: Domain, min_angle: float) -> dict[str, Any]:
    """Triangle ``-pq<min_angle>D`` on ``domain``: ``vertices`` (its output's), ``boundary_steiner`` (its
    vertices on output segments beyond the input's), ``min_angle`` (its smallest angle, degrees) and
    ``seconds``. Raises ImportError when the ``triangle`` package is not installed."""
    out, seconds = _triangulate(domain, f"q{min_angle:g}D")
    on_segments = np.unique(out["segments"]) if "segments" in out else np.zeros(0, int)
    return {"vertices": len(out["vertices"]),
            "boundary_steiner": int(np.count_nonzero(on_segments >= len(domain.points))),
            "min_angle": smallest_angle(out["vertices"], out["triangles"]), "seconds": seconds}
