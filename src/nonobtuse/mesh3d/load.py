"""Reading 3D inputs into a validated :class:`~nonobtuse.mesh3d.plc.PLC`.

Formats (by suffix): surfaces .off, .obj, .ply (meshio), .stl (binary and ASCII; exactly equal vertices are
merged, first occurrence first); TetGen PLCs .poly and .smesh (polygonal facets with facet holes, volume
holes, regions; nodes from the sibling .node file when the node count is 0).

Polygonal facets are triangulated in 2D (the constrained Delaunay triangulation of the C++ core on the polygon
projected along its dominant normal axis, facet holes removed); a facet must be exactly planar. Triangles of
one input polygon share a facet id. For surfaces, adjacent triangles that are exactly coplanar (orient3d == 0)
are merged into one facet. PLC segments are the facet boundary edges (edges whose triangles do not all belong
to one facet) plus the dangling two-vertex polygons of .poly files.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from nonobtuse import _core
from nonobtuse.errors import InvalidInputError
from nonobtuse.io import surfaces, tetgen
from nonobtuse.io.raw3d import Facet, RawInput, TriangleFacets
from nonobtuse.mesh3d.gabriel import power_of_two_exponent
from nonobtuse.mesh3d.plc import PLC
from nonobtuse.mesh3d.validate3d import EdgeFaces, edge_faces, manifold_face_pairs, unique_rows, validate_plc

SURFACE_SUFFIXES = surfaces.SUFFIXES
PLC_SUFFIXES = tetgen.SUFFIXES
READERS = {".off": surfaces.read_off, ".obj": surfaces.read_obj, ".ply": surfaces.read_ply,
           ".stl": surfaces.read_stl, ".poly": tetgen.read_tetgen, ".smesh": tetgen.read_tetgen}


# ---------------------------------------------------------------------------------------------------------
# Facets -> triangles


def _check_finite(raw: RawInput) -> None:
    """Finite coordinates (before any arithmetic on them)."""
    bad = np.flatnonzero(~np.isfinite(raw.points).all(axis=1))
    if len(bad):
        v = int(bad[0])
        raise InvalidInputError(f"vertex {v} has a NaN or infinite coordinate {raw.points[v].tolist()} "
                                f"in {raw.source} (a number too large for float64, such as 1e400, reads as "
                                "infinity)")


def _check_points_and_indices(raw: RawInput) -> None:
    """Finite coordinates (before any arithmetic on them) and facet indices in range."""
    _check_finite(raw)
    n = len(raw.points)
    for j, f in enumerate(raw.facets):
        for loop in f.loops:
            if len(loop) and (loop.min() < 0 or loop.max() >= n):
                bad = loop[(loop < 0) | (loop >= n)][0]
                raise InvalidInputError(f"facet {j} ({f.where or raw.source}) refers to vertex {bad}, but "
                                        f"there "
                                        f"are {n} vertices")


def triangulate_facet(points: np.ndarray, facet: Facet, j: int) -> np.ndarray:
    """Triangles (t, 3) covering the polygons of one planar facet minus its holes, oriented like the facet's
    first polygon. Raises when the facet is not exactly planar or its polygons cross."""
    polygons = [lp for lp in facet.loops if len(lp) >= 3]
    first = polygons[0]
    if len(polygons) == 1 and len(first) == 3 and len(facet.loops) == 1 and not len(facet.holes):
        return first.reshape(1, 3)
    local = np.unique(np.concatenate(facet.loops))
    to_local = {v: i for i, v in enumerate(local.tolist())}
    segs = [(to_local[int(lp[i])], to_local[int(lp[(i + 1) % len(lp)])])
            for lp in facet.loops if len(lp) >= 2 for i in range(len(lp) if len(lp) >= 3 else 1)]
    p = np.ldexp(points[first], -power_of_two_exponent(points[first]))  # exact, and no overflow below
    normal = np.cross(np.roll(p, -1, axis=0) - p, p - p[0]).sum(axis=0)  # Newell: only picks the projection
    if not normal.any():  # zero area: a self-crossing polygon (a bow tie); project along a corner's normal
        corners = np.cross(p - p[0], np.roll(p, -1, axis=0) - p[0])
        normal = corners[np.argmax(np.abs(corners).max(axis=1))]
    drop = int(np.argmax(np.abs(normal)))
    keep = [k for k in range(3) if k != drop]
    try:
        mesh = _core.triangulate(points[local][:, keep], np.array(segs, dtype=np.int64).reshape(-1, 2),
                                 facet.holes[:, keep], np.zeros((0, 3)), False)
    except InvalidInputError as e:
        raise InvalidInputError(f"facet {j} ({facet.where}): {e}") from None
    tri = mesh.triangles
    if len(mesh.points) != len(local) or len(tri) == 0:
        raise InvalidInputError(f"facet {j} ({facet.where}): its polygons do not bound a planar region "
                                f"(crossing or degenerate polygons)")
    _check_planar(points, local, tri[0], j, facet)
    # The 2D triangles are counter-clockwise. Orient them like the first polygon: the triangle on the inner
    # side of the polygon's first edge (a, b) contains it as (a, b) when the polygon runs counter-clockwise.
    a, b = to_local[int(first[0])], to_local[int(first[1])]
    d = np.stack([tri, np.roll(tri, -1, axis=1)], axis=2).reshape(-1, 2)
    ccw = bool(((d[:, 0] == a) & (d[:, 1] == b)).any())
    out = local[tri]
    return out if ccw else out[:, ::-1]


def _check_planar(points: np.ndarray, local: np.ndarray, ref: np.ndarray, j: int, facet: Facet) -> None:
    a, b, c = local[ref]
    quads = np.stack([np.full(len(local), a), np.full(len(local), b), np.full(len(local), c), local], axis=1)
    off = np.flatnonzero(_core.plc_orient3d(points, quads))
    if len(off):
        v = local[off[0]]
        raise InvalidInputError(f"facet {j} ({facet.where}) is not planar: vertex {v} {points[v].tolist()} "
                                f"is "
                                f"off the plane of its vertices {a}, {b}, {c}")


def _triangle_facets(raw: RawInput) -> np.ndarray | None:
    """The facets as triangles (m, 3) when every facet is one triangle without holes (a triangle surface),
    checked as :func:`_check_points_and_indices` checks them, with the same messages, but in numpy rather than
    a Python step per facet; None for any other input."""
    facets = raw.facets
    if isinstance(facets, TriangleFacets):
        t = facets.corners
    elif not facets or any(len(f.loops) != 1 or len(f.loops[0]) != 3 or len(f.holes) for f in facets):
        return None
    else:
        t = np.array([f.loops[0] for f in facets], dtype=np.int64).reshape(-1, 3)
    if not len(t):
        return None
    _check_finite(raw)
    n = len(raw.points)
    out = (t < 0) | (t >= n)
    rows = np.flatnonzero(out.any(axis=1))
    if len(rows):
        j = int(rows[0])
        raise InvalidInputError(f"facet {j} ({facets[j].where or raw.source}) refers to vertex "
                                f"{t[j][out[j]][0]}, but there are {n} vertices")
    return t


def triangulate_facets(raw: RawInput) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(triangles (m, 3), facet_ids (m,), dangling segments (k, 2)) of all facets."""
    triangles = _triangle_facets(raw)
    if triangles is not None:  # what the loop below makes of one-triangle facets
        return triangles, np.arange(len(triangles), dtype=np.int64), np.zeros((0, 2), dtype=np.int64)
    _check_points_and_indices(raw)
    tris, ids, dangling = [], [], []
    for j, f in enumerate(raw.facets):
        dangling += [lp for lp in f.loops if len(lp) == 2]
        if any(len(lp) >= 3 for lp in f.loops):
            t = triangulate_facet(raw.points, f, j)
            tris.append(t)
            ids.append(np.full(len(t), j, dtype=np.int64))
    if not tris:
        raise InvalidInputError(f"empty input: no facet with 3 or more vertices in {raw.source}")
    seg = np.array(dangling, dtype=np.int64).reshape(-1, 2)
    return np.concatenate(tris), np.concatenate(ids), seg


