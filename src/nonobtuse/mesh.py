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
    """

    points: np.ndarray
    triangles: np.ndarray
    segments: np.ndarray
    input_points: np.ndarray
    input_segments: np.ndarray
    regions: np.ndarray | None = None
    stats: dict[str, Any] = field(default_factory=dict)

    @property
    def steiner_points(self) -> int:
        return len(self.points) - len(self.input_points)
