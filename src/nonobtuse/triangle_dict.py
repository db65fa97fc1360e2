"""The dictionaries of the ``triangle`` package (Python bindings of Shewchuk's Triangle), in and out, so that
its users can call :func:`nonobtuse.triangulate`, :func:`nonobtuse.refine` and :func:`nonobtuse.check` on
what they already have.

Input (what ``triangle.triangulate`` takes): ``vertices`` (n, 2) floats; optional ``segments`` (k, 2)
0-based indices, ``holes`` (h, 2), ``regions`` (r, 4) rows ``x, y, attribute, max_area`` (the maximum area
is ignored: nonobtuse adds points on the boundary only; 3 columns are accepted too), ``vertex_markers`` (n,)
or (n, 1) integers, ``segment_markers`` (k,) or (k, 1) integers; ``vertex_attributes`` and
``triangle_max_area`` are accepted and ignored. A dict with ``triangles`` (m, 3) is a mesh (for
:func:`nonobtuse.check`), with ``triangle_attributes`` (m, 1) as the region of each triangle (``edges``,
``edge_markers``, ``neighbors`` and our ``stats`` are ignored).

Output (what ``triangle.triangulate`` returns): ``vertices`` (n, 2) float64 (the input vertices first, in
order), ``vertex_markers`` (n, 1) int32, ``triangles`` (m, 3) int32 counter-clockwise, ``segments`` (k, 2)
int32 (every subsegment), ``segment_markers`` (k, 1) int32, ``triangle_attributes`` (m, 1) float64 when the
input has regions, and the input's ``holes`` and ``regions`` as given. The markers follow Triangle's rules
(:mod:`nonobtuse.markers`). :func:`nonobtuse.refine` adds ``stats`` (its statistics, ``status`` included).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from nonobtuse.domain import Domain, marker_array
from nonobtuse.errors import InvalidInputError
from nonobtuse.markers import as_int32
from nonobtuse.mesh import Mesh
from nonobtuse.validate import check_coverage, validate_graph

INPUT_KEYS = {"vertices", "segments", "holes", "regions", "vertex_markers", "segment_markers"}
IGNORED_KEYS = {"vertex_attributes", "triangle_max_area"}
MESH_KEYS = {"triangles", "triangle_attributes", "stats", "edges", "edge_markers", "neighbors"}


def _array(d: dict, key: str, cols: int, dtype: type) -> np.ndarray:
    value = d.get(key)
    if value is None:
        return np.zeros((0, cols), dtype=dtype)
    arr = np.asarray(value)
    if arr.size == 0:
        return np.zeros((0, cols), dtype=dtype)
    if arr.ndim != 2 or arr.shape[1] != cols:
        raise InvalidInputError(f"triangle dict: '{key}' must have shape (k, {cols}), got {arr.shape}")
    if dtype is np.int64 and arr.dtype.kind not in "iu":
        raise InvalidInputError(f"triangle dict: '{key}' must hold integers, got {arr.dtype}")
    if dtype is np.float64 and arr.dtype.kind not in "iuf":
        raise InvalidInputError(f"triangle dict: '{key}' must hold numbers, got {arr.dtype}")
    return np.ascontiguousarray(arr, dtype=dtype)


def _check_keys(d: Any, allowed: set[str]) -> None:
    if not isinstance(d, dict):
        raise InvalidInputError(f"expected a Domain, a Mesh or a triangle dict, got {type(d).__name__}")
    if "vertices" not in d:
        raise InvalidInputError("triangle dict: 'vertices' is missing")
    unknown = sorted(set(d) - allowed - IGNORED_KEYS)
    if unknown:
        raise InvalidInputError(f"triangle dict: unknown key(s) {unknown} (known: {sorted(allowed)})")


def domain_from_dict(d: dict[str, Any]) -> Domain:
    """A :class:`Domain` (not yet validated) from a ``triangle.triangulate`` input dict (module docstring).
    Raises InvalidInputError for a missing ``vertices``, unknown keys or wrong shapes."""
    _check_keys(d, INPUT_KEYS)
    regions = d.get("regions")
    regions = None if regions is None else np.asarray(regions)
    if regions is not None and regions.size and (regions.ndim != 2 or regions.shape[1] not in (3, 4)):
        raise InvalidInputError(f"triangle dict: 'regions' must have shape (r, 4) or (r, 3): {regions.shape}")
    return Domain(
        _array(d, "vertices", 2, np.float64),
        _array(d, "segments", 2, np.int64),
        _array(d, "holes", 2, np.float64),
        np.zeros((0, 3)) if regions is None or regions.size == 0 else regions[:, :3],
        source="<triangle dict>",
        point_markers=d.get("vertex_markers"),
        segment_markers=d.get("segment_markers"),
        region_max_areas=regions[:, 3] if regions is not None and regions.size and regions.shape[1] == 4
        else None,
    )


def validated_domain(d: dict[str, Any]) -> Domain:
    """:func:`domain_from_dict`, validated as :func:`nonobtuse.io.load_domain` validates a file (the
    convex hull closes a point set or segments enclosing no area, as with Triangle's ``-c``)."""
    return check_coverage(validate_graph(domain_from_dict(d)), require_closed=True, decide_convex_hull=True)


def mesh_from_dict(d: dict[str, Any]) -> Mesh:
    """A :class:`Mesh` from a ``triangle.triangulate`` output dict (``vertices``, ``triangles``, optional
    ``segments``, markers, ``triangle_attributes``). Every vertex counts as an input vertex. Raises
    InvalidInputError for wrong shapes or indices out of range."""
    _check_keys(d, INPUT_KEYS | MESH_KEYS)
    points = _array(d, "vertices", 2, np.float64)
    triangles = _array(d, "triangles", 3, np.int64)
    segments = _array(d, "segments", 2, np.int64)
    for key, idx in (("triangles", triangles), ("segments", segments)):
        if idx.size and (idx.min() < 0 or idx.max() >= len(points)):
            raise InvalidInputError(f"triangle dict: '{key}' refers to a vertex that does not exist")
    attributes = d.get("triangle_attributes")
    regions = None
    if attributes is not None:
        regions = np.asarray(attributes, dtype=np.float64).reshape(len(triangles), -1)[:, 0]
    return Mesh(
        points, triangles, segments, points.copy(), segments.copy(), regions,
        point_markers=marker_array(d.get("vertex_markers"), len(points), "vertex_markers"),
        segment_markers=marker_array(d.get("segment_markers"), len(segments), "segment_markers"),
    )  # fmt: skip


def mesh_to_dict(mesh: Mesh, given: dict[str, Any]) -> dict[str, Any]:
    """The ``triangle.triangulate`` output dict of ``mesh`` (module docstring); ``given`` is the input dict,
    whose ``holes`` and ``regions`` are passed on as Triangle does."""
    out: dict[str, Any] = {"vertices": np.ascontiguousarray(mesh.points, dtype=np.float64)}
    if mesh.point_markers is not None:
        out["vertex_markers"] = as_int32(mesh.point_markers, "vertex_markers").reshape(-1, 1)
    out["triangles"] = mesh.triangles.astype(np.int32).reshape(-1, 3)
    out["segments"] = mesh.segments.astype(np.int32).reshape(-1, 2)
    if mesh.segment_markers is not None:
        out["segment_markers"] = as_int32(mesh.segment_markers, "segment_markers").reshape(-1, 1)
    if mesh.regions is not None and given.get("regions") is not None and np.size(given["regions"]):
        out["triangle_attributes"] = np.asarray(mesh.regions, dtype=np.float64).reshape(-1, 1)
    for key in ("holes", "regions"):
        if given.get(key) is not None:
            out[key] = given[key]
    return out