def merge_coplanar_facets(plc: PLC, ef: EdgeFaces | None = None) -> PLC:
    """Give adjacent exactly coplanar triangles (sharing an edge of exactly two faces; exact orient3d == 0 of
    the four vertices) with the same facet marker one facet id, numbered by first triangle. ``ef``: the edge
    table of plc.triangles when known."""
    t = plc.triangles
    ef = edge_faces(t) if ef is None else ef
    r1, r2 = manifold_face_pairs(ef)
    f1, f2 = r1 // 3, r2 // 3
    apex2 = t[f2, (r2 % 3 + 2) % 3]  # the vertex of face 2 off the shared edge
    coplanar = _core.plc_orient3d(plc.points, np.column_stack([t[f1], apex2])) == 0
    if plc.facet_markers is not None:  # a marker boundary stays a facet boundary
        coplanar &= plc.facet_markers[plc.facet_ids[f1]] == plc.facet_markers[plc.facet_ids[f2]]
    m = len(t)
    graph = coo_matrix((np.ones(coplanar.sum()), (f1[coplanar], f2[coplanar])), shape=(m, m))
    _, label = connected_components(graph, directed=False)
    _, first = np.unique(label, return_index=True)
    rank = np.empty(len(first), dtype=np.int64)
    rank[np.argsort(first)] = np.arange(len(first))
    markers = None
    if plc.facet_markers is not None:
        markers = np.empty(len(first), dtype=np.int64)
        markers[rank[label]] = plc.facet_markers[plc.facet_ids]
    return replace(plc, facet_ids=rank[label], facet_markers=markers)


