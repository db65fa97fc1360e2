"""Boundary markers carried from a domain to its mesh, by Triangle's rules.

Every output segment of a mesh (a subsegment) lies on exactly one input segment, or on none (a convex hull
edge closing a point set). The parent is found without geometry: a Steiner point lies inside one input
segment, so it has exactly two subsegments, and the chain of subsegments between two input vertices through
Steiner points is exactly one input segment (validation leaves no input point inside a segment and no two
segments between the same two points). Cost: O(m) for m triangles (which subsegments are on the
boundary) plus O(k log k) for k output segments (the chains, then one sorted look-up of their ends).

The markers follow Triangle (https://www.cs.cmu.edu/~quake/triangle.markers.html), so that a user gets from
us what ``triangle.triangulate`` would give on the same input:

- a segment: its parent's marker when nonzero; else 1 when it lies on the boundary of the triangulation (a
  triangle on one side only, holes included); else 0.
- a point: its own input marker when nonzero; else the first nonzero marker (in input order) of the input
  segments it lies on (a Steiner point lies on one); else 1 when it is a corner of a boundary edge; else 0.
"""

from __future__ import annotations

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from nonobtuse.errors import InternalError, InvalidInputError

__all__ = ["as_int32", "mesh_markers", "on_boundary", "point_markers", "segment_markers", "segment_parents"]

_INT32 = np.iinfo(np.int32)


def as_int32(markers: np.ndarray, where: str) -> np.ndarray:
    """``markers`` as int32 (Gmsh physical tags, the ``triangle`` package's arrays); InvalidInputError naming
    ``where`` and the first marker outside the 32-bit range instead of wrapping it around."""
    markers = np.asarray(markers, dtype=np.int64)
    bad = np.flatnonzero((markers < _INT32.min) | (markers > _INT32.max))
    if len(bad):
        raise InvalidInputError(f"{where}: marker {markers[bad[0]]} (index {bad[0]}) does not fit in 32 bits")
    return markers.astype(np.int32)


def _edge_keys(edges: np.ndarray, n: int) -> np.ndarray:
    e = np.asarray(edges, dtype=np.int64).reshape(-1, 2)
    return np.minimum(e[:, 0], e[:, 1]) * n + np.maximum(e[:, 0], e[:, 1])


