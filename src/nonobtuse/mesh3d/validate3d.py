"""Validation of 3D piecewise linear complexes (PLCs): every problem is an :class:`InvalidInputError` naming
what and where (face and vertex indices, coordinates, the source file).

Geometric decisions (degenerate faces, self-intersections, coplanarity) use the exact predicates of the C++
core (CGAL exact-predicates kernel); the rest is combinatorics on the triangle list.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

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


def edge_faces(triangles: np.ndarray) -> EdgeFaces:
    """Undirected edge table of `triangles` (m, 3). Cost: O(m log m)."""
    d = directed_edges(triangles)
    edges, of_corner, count = np.unique(np.sort(d, axis=1), axis=0, return_inverse=True, return_counts=True)
    return EdgeFaces(edges.reshape(-1, 2), count, of_corner.ravel())


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
    _, first, inv = np.unique(key, axis=0, return_index=True, return_inverse=True)
    dup = np.flatnonzero(first[inv.ravel()] != np.arange(len(t)))
    if len(dup):
        g = dup[0]
        raise InvalidInputError(f"duplicate face: faces {first[inv.ravel()[g]]} and {g} both have vertices "
                                f"{sorted(t[g].tolist())}{_where(plc)}")


def check_closed(plc: PLC, ef: EdgeFaces, *, require_manifold: bool) -> None:
    """Raise on a boundary edge (one face: the surface is not closed) and, when `require_manifold`, on an edge
    in more than two faces. PLCs with several regions share internal facets: there an edge may have more."""
    open_e = np.flatnonzero(ef.count == 1)
    if len(open_e):
        a, b = ef.edges[open_e[0]]
        raise InvalidInputError(
            f"surface not closed: {len(open_e)} boundary edges, e.g. edge ({a}, {b}) of face "
            f"{ef.faces_of(open_e[0])[0]} has no neighbour; {_pt(plc, a)}, {_pt(plc, b)}{_where(plc)}")
    if require_manifold:
        many = np.flatnonzero(ef.count > 2)
        if len(many):
            a, b = ef.edges[many[0]]
            raise InvalidInputError(
                f"non-manifold edge ({a}, {b}) shared by {ef.count[many[0]]} faces "
                f"{ef.faces_of(many[0]).tolist()}; {_pt(plc, a)}, {_pt(plc, b)}{_where(plc)}")


def fans_per_vertex(plc: PLC, ef: EdgeFaces) -> np.ndarray:
    """Per vertex, the number of fans its faces form (1 for a manifold vertex, 0 for an unused one).

    The corners (face, vertex) around a vertex are joined when their faces share an edge (of exactly two
    faces) through the vertex; each group is a fan. Corner k of face f is number 3f + k. Cost: O(m log m)."""
    t = plc.triangles
    m = len(t)
    # Each triangle edge (row 3f + k: t[f,k] -> t[f,k+1]) touches corners k and k+1 of face f. Two faces
    # sharing the edge join their corners at each endpoint. Only manifold edges (two faces) matter here.
    f_of = np.arange(3 * m) // 3
    k_of = np.arange(3 * m) % 3
    r1, r2 = manifold_face_pairs(ef)
    rows, cols = [], []
    for end in (0, 1):  # both endpoints of the shared edge
        v1 = t[f_of[r1], (k_of[r1] + end) % 3]
        # the corner of face 2 at the same vertex
        k2 = np.where(t[f_of[r2], k_of[r2]] == v1, k_of[r2], (k_of[r2] + 1) % 3)
        rows.append(3 * f_of[r1] + (k_of[r1] + end) % 3)
        cols.append(3 * f_of[r2] + k2)
    row, col = np.concatenate(rows), np.concatenate(cols)
    graph = coo_matrix((np.ones(len(row)), (row, col)), shape=(3 * m, 3 * m))
    _, label = connected_components(graph, directed=False)
    vertex_of_corner = t.ravel()
    fans = np.unique(np.stack([vertex_of_corner, label], axis=1), axis=0)
    return np.bincount(fans[:, 0], minlength=len(plc.points))


def check_manifold_vertices(plc: PLC, ef: EdgeFaces) -> None:
    """Raise on a vertex whose faces form more than one fan (two surface sheets touching at a point)."""
    fans = fans_per_vertex(plc, ef)
    bad = np.flatnonzero(fans > 1)
    if len(bad):
        v = bad[0]
        raise InvalidInputError(f"non-manifold {_pt(plc, v)}: its faces form {fans[v]} separate fans "
                                f"(surface sheets touching at a point){_where(plc)}")


def orientation_flips(plc: PLC, ef: EdgeFaces) -> np.ndarray | None:
    """Per face, whether to reverse it so that every two faces sharing an edge traverse it in opposite
    directions; None when they already do. Raises on a non-orientable surface. BFS per connected component
    (faces joined by manifold edges); each component keeps the orientation of its lowest face."""
    t = plc.triangles
    m = len(t)
    d = directed_edges(t)
    r1, r2 = manifold_face_pairs(ef)
    same_direction = d[r1, 0] == d[r2, 0]  # both faces traverse the edge the same way: one must flip
    if not same_direction.any():
        return None
    f1, f2 = r1 // 3, r2 // 3
    # parity graph: traverse; flip[g] = flip[f] xor same_direction(f, g)
    graph = coo_matrix((np.ones(len(f1)), (f1, f2)), shape=(m, m)).tocsr()
    graph = graph + graph.T
    parity = {}
    for a, b, s in zip(f1.tolist(), f2.tolist(), same_direction.tolist()):
        parity[(a, b)] = parity[(b, a)] = s
    flip = np.full(m, -1, dtype=np.int8)
    for root in range(m):
        if flip[root] >= 0:
            continue
        flip[root] = 0
        nodes, pred = breadth_first_order(graph, root, directed=False, return_predecessors=True)
        for g in nodes[1:]:
            flip[g] = flip[pred[g]] ^ parity[(pred[g], g)]
    bad = np.flatnonzero((flip[f1] ^ flip[f2]) != same_direction)
    if len(bad):
        a, b = np.sort(d[r1[bad[0]]])
        raise InvalidInputError(f"non-orientable surface (Moebius-like): no consistent orientation across "
                                f"edge "
                                f"({a}, {b}) of faces {f1[bad[0]]} and {f2[bad[0]]}{_where(plc)}")
    return flip.astype(bool)


def outward_flips(plc: PLC, triangles: np.ndarray) -> np.ndarray:
    """Per face, whether to reverse it so that each connected component of the (consistently oriented) surface
    encloses a positive signed volume, i.e. faces outward. Cavities (nested shells) come out outward-facing as
    well: orient those by hand. The sign is a floating-point sum; it is a convention, not a certificate."""
    m = len(triangles)
    r1, r2 = manifold_face_pairs(edge_faces(triangles))
    graph = coo_matrix((np.ones(len(r1)), (r1 // 3, r2 // 3)), shape=(m, m))
    _, comp = connected_components(graph, directed=False)
    p = plc.points[triangles]
    vol6 = np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2]))
    comp_vol = np.bincount(comp, weights=vol6)
    return comp_vol[comp] < 0


def check_orientation(plc: PLC, ef: EdgeFaces, *, fix: bool) -> PLC:
    """Check (or, with `fix`, repair) that faces sharing an edge are consistently oriented; with `fix` the
    result also faces outward per component (see :func:`outward_flips`)."""
    flip = orientation_flips(plc, ef)
    if flip is not None and not fix:
        f = int(np.argmax(flip))
        raise InvalidInputError(
            f"inconsistent orientation: face {f} {plc.triangles[f].tolist()} is reversed relative to its "
            f"neighbours (two faces traverse a shared edge in the same direction); load with "
            f"fix_orientation=True to reorient{_where(plc)}")
    if not fix:
        return plc
    t = plc.triangles.copy()
    if flip is not None:
        t[flip] = t[flip][:, ::-1]
    out = outward_flips(plc, t)
    t[out] = t[out][:, ::-1]
    return replace(plc, triangles=t)


def check_self_intersections(plc: PLC) -> None:
    """Raise when two faces intersect other than in shared vertices or a shared edge (exact)."""
    pairs = _core.plc_self_intersections(plc.points, plc.triangles, 1)
    if len(pairs):
        i, j = pairs[0]
        raise InvalidInputError(f"self-intersection: faces {i} {plc.triangles[i].tolist()} and {j} "
                                f"{plc.triangles[j].tolist()} intersect{_where(plc)}")


def validate_plc(plc: PLC, *, require_manifold: bool = True, fix_orientation: bool = False) -> PLC:
    """Validate a triangulated PLC; return it (with faces reoriented when `fix_orientation`).

    Checks, in order: non-empty and finite coordinates; no degenerate (repeated vertex, exactly collinear) or
    duplicate faces; closed (every edge in at least two faces); with `require_manifold` (surface inputs: OFF,
    OBJ, PLY, STL) also manifold edges (exactly two faces), manifold vertices (one fan) and consistent
    orientation; finally no self-intersection (exact). PLCs with several regions (.poly/.smesh) have internal
    facets and legitimately non-manifold edges: pass require_manifold=False. Their facet orientation is free
    (TetGen ignores it), so when such a PLC is a manifold surface after all (every edge in two faces, every
    vertex one fan) it is reoriented consistently and outward; otherwise its orientation is left as given.
    Cost: O(m log m) plus the candidate pairs of the self-intersection sweep.
    """
    check_points(plc)
    check_faces(plc)
    ef = edge_faces(plc.triangles)
    check_closed(plc, ef, require_manifold=require_manifold)
    if require_manifold:
        check_manifold_vertices(plc, ef)
        plc = check_orientation(plc, ef, fix=fix_orientation)
    elif (ef.count == 2).all() and (fans_per_vertex(plc, ef) <= 1).all():
        plc = check_orientation(plc, ef, fix=True)
    check_self_intersections(plc)
    return plc
