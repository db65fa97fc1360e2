"""The 2D output model: a triangulated domain, with the domain it came from and the statistics of how."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np


@dataclass
class Mesh:
    """A triangle mesh of a 2D domain.

    points:          (n, 2) float64; the first ``len(input_points)`` are the input points in input order,
                     Steiner points follow.
    triangles:       (m, 3) int64, counter-clockwise.
    segments:        (k, 2) int64, every constrained subsegment (boundary, interface, dangling).
    input_points:    (n0, 2) float64, the domain as given.
    input_segments:  (k0, 2) int64, the domain as given.
    regions:         (m,) float64 region attribute per triangle, or None.
    stats:           free-form statistics (refinement status, Steiner counts, timings).
    point_markers:   (n,) int64 boundary marker per point, or None.
    segment_markers: (k,) int64 boundary marker per segment, or None. Meshes made by
                     :func:`~nonobtuse.triangulate` and :func:`~nonobtuse.refine` carry the domain's
                     markers by Triangle's rules (:mod:`nonobtuse.markers`): a subsegment has its input
                     segment's marker, a Steiner point the marker of the segment it lies on.
    """

    points: np.ndarray
    triangles: np.ndarray
    segments: np.ndarray
    input_points: np.ndarray
    input_segments: np.ndarray
    regions: np.ndarray | None = None
    stats: dict[str, Any] = field(default_factory=dict)
    point_markers: np.ndarray | None = None
    segment_markers: np.ndarray | None = None

    @property
    def steiner_points(self) -> int:
        return len(self.points) - len(self.input_points)

    def to_meshio(self) -> Any:
        """This mesh as a ``meshio.Mesh``: points with z = 0, cell blocks ``triangle`` and ``line`` (the
        segments), cell data ``region`` and ``marker``, point data ``point_marker`` (those present). See
        :mod:`nonobtuse.io.meshio_formats`."""
        from nonobtuse.io.meshio_formats import to_meshio

        return to_meshio(self)

    @classmethod
    def from_meshio(cls, m: Any) -> Mesh:
        """A Mesh from a ``meshio.Mesh`` with triangle (and line) cells, planar (z = 0 or 2D points);
        regions and markers read as :meth:`to_meshio` writes them, or from ``gmsh:physical`` tags. Every
        point counts as an input point. Raises InvalidInputError for a non-planar mesh or no triangles."""
        from nonobtuse.io.meshio_formats import from_meshio

        return from_meshio(m)
