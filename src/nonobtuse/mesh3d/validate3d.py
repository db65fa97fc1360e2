"""Validation of 3D piecewise linear complexes (PLCs): every problem is an :class:`InvalidInputError` naming
what and where (face and vertex indices, coordinates, the source file).

Geometric decisions (degenerate faces, self-intersections, coplanarity) use the exact predicates of the C++
core (CGAL exact-predicates kernel); the rest is combinatorics on the triangle list.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import breadth_first_order, connected_components

from nonobtuse import _core
from nonobtuse.errors import InvalidInputError
from nonobtuse.mesh3d.plc import PLC


@dataclass(frozen=True)
class EdgeFaces:
    """The undirected edges of a triangle list and the faces around each.

    edges:     (e, 2) int64, a < b, sorted lexicographically.
    count:     (e,) number of triangles containing each edge.
    of_corner: (3m,) edge index of the triangle edge (t[k], t[k+1 mod 3]) of triangle j at row 3j + k.
    """

    edges: np.ndarray
    count: np.ndarray
    of_corner: np.ndarray

    def faces_of(self, e: int) -> np.ndarray:
        """Triangles containing edge e (ascending)."""
        return np.flatnonzero(self.of_corner == e) // 3


def directed_edges(triangles: np.ndarray) -> np.ndarray:
    """(3m, 2) directed edges (t0,t1), (t1,t2), (t2,t0) of each triangle, row 3j + k for triangle j."""
    t = np.asarray(triangles, dtype=np.int64)
    return np.stack([t, np.roll(t, -1, axis=1)], axis=2).reshape(-1, 2)


def unique_rows(rows: np.ndarray, **options: Any) -> Any:
    """``np.unique(rows, axis=0, **options)`` for (k, w) int64 rows of indices >= 0 (the same rows, order,
    first indices, inverse (k,) and counts), sorting one int64 key per row (``r0 * base + r1 ...``) when
    ``base ** w`` fits: numpy sorts rows as bytes, ten times slower on a million rows. Cost: O(k log k)."""
    rows = np.asarray(rows, dtype=np.int64)
    width = rows.shape[1]
    base = int(rows.max()) + 1 if rows.size else 0
    if not rows.size or int(rows.min()) < 0 or base**width >= 2**62:
        return np.unique(rows, axis=0, **options)
    key = rows[:, 0]
    for c in range(1, width):
        key = key * base + rows[:, c]
    out = np.unique(key, **options)
    keys, rest = (out[0], out[1:]) if isinstance(out, tuple) else (out, ())
    columns = []
    for _ in range(width):
        keys, column = np.divmod(keys, base)
        columns.append(column)
    unique = np.column_stack(columns[::-1])
    return (unique, *rest) if rest else unique


def edge_faces(triangles: np.ndarray) -> EdgeFaces:
    """Undirected edge table of `triangles` (m, 3). Cost: O(m log m)."""
    d = directed_edges(triangles)
    edges, of_corner, count = unique_rows(np.sort(d, axis=1), return_inverse=True, return_counts=True)
    return EdgeFaces(edges.reshape(-1, 2), count, of_corner.ravel())


def reversed_faces(ef: EdgeFaces, flip: np.ndarray) -> EdgeFaces:
    """The edge table of the same triangles with the faces where ``flip`` (m,) bool reversed: (a, b, c)
    becomes (c, b, a), whose rows 0, 1, 2 are the rows 1, 0, 2 of (a, b, c). Exactly
    ``edge_faces(reversed triangles)`` without its sort. Cost: O(m)."""
    rows = ef.of_corner.reshape(-1, 3).copy()
    rows[flip] = rows[flip][:, [1, 0, 2]]
    return EdgeFaces(ef.edges, ef.count, rows.ravel())


def manifold_face_pairs(ef: EdgeFaces) -> tuple[np.ndarray, np.ndarray]:
    """For every edge in exactly two faces, the rows (3f + k, see :func:`directed_edges`) of the edge in
    its two faces."""
    order = np.argsort(ef.of_corner, kind="stable")
    e_sorted = ef.of_corner[order]
    pair = np.flatnonzero((e_sorted[:-1] == e_sorted[1:]) & (ef.count[e_sorted[:-1]] == 2))
    return order[pair], order[pair + 1]


def _where(plc: PLC) -> str:
    return f" in {plc.source}" if plc.source else ""


def _pt(plc: PLC, v: int) -> str:
    x, y, z = plc.points[v]
    return f"vertex {v} ({x:.17g}, {y:.17g}, {z:.17g})"


def check_points(plc: PLC) -> None:
    """Raise when the PLC is empty or a coordinate is NaN or infinite."""
    if len(plc.points) == 0 or len(plc.triangles) == 0:
        raise InvalidInputError(f"empty input: no vertices or no facets{_where(plc)}")
    bad = np.flatnonzero(~np.isfinite(plc.points).all(axis=1))
    if len(bad):
        raise InvalidInputError(f"vertex {bad[0]} has a NaN or infinite coordinate {plc.points[bad[0]]}"
                                f"{_where(plc)}")


def check_faces(plc: PLC) -> None:
    """Raise on a face with a repeated vertex, an exactly collinear (zero-area) face, or a duplicate face."""
    t = plc.triangles
    rep = np.flatnonzero((t[:, 0] == t[:, 1]) | (t[:, 1] == t[:, 2]) | (t[:, 0] == t[:, 2]))
    if len(rep):
        raise InvalidInputError(f"degenerate face {rep[0]} {t[rep[0]].tolist()}: a repeated "
                                f"vertex{_where(plc)}")
    col = np.flatnonzero(_core.plc_collinear(plc.points, t))
    if len(col):
        f = col[0]
        raise InvalidInputError(f"degenerate face {f} {t[f].tolist()}: its vertices are exactly collinear "
                                f"(zero area){_where(plc)}")
    key = np.sort(t, axis=1)
    _, first, inv = unique_rows(key, return_index=True, return_inverse=True)
    dup = np.flatnonzero(first[inv.ravel()] != np.arange(len(t)))
    if len(dup):
        g = dup[0]
        raise InvalidInputError(f"duplicate face: faces {first[inv.ravel()[g]]} and {g} both have vertices "
                                f"{sorted(t[g].tolist())}{_where(plc)}")


def dangling_faces(ef: EdgeFaces, m: int) -> np.ndarray:
    """Per face (m,), whether it is dangling: peeled off by repeatedly removing faces that have an edge no
    other remaining face contains. What remains is the part of the PLC that can enclose volume (every edge in
    two or more remaining faces); the peeled faces are dangling facets (fins, open sheets).
    Cost: O(m log m) plus O(1) per peeled face."""
    count = ef.count.copy()
    order = np.argsort(ef.of_corner, kind="stable")  # corner rows grouped by edge
    start = np.searchsorted(ef.of_corner[order], np.arange(len(count) + 1))
    removed = np.zeros(m, dtype=bool)
    stack = np.unique(np.flatnonzero(count[ef.of_corner] == 1) // 3).tolist()
    while stack:
        f = stack.pop()
        if removed[f]:
            continue
        removed[f] = True
        for e in ef.of_corner[3 * f:3 * f + 3].tolist():
            count[e] -= 1
            if count[e] == 1:  # the last face left on e is now dangling too
                stack += [g for g in (order[start[e]:start[e + 1]] // 3).tolist() if not removed[g]]
    return removed


def check_bounds_volume(plc: PLC, ef: EdgeFaces) -> list[str]:
    """Raise when the faces enclose no volume (every face peels off as dangling, e.g. an open surface);
    return a warning naming the dangling faces otherwise (none when there are none)."""
    dangling = dangling_faces(ef, len(plc.triangles))
    if not dangling.any():
        return []
    open_e = np.flatnonzero(ef.count == 1)
    a, b = ef.edges[open_e[0]]
    where = (f"{len(open_e)} boundary edges, e.g. edge ({a}, {b}) of face {ef.faces_of(open_e[0])[0]} has "
             f"no neighbour; {_pt(plc, a)}, {_pt(plc, b)}")
    if dangling.all():
        raise InvalidInputError(f"surface not closed: {where}; no part of it encloses a volume{_where(plc)}")
    return [f"{int(dangling.sum())} dangling faces (not part of a closed surface; {where}): kept as dangling "
            f"facets, which bound nothing"]


def orientation_flips(plc: PLC, ef: EdgeFaces, *, warn_reversed: bool = True) -> tuple[np.ndarray, list[str]]:
    """Per face, whether to reverse it so that every two faces sharing an edge of exactly two faces traverse
    it in opposite directions, and warnings. BFS per connected component (faces joined by such edges); each
    component keeps the orientation of its lowest face. A non-orientable component (Moebius-like) keeps the
    BFS orientation, consistent except across some edges, and gets a warning naming one of them; with
    `warn_reversed`, reversed faces get one too."""
    t = plc.triangles
    m = len(t)
    d = directed_edges(t)
    r1, r2 = manifold_face_pairs(ef)
    same_direction = d[r1, 0] == d[r2, 0]  # both faces traverse the edge the same way: one must flip
    if not same_direction.any():
        return np.zeros(m, dtype=bool), []
    f1, f2 = r1 // 3, r2 // 3
    # parity graph: traverse; flip[g] = flip[f] xor same_direction(f, g)
    graph = coo_matrix((np.ones(len(f1)), (f1, f2)), shape=(m, m)).tocsr()
    graph = graph + graph.T
    parity = {}
    for a, b, s in zip(f1.tolist(), f2.tolist(), same_direction.tolist()):
        parity[(a, b)] = parity[(b, a)] = s
    flip = np.full(m, -1, dtype=np.int8)
    component = np.full(m, -1, dtype=np.int64)
    for root in range(m):
        if flip[root] >= 0:
            continue
        flip[root] = 0
        nodes, pred = breadth_first_order(graph, root, directed=False, return_predecessors=True)
        component[nodes] = root
        for g in nodes[1:]:
            flip[g] = flip[pred[g]] ^ parity[(pred[g], g)]
    # Per component, the faces in the minority orientation are the ones "reversed relative to their
    # neighbours".
    flipped = np.bincount(component, weights=flip, minlength=m)
    size = np.bincount(component, minlength=m)
    reversed_faces = int(np.minimum(flipped, size - flipped).sum())
    warnings = []
    if reversed_faces and warn_reversed:
        f = int(np.flatnonzero(flip != (flipped[component] * 2 > size[component]))[0])
        warnings.append(f"inconsistent orientation: {reversed_faces} faces (e.g. face {f} {t[f].tolist()}) "
                        f"were reversed relative to their neighbours (two faces traversed a shared edge in "
                        f"the same direction); reoriented")
    bad = np.flatnonzero((flip[f1] ^ flip[f2]) != same_direction)
    if len(bad):
        a, b = np.sort(d[r1[bad[0]]])
        warnings.append(f"non-orientable surface (Moebius-like): no consistent orientation across edge "
                        f"({a}, {b}) of faces {f1[bad[0]]} and {f2[bad[0]]}; left inconsistent there")
    return flip.astype(bool), warnings


def outward_flips(plc: PLC, triangles: np.ndarray, ef: EdgeFaces | None = None) -> np.ndarray:
    """Per face, whether to reverse it so that each connected component of the (consistently oriented)
    surface (faces joined by edges of exactly two faces) encloses a positive signed volume, i.e. faces
    outward. Cavities (nested shells) come out outward-facing as well. The sign is a floating-point sum; it is
    a convention for writers and viewers, not a certificate, and nothing downstream depends on it. It is
    computed on the points scaled by a power of two, so it does not overflow at any float64 scale. ``ef``: the
    edge table of ``triangles`` when known."""
    m = len(triangles)
    r1, r2 = manifold_face_pairs(edge_faces(triangles) if ef is None else ef)
    graph = coo_matrix((np.ones(len(r1)), (r1 // 3, r2 // 3)), shape=(m, m))
    _, comp = connected_components(graph, directed=False)
    # Scaled by a power of two so the largest |coordinate| lies in [1/2, 1): the triple products neither
    # overflow (coordinates near 1e300) nor underflow to 0 (near 1e-300); the sign is unchanged.
    largest = float(np.abs(plc.points).max()) if plc.points.size else 0.0
    scale = -int(np.frexp(largest)[1]) if np.isfinite(largest) and largest > 0 else 0
    p = np.ldexp(plc.points[triangles], scale)
    vol6 = np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2]))
    comp_vol = np.bincount(comp, weights=vol6)
    return comp_vol[comp] < 0


def orient_faces(plc: PLC, ef: EdgeFaces, *, warn_reversed: bool = True) -> tuple[PLC, list[str]]:
    """The PLC with its faces oriented consistently where they can be (see :func:`orientation_flips`) and each
    component outward (see :func:`outward_flips`), and the warnings: orientation is never refused."""
    flip, warnings = orientation_flips(plc, ef, warn_reversed=warn_reversed)
    t = plc.triangles.copy()
    t[flip] = t[flip][:, ::-1]
    out = outward_flips(plc, t, reversed_faces(ef, flip))
    t[out] = t[out][:, ::-1]
    return replace(plc, triangles=t), warnings


def check_self_intersections(plc: PLC) -> None:
    """Raise when two faces intersect other than in shared vertices or a shared edge (exact)."""
    pairs = _core.plc_self_intersections(plc.points, plc.triangles, 1)
    if len(pairs):
        i, j = pairs[0]
        raise InvalidInputError(f"self-intersection: faces {i} {plc.triangles[i].tolist()} and {j} "
                                f"{plc.triangles[j].tolist()} intersect{_where(plc)}")


def validate_plc(plc: PLC, *, oriented_format: bool = True) -> PLC:
    """Validate a triangulated PLC; return it with its faces oriented and its warnings.

    A PLC is what TetGen accepts: facets may meet along non-manifold edges (internal facets between regions,
    solids sharing an edge) and at non-manifold vertices, dangle (fins inside the volume), and need no
    consistent orientation. Errors, in order: empty input, NaN or infinite coordinates; degenerate (repeated
    vertex, exactly collinear) or duplicate faces; no enclosed volume (every face dangling, e.g. an open
    surface); self-intersections (exact). Not errors, but warnings in the returned PLC's `warnings`: dangling
    faces, faces reoriented because their neighbours disagreed, non-orientable pieces. Faces are oriented
    consistently per component (faces joined by edges of exactly two faces) and each component outward.
    oriented_format: whether the input format gives faces an orientation (surfaces: OFF, OBJ, PLY, STL).
    TetGen .poly/.smesh facets have none: pass False and they are oriented the same way, without the warning.
    Cost: O(m log m) plus the candidate pairs of the self-intersection sweep.
    """
    check_points(plc)
    check_faces(plc)
    ef = edge_faces(plc.triangles)
    warnings = check_bounds_volume(plc, ef)
    plc, oriented = orient_faces(plc, ef, warn_reversed=oriented_format)
    check_self_intersections(plc)
    return replace(plc, warnings=(*plc.warnings, *warnings, *oriented))
