"""The 2D input model: a planar straight-line graph (PSLG) and what lies inside it.

A :class:`Domain` is *validated* when :mod:`nonobtuse.validate` returned it (``load_domain`` and
``validate_domain`` do): ``Domain.validated`` is then True, its arrays are its own (not the caller's), and
assigning any field makes it unvalidated again (editing its arrays in place is not detected: don't). The API
entry points (``triangulate``, ``check``, ``refine``) validate an unvalidated domain once and never validate a
validated one again.

A validated domain also carries the constrained Delaunay triangulation validation built (an opaque C++
object, :func:`kept_triangulation`): the first :func:`nonobtuse.refine` of it takes that triangulation over
instead of building the same one again (the core compares the domain it triangulates with the one it is given,
exactly). It goes with the validated mark: assigning a field drops it, copies and pickles do not carry it
(refine then triangulates).
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields
from typing import Any

import numpy as np

from nonobtuse.errors import InvalidInputError


def _points(a, name: str) -> np.ndarray:
    arr = np.asarray(a, dtype=np.float64)
    if arr.size == 0:
        return np.zeros((0, 2), dtype=np.float64)
    if arr.ndim != 2 or arr.shape[1] != 2:
        raise ValueError(f"{name} must have shape (n, 2), got {arr.shape}")
    return np.ascontiguousarray(arr)


@dataclass
class SourceMap:
    """Where the items of a :class:`Domain` were read from, so that messages can name the file and line.

    file:      the file's name as given.
    first_id:  the id the file gives point 0 (Triangle files number from 0 or 1; 0 elsewhere).
    points_file: the file the points were read from when it is not ``file`` (a .poly listing no vertices takes
               them from the .node file beside it), else None.
    points, segments, holes, regions: (k,) int64 1-based line numbers, one per item (0 where unknown, e.g.
               a JSON file).
    """

    file: str
    first_id: int = 0
    points_file: str | None = None
    points: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))
    segments: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))
    holes: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))
    regions: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))


@dataclass
class Domain:
    """A 2D domain.

    points:   (n, 2) float64 coordinates.
    segments: (m, 2) int64 indices into ``points``: the boundary loops, and interior constraints (interfaces
              between materials, cracks, wells). Orientation does not matter.
    holes:    (h, 2) float64 seed points; the region around each seed, bounded by segments, is removed.
    regions:  (r, 3) float64 rows ``x, y, attribute``: the region around the seed gets the attribute
              (e.g. a material id used to pick a conductivity).
    convex_hull: when True the domain is the convex hull of the points (point sets, open boundaries);
              otherwise it is what the closed segment loops enclose.
    source:   where it came from (a file name), for messages.
    origin:   file lines of every item (set by the readers in :mod:`nonobtuse.io`), or None.
    repairs:  what validation changed (segments split at points lying on them, duplicate segments dropped),
              one sentence each; empty when the domain was used as given.
    point_markers:   (n,) int64 boundary marker per point (Triangle's vertex markers), or None.
    segment_markers: (m,) int64 boundary marker per segment (Triangle's segment markers, e.g. a boundary
              condition id), or None. Validation carries them through its repairs (a split segment's pieces
              keep its marker); refinement and the writers carry them on (:mod:`nonobtuse.markers`).
    region_max_areas: (r,) float64 the largest triangle area of each region (Triangle's regional area
              constraint, used by ``refine(..., size="regions")``; NaN where a region gives none), or None.
    validated: read-only; True when :mod:`nonobtuse.validate` returned this domain and no field was assigned
              since (see the module docstring). ``dataclasses.replace`` gives an unvalidated copy.
    """

    points: np.ndarray
    segments: np.ndarray = field(default_factory=lambda: np.zeros((0, 2), dtype=np.int64))
    holes: np.ndarray = field(default_factory=lambda: np.zeros((0, 2), dtype=np.float64))
    regions: np.ndarray = field(default_factory=lambda: np.zeros((0, 3), dtype=np.float64))
    convex_hull: bool = False
    source: str = "<memory>"
    origin: SourceMap | None = None
    repairs: list[str] = field(default_factory=list)
    point_markers: np.ndarray | None = None
    segment_markers: np.ndarray | None = None
    region_max_areas: np.ndarray | None = None
    _validated: bool = field(default=False, init=False, repr=False, compare=False)

    def __setattr__(self, name: str, value: Any) -> None:
        object.__setattr__(self, "_validated", False)  # any change voids the validator's word
        object.__setattr__(self, "_triangulation", None)  # and what it built
        object.__setattr__(self, name, value)

    def __getstate__(self) -> dict[str, Any]:
        """copy, deepcopy and pickle: everything but the kept triangulation (a C++ object)."""
        return {**self.__dict__, "_triangulation": None}

    @property
    def validated(self) -> bool:
        return self._validated

    def __post_init__(self) -> None:
        self.points = _points(self.points, "points")
        seg = np.asarray(self.segments, dtype=np.int64)
        self.segments = np.ascontiguousarray(seg.reshape(-1, 2) if seg.size else np.zeros((0, 2), np.int64))
        self.holes = _points(self.holes, "holes")
        reg = np.asarray(self.regions, dtype=np.float64)
        self.regions = np.ascontiguousarray(reg.reshape(-1, 3) if reg.size else np.zeros((0, 3), np.float64))
        self.point_markers = marker_array(self.point_markers, len(self.points), "point_markers")
        self.segment_markers = marker_array(self.segment_markers, len(self.segments), "segment_markers")
        if self.region_max_areas is not None:
            areas = np.asarray(self.region_max_areas, dtype=np.float64).ravel()
            if areas.shape != (len(self.regions),):
                raise InvalidInputError(f"region_max_areas must have one value per region "
                                        f"({len(self.regions)}), got shape {areas.shape}")
            self.region_max_areas = np.ascontiguousarray(areas)


def marker_array(a: Any, n: int, name: str) -> np.ndarray | None:
    """``a`` as (n,) int64 (a Triangle-style (n, 1) column is accepted), or None."""
    if a is None:
        return None
    arr = np.asarray(a)
    if arr.ndim == 2 and arr.shape[1] == 1:
        arr = arr[:, 0]
    integral = arr.dtype.kind in "iu" or (arr.dtype.kind == "f" and bool(np.all(arr == np.round(arr))))
    if arr.shape != (n,) or (arr.size and not integral):
        raise InvalidInputError(f"{name} must be {n} integers (one per item), got {arr.shape} {arr.dtype}")
    return np.ascontiguousarray(arr, dtype=np.int64)


def mark_validated(domain: Domain, triangulation: Any = None) -> Domain:
    """Set ``domain.validated``; only :mod:`nonobtuse.validate` calls this, on a domain it made and checked.
    The arrays and ``repairs`` become copies, so that edits of the caller's arrays cannot change what was
    checked (they stay writable: third-party code, e.g. Triangle's bindings, refuses read-only arrays).
    triangulation: the ``_core.Triangulation2`` validation built of this domain (kept for refine), or None.
    Returns ``domain``. Cost: one copy of each array."""
    for f in fields(domain):
        value = getattr(domain, f.name)
        if isinstance(value, np.ndarray):
            object.__setattr__(domain, f.name, np.array(value))
    object.__setattr__(domain, "repairs", list(domain.repairs))
    object.__setattr__(domain, "_validated", True)
    object.__setattr__(domain, "_triangulation", triangulation)
    return domain


def kept_triangulation(domain: Domain) -> Any:
    """The ``_core.Triangulation2`` validation built of ``domain`` (refine takes it over: it is empty once
    taken), or None when ``domain`` is not validated, was copied, or validation kept none."""
    return getattr(domain, "_triangulation", None) if domain.validated else None
