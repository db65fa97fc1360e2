"""What a 3D input file holds before its facets are triangulated and validated: points, polygonal facets,
holes and regions (:class:`RawInput`), and the line-reading helpers the text formats share."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import overload

import numpy as np

from nonobtuse.io._files import Line


@dataclass
class Facet:
    """One input facet: loops of vertex indices (closed polygons when >= 3 vertices, a segment when 2, an
    isolated point when 1) and hole points (h, 3) inside the facet's plane."""

    loops: list[np.ndarray]
    holes: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))
    where: str = ""


class TriangleFacets(Sequence[Facet]):
    """The facets of a triangle surface without building one :class:`Facet` per face: ``corners`` (m, 3)
    int64, and the file and 1-based line of each face for messages (``file``, ``lines`` (m,) int64; lines
    None: no line numbers). Reads as a sequence of one-triangle Facets, made when asked for."""

    def __init__(self, corners: np.ndarray, file: str = "", lines: np.ndarray | None = None) -> None:
        self.corners, self.file, self.lines = corners, file, lines

    def __len__(self) -> int:
        return len(self.corners)

    @overload
    def __getitem__(self, j: int) -> Facet: ...
    @overload
    def __getitem__(self, j: slice) -> list[Facet]: ...
    def __getitem__(self, j: int | slice) -> Facet | list[Facet]:
        if isinstance(j, slice):
            return [self[k] for k in range(len(self))[j]]
        where = f"{self.file}:{int(self.lines[j])}" if self.lines is not None else ""
        return Facet([self.corners[j]], where=where)


@dataclass
class RawInput:
    """A parsed file before triangulation and validation. facet_markers: (len(facets),) int64, the marker of
    each facet (TetGen's facet boundary marker, an OBJ group, a PLY face property), or None when the file
    has none. region_volumes: (len(regions),) float64, the volume constraint of each region (the fifth number
    of a TetGen region line), NaN where none."""

    points: np.ndarray
    facets: Sequence[Facet]  # a list, or TriangleFacets for a triangle surface
    holes: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))
    regions: np.ndarray = field(default_factory=lambda: np.zeros((0, 4)))
    source: str = "<memory>"
    facet_markers: np.ndarray | None = None
    region_volumes: np.ndarray = field(default_factory=lambda: np.zeros(0))


def floats(line: Line, start: int, n: int, what: str) -> list[float]:
    line.need(start + n, what)
    return [line.float(k, what) for k in range(start, start + n)]


def ints(line: Line, start: int, n: int, what: str) -> list[int]:
    line.need(start + n, what)
    return [line.int(k, what) for k in range(start, start + n)]


def merge_equal_points(corners: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Merge exactly equal rows of `corners` (k, 3) (-0.0 equals 0.0). Returns the distinct points in order of
    first occurrence and, per row, its index among them."""
    key = corners + 0.0  # -0.0 + 0.0 == +0.0: equal values get equal bytes
    _, first, inv = np.unique(key, axis=0, return_index=True, return_inverse=True)
    inv = inv.ravel()
    rank = np.empty(len(first), dtype=np.int64)
    rank[np.argsort(first, kind="stable")] = np.arange(len(first))
    return corners[np.sort(first)], rank[inv]


def points_array(pts: list | np.ndarray) -> np.ndarray:
    return np.array(pts, dtype=np.float64).reshape(-1, 3)