def facet_boundary_segments(triangles: np.ndarray, facet_ids: np.ndarray,
                            ef: EdgeFaces | None = None) -> np.ndarray:
    """Edges (k, 2), a < b, sorted, whose triangles do not all carry the same facet id. ``ef``: the edge table
    of ``triangles`` when known."""
    ef = edge_faces(triangles) if ef is None else ef
    fid = facet_ids[np.arange(len(ef.of_corner)) // 3]
    lo = np.full(len(ef.edges), np.iinfo(np.int64).max)
    hi = np.full(len(ef.edges), np.iinfo(np.int64).min)
    np.minimum.at(lo, ef.of_corner, fid)
    np.maximum.at(hi, ef.of_corner, fid)
    return ef.edges[lo != hi]


def build_plc(raw: RawInput, *, surface: bool) -> PLC:
    """Triangulate, validate (and orient), merge coplanar facets (surfaces only) and collect segments."""
    tris, ids, dangling = triangulate_facets(raw)
    plc = PLC(raw.points, tris, ids, holes=raw.holes, regions=raw.regions, source=raw.source,
              facet_markers=raw.facet_markers, region_volumes=raw.region_volumes)
    plc = validate_plc(plc, oriented_format=surface)
    ef = edge_faces(plc.triangles)  # merging facets keeps the triangles
    if surface:
        plc = merge_coplanar_facets(plc, ef)
    segs = facet_boundary_segments(plc.triangles, plc.facet_ids, ef)
    if len(dangling):
        segs = unique_rows(np.concatenate([segs, np.sort(dangling, axis=1)]))
    return replace(plc, segments=segs)


def load_plc(path: str | Path) -> PLC:
    """Read and validate a PLC from `path` (format by suffix, see the module docstring).

    Returns a PLC with the file's vertices in file order (STL: distinct vertices in order of first
    occurrence), triangulated facets (oriented consistently where they can be, each component outward),
    facet ids, facet markers (where the format has them), segments, holes, regions and warnings. Any PLC
    TetGen accepts loads, whatever the format: non-manifold edges and vertices, internal facets, several
    regions, dangling facets, any orientation (see :func:`~nonobtuse.mesh3d.validate3d.validate_plc`). Raises
    InvalidInputError naming the problem and where for degenerate, duplicate or self-intersecting faces,
    faces that enclose no volume, bad indices or coordinates. Cost: O(m log m) for m triangles plus the
    self-intersection sweep.
    """
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in READERS:
        raise InvalidInputError(f"{path}: unknown 3D format {suffix!r}; expected one of {sorted(READERS)}")
    if not path.exists():
        raise InvalidInputError(f"{path}: no such file")
    raw = READERS[suffix](path)
    return build_plc(raw, surface=suffix in SURFACE_SUFFIXES)