def segment_parents(segments: np.ndarray, n_input: int, input_segments: np.ndarray) -> np.ndarray:
    """The input segment each output segment lies on.

    segments: (k, 2) int64 output subsegments; points below ``n_input`` are input points, the others Steiner
    points, each inside one input segment. input_segments: (k0, 2) int64, no two between the same points.
    Returns (k,) int64 row indices into ``input_segments``, -1 for a chain between two input points that no
    input segment joins (a convex hull edge). Raises InternalError when a Steiner point is not on exactly two
    subsegments (it would not lie inside one input segment).
    """
    segments = np.asarray(segments, dtype=np.int64).reshape(-1, 2)
    k = len(segments)
    if k == 0:
        return np.zeros(0, dtype=np.int64)
    n = int(max(segments.max() + 1, n_input))
    ends = segments.ravel()
    steiner = ends >= n_input
    # Subsegments sharing a Steiner point are links of one chain: join them.
    order = np.argsort(ends[steiner], kind="stable")
    rows = (np.flatnonzero(steiner) // 2)[order]
    if len(rows) % 2 or (len(rows) and np.any(ends[steiner][order][0::2] != ends[steiner][order][1::2])):
        raise InternalError("a Steiner point is not on exactly two subsegments")
    graph = coo_matrix((np.ones(len(rows) // 2), (rows[0::2], rows[1::2])), shape=(k, k))
    n_chains, chain = connected_components(graph, directed=False)
    # The two input-point ends of every chain, in any order.
    corner = np.flatnonzero(~steiner)
    first = np.full(n_chains, -1, dtype=np.int64)
    last = np.full(n_chains, -1, dtype=np.int64)
    first[chain[corner[::-1] // 2]] = ends[corner[::-1]]
    last[chain[corner // 2]] = ends[corner]
    if np.any(first < 0) or np.any(first == last):
        raise InternalError("a chain of subsegments does not join two input points")
    chain_keys = _edge_keys(np.column_stack([first, last]), n)
    input_keys = _edge_keys(input_segments, n)
    order = np.argsort(input_keys, kind="stable")
    at = np.minimum(np.searchsorted(input_keys[order], chain_keys), len(order) - 1)
    if len(order) == 0:
        return np.full(k, -1, dtype=np.int64)
    parent = np.where(input_keys[order[at]] == chain_keys, order[at], -1)
    return parent[chain]


def on_boundary(segments: np.ndarray, triangles: np.ndarray, n: int) -> np.ndarray:
    """(k,) bool: which ``segments`` (k, 2) have a triangle of ``triangles`` (m, 3) on one side only. Only
    triangle edges between two segment vertices are counted (every boundary edge of a constrained
    triangulation is a segment), so the cost is O(m) plus a sort of those edges (every edge of a polygon
    without interior points) and a binary search per segment."""
    segments = np.asarray(segments, dtype=np.int64).reshape(-1, 2)
    t = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    on_segment = np.zeros(n, dtype=bool)
    on_segment[segments.ravel()] = True
    corner_on_segment = on_segment[t]
    keys = []
    for i, j in ((0, 1), (1, 2), (2, 0)):
        near = np.flatnonzero(corner_on_segment[:, i] & corner_on_segment[:, j])
        keys.append(_edge_keys(np.column_stack([t[near, i], t[near, j]]), n))
    edges = np.sort(np.concatenate(keys))
    segment_keys = _edge_keys(segments, n)
    sides = np.searchsorted(edges, segment_keys, side="right") - np.searchsorted(edges, segment_keys)
    return sides == 1


def segment_markers(
    parents: np.ndarray, boundary: np.ndarray, input_markers: np.ndarray | None
) -> np.ndarray:
    """(k,) int64 markers of the output segments by Triangle's rule (module docstring). parents: (k,) from
    :func:`segment_parents`; boundary: (k,) from :func:`on_boundary`; input_markers: (k0,) or None (all 0)."""
    inherited = np.zeros(len(parents), dtype=np.int64)
    if input_markers is not None and len(parents):
        has = parents >= 0
        inherited[has] = input_markers[parents[has]]
    return np.where(inherited != 0, inherited, boundary.astype(np.int64))


def point_markers(
    n: int,
    n_input: int,
    segments: np.ndarray,
    parents: np.ndarray,
    boundary: np.ndarray,
    input_segments: np.ndarray,
    input_point_markers: np.ndarray | None,
    input_segment_markers: np.ndarray | None,
) -> np.ndarray:
    """(n,) int64 markers of the mesh's points by Triangle's rule (module docstring); the first ``n_input``
    are the input points. segments (k, 2), parents, boundary (k,): as for :func:`segment_markers`;
    input_segments (k0, 2); input_point_markers (n_input,) or None; input_segment_markers (k0,) or None."""
    out = np.zeros(n, dtype=np.int64)
    if input_segment_markers is not None:
        # Steiner points: the marker of the input segment of their subsegments.
        ends = np.asarray(segments, dtype=np.int64).ravel()
        parent = np.repeat(parents, 2)
        steiner = (ends >= n_input) & (parent >= 0)
        out[ends[steiner]] = input_segment_markers[parent[steiner]]
        # Input points: the marker of the first input segment with a nonzero marker they are an end of.
        rows = np.flatnonzero(input_segment_markers != 0)
        first = np.full(n, len(input_segment_markers), dtype=np.int64)
        for j in (0, 1):
            np.minimum.at(first, input_segments[rows, j], rows)
        marked = first < len(input_segment_markers)
        out[marked] = input_segment_markers[first[marked]]
    if input_point_markers is not None:
        own = np.flatnonzero(input_point_markers != 0)
        out[own] = input_point_markers[own]
    corner = np.zeros(n, dtype=bool)
    corner[np.asarray(segments, dtype=np.int64).reshape(-1, 2)[boundary].ravel()] = True
    out[corner & (out == 0)] = 1
    return out


def mesh_markers(mesh, domain) -> None:
    """Set ``mesh.point_markers`` and ``mesh.segment_markers`` from ``domain`` (the validated domain the mesh
    was made of: its points are the mesh's first points, its segments the input segments)."""
    n = len(mesh.points)
    parents = segment_parents(mesh.segments, len(domain.points), domain.segments)
    boundary = on_boundary(mesh.segments, mesh.triangles, n)
    mesh.segment_markers = segment_markers(parents, boundary, domain.segment_markers)
    mesh.point_markers = point_markers(
        n, len(domain.points), mesh.segments, parents, boundary, domain.segments, domain.point_markers,
        domain.segment_markers,
    )  # fmt: skip
