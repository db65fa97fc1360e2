"""Shared by the property tests: the triangulated convex hull of a generated point set."""

from __future__ import annotations

import numpy as np

from nonobtuse import Domain, Mesh, triangulate


def point_set_mesh(coords) -> Mesh | None:
    """The constrained Delaunay triangulation of the convex hull of ``coords`` (distinct (x, y) pairs), or
    None when they are collinear (no triangle)."""
    points = np.unique(np.asarray(coords, dtype=float), axis=0)
    if len(points) < 3 or np.linalg.matrix_rank(points[1:] - points[0]) < 2:
        return None
    return triangulate(Domain(points=points, convex_hull=True))
