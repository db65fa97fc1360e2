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

import re
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from nonobtuse import _core
from nonobtuse.errors import InvalidInputError
from nonobtuse.io._files import Line, Lines
from nonobtuse.mesh3d.plc import PLC
from nonobtuse.mesh3d.validate3d import edge_faces, manifold_face_pairs, validate_plc

SURFACE_SUFFIXES = (".off", ".obj", ".ply", ".stl")
PLC_SUFFIXES = (".poly", ".smesh")


@dataclass
class Facet:
    """One input facet: loops of vertex indices (closed polygons when >= 3 vertices, a segment when 2, an
    isolated point when 1) and hole points (h, 3) inside the facet's plane."""

    loops: list[np.ndarray]
    holes: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))
    where: str = ""


@dataclass
class RawInput:
    """A parsed file before triangulation and validation."""

    points: np.ndarray
    facets: list[Facet]
    holes: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))
    regions: np.ndarray = field(default_factory=lambda: np.zeros((0, 4)))
    source: str = "<memory>"


# ---------------------------------------------------------------------------------------------------------
# Text formats (OFF, OBJ, .poly, .smesh, .node), read line by line with file:line messages


def _floats(line: Line, start: int, n: int, what: str) -> list[float]:
    line.need(start + n, what)
    return [line.float(k, what) for k in range(start, start + n)]


def _ints(line: Line, start: int, n: int, what: str) -> list[int]:
    line.need(start + n, what)
    return [line.int(k, what) for k in range(start, start + n)]


def _read_off(path: Path) -> RawInput:
    lines = Lines(path)
    head = lines.next("the OFF header")
    if not head.tokens[0].upper().endswith("OFF"):
        raise head.error(f"not an OFF file: the first line is {' '.join(head.tokens)!r}, expected 'OFF'")
    counts = head if len(head.tokens) > 1 else lines.next("the OFF counts")
    start = 1 if counts is head else 0
    nv, nf = (counts.count(start + k, "the OFF counts") for k in range(2))
    pts = [_floats(lines.next(f"vertex {i}"), 0, 3, f"vertex {i}") for i in range(nv)]
    facets = []
    for j in range(nf):
        line = lines.next(f"face {j}")
        n = line.count(0, f"the vertex count of face {j}")
        facets.append(Facet([np.array(_ints(line, 1, n, f"face {j}"), dtype=np.int64)],
                            where=f"{line.file}:{line.number}"))
    return RawInput(_points_array(pts), facets, source=str(path))


def _read_obj(path: Path) -> RawInput:
    lines = Lines(path)
    pts, facets = [], []
    while not lines.at_end():
        line = lines.next("a line")
        if line.tokens[0] == "v":
            pts.append(_floats(line, 1, 3, "a vertex"))
        elif line.tokens[0] == "f":
            line.tokens = [w.split("/")[0] for w in line.tokens]  # v/vt/vn: the vertex index
            idx = _ints(line, 1, len(line.tokens) - 1, "a face")
            # OBJ indices are 1-based; negative ones count back from the last vertex read so far
            idx = [i - 1 if i > 0 else len(pts) + i for i in idx]
            facets.append(Facet([np.array(idx, dtype=np.int64)], where=f"{line.file}:{line.number}"))
    return RawInput(_points_array(pts), facets, source=str(path))


def _read_ply(path: Path) -> RawInput:
    import meshio

    if not path.read_bytes()[:3] == b"ply":
        raise InvalidInputError(f"{path}: not a PLY file (it does not start with 'ply')")
    try:
        m = meshio.read(path, file_format="ply")
    except Exception as e:  # meshio raises bare errors of many types on malformed files
        raise InvalidInputError(f"{path}: malformed PLY file: {e}") from None
    facets = []
    for block in m.cells:
        if block.type in ("triangle", "quad", "polygon"):
            facets += [Facet([np.asarray(c, dtype=np.int64)], where=f"{path}: face") for c in block.data]
    return RawInput(np.asarray(m.points, dtype=np.float64), facets, source=str(path))


_STL_RECORD = np.dtype([("normal", "<f4", 3), ("v", "<f4", (3, 3)), ("attr", "<u2")])


def _read_stl(path: Path) -> RawInput:
    data = path.read_bytes()
    if not data.strip():
        raise InvalidInputError(f"{path}: the file is empty")
    n = int.from_bytes(data[80:84], "little") if len(data) >= 84 else -1
    if n >= 0 and 84 + 50 * n == len(data):  # binary (the header may still start with "solid")
        corners = np.frombuffer(data, dtype=_STL_RECORD, count=n, offset=84)["v"].reshape(-1, 3)
    elif data.lstrip()[:5].lower() == b"solid":
        nums = re.findall(rb"vertex\s+(\S+)\s+(\S+)\s+(\S+)", data)
        try:
            corners = np.array([[float(x) for x in row] for row in nums], dtype=np.float64).reshape(-1, 3)
        except ValueError:
            raise InvalidInputError(f"{path}: malformed ASCII STL vertex line") from None
        if len(corners) % 3:
            raise InvalidInputError(f"{path}: ASCII STL with {len(corners)} vertices, not a multiple of 3")
    else:
        raise InvalidInputError(f"{path}: not an STL file (neither binary of consistent size nor 'solid' "
                                f"ASCII)")
    points, inverse = merge_equal_points(corners.astype(np.float64))
    faces = inverse.reshape(-1, 3)
    return RawInput(points, [Facet([f]) for f in faces], source=str(path))


def merge_equal_points(corners: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Merge exactly equal rows of `corners` (k, 3) (-0.0 equals 0.0). Returns the distinct points in order of
    first occurrence and, per row, its index among them."""
    key = corners + 0.0  # -0.0 + 0.0 == +0.0: equal values get equal bytes
    _, first, inv = np.unique(key, axis=0, return_index=True, return_inverse=True)
    inv = inv.ravel()
    rank = np.empty(len(first), dtype=np.int64)
    rank[np.argsort(first, kind="stable")] = np.arange(len(first))
    return corners[np.sort(first)], rank[inv]


def _points_array(pts: list) -> np.ndarray:
    return np.array(pts, dtype=np.float64).reshape(-1, 3)


def _read_tetgen(path: Path) -> RawInput:
    """TetGen .poly (facets of polygons with facet holes) or .smesh (one polygon per facet)."""
    lines = Lines(path)
    head = lines.next("the node header")
    n_nodes = head.count(0, "the number of nodes")
    dim = head.int(1, "the dimension") if len(head.tokens) > 1 else 3
    if dim != 3:
        raise head.error(f"dimension {dim}: only 3D PLCs are read here")
    if n_nodes == 0:
        points, first_index = _read_nodes(Lines(path.with_suffix(".node")))
    else:
        points, first_index = _node_rows(lines, n_nodes)
    base = first_index if first_index in (0, 1) else 0
    n_facets = lines.next("the facet header").count(0, "the number of facets")
    read_facet = _smesh_facet if path.suffix == ".smesh" else _poly_facet
    facets = [read_facet(lines, base, j) for j in range(n_facets)]
    holes = _point_list(lines, "hole", 3)
    regions = _point_list(lines, "region", 4) if not lines.at_end() else np.zeros((0, 4))
    return RawInput(points, facets, holes, regions, source=str(path))


def _node_rows(lines: Lines, n: int) -> tuple[np.ndarray, int]:
    """n node lines "index x y z ..."; returns the coordinates and the first index (0 or 1 based)."""
    rows = [lines.next(f"node {i}").need(4, f"node {i}: an index and 3 coordinates") for i in range(n)]
    points = np.array([_floats(r, 1, 3, f"node {i}") for i, r in enumerate(rows)], dtype=np.float64)
    return points.reshape(-1, 3), (rows[0].int(0, "the node index") if rows else 0)


def _read_nodes(lines: Lines) -> tuple[np.ndarray, int]:
    head = lines.next("the node header")
    n = head.count(0, "the number of nodes")
    if n == 0:
        raise head.error("no nodes")
    return _node_rows(lines, n)


def _loop(line: Line, base: int, what: str) -> np.ndarray:
    n = line.count(0, f"the vertex count of {what}")
    return np.array(_ints(line, 1, n, what), dtype=np.int64) - base


def _smesh_facet(lines: Lines, base: int, j: int) -> Facet:
    line = lines.next(f"facet {j}")
    return Facet([_loop(line, base, f"facet {j}")], where=f"{line.file}:{line.number}")


def _poly_facet(lines: Lines, base: int, j: int) -> Facet:
    head = lines.next(f"facet {j}")
    n_polygons = head.count(0, f"the polygon count of facet {j}")
    n_holes = head.count(1, f"the hole count of facet {j}") if len(head.tokens) > 1 else 0
    loops = [_loop(lines.next(f"facet {j} polygon {k}"), base, f"facet {j} polygon {k}")
             for k in range(n_polygons)]
    holes = [_floats(lines.next(f"facet {j} hole {k}"), 1, 3, f"facet {j} hole {k}") for k in range(n_holes)]
    return Facet(loops, np.array(holes, dtype=np.float64).reshape(-1, 3), f"{head.file}:{head.number}")


def _point_list(lines: Lines, what: str, cols: int) -> np.ndarray:
    n = lines.next(f"the {what} list").count(0, f"the number of {what}s")
    rows = [_floats(lines.next(f"{what} {k}"), 1, cols, f"{what} {k}") for k in range(n)]
    return np.array(rows, dtype=np.float64).reshape(-1, cols)


READERS = {".off": _read_off, ".obj": _read_obj, ".ply": _read_ply, ".stl": _read_stl,
           ".poly": _read_tetgen, ".smesh": _read_tetgen}


# ---------------------------------------------------------------------------------------------------------
# Facets -> triangles


def _check_indices(raw: RawInput) -> None:
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
    p = points[first]
    normal = np.cross(np.roll(p, -1, axis=0) - p, p - p[0]).sum(axis=0)  # Newell: only picks the projection
    drop = int(np.argmax(np.abs(normal)))
    keep = [k for k in range(3) if k != drop]
    try:
        mesh = _core.triangulate(points[local][:, keep], np.array(segs, dtype=np.int64).reshape(-1, 2),
                                 facet.holes[:, keep], np.zeros((0, 3)), False)
    except InvalidInputError as e:
        raise InvalidInputError(f"facet {j} ({facet.where}): {e}") from None
    tri = mesh["triangles"]
    if len(mesh["points"]) != len(local) or len(tri) == 0:
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


def triangulate_facets(raw: RawInput) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(triangles (m, 3), facet_ids (m,), dangling segments (k, 2)) of all facets."""
    _check_indices(raw)
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


def merge_coplanar_facets(plc: PLC) -> PLC:
    """Give adjacent exactly coplanar triangles (sharing an edge of exactly two faces; exact orient3d == 0 of
    the four vertices) one facet id, numbered by first triangle."""
    t = plc.triangles
    ef = edge_faces(t)
    r1, r2 = manifold_face_pairs(ef)
    f1, f2 = r1 // 3, r2 // 3
    apex2 = t[f2, (r2 % 3 + 2) % 3]  # the vertex of face 2 off the shared edge
    coplanar = _core.plc_orient3d(plc.points, np.column_stack([t[f1], apex2])) == 0
    m = len(t)
    graph = coo_matrix((np.ones(coplanar.sum()), (f1[coplanar], f2[coplanar])), shape=(m, m))
    _, label = connected_components(graph, directed=False)
    _, first = np.unique(label, return_index=True)
    rank = np.empty(len(first), dtype=np.int64)
    rank[np.argsort(first)] = np.arange(len(first))
    return replace(plc, facet_ids=rank[label])


def facet_boundary_segments(triangles: np.ndarray, facet_ids: np.ndarray) -> np.ndarray:
    """Edges (k, 2), a < b, sorted, whose triangles do not all carry the same facet id."""
    ef = edge_faces(triangles)
    fid = facet_ids[np.arange(len(ef.of_corner)) // 3]
    lo = np.full(len(ef.edges), np.iinfo(np.int64).max)
    hi = np.full(len(ef.edges), np.iinfo(np.int64).min)
    np.minimum.at(lo, ef.of_corner, fid)
    np.maximum.at(hi, ef.of_corner, fid)
    return ef.edges[lo != hi]


def build_plc(raw: RawInput, *, surface: bool, fix_orientation: bool = False) -> PLC:
    """Triangulate, validate, merge coplanar facets (surfaces only) and collect segments."""
    tris, ids, dangling = triangulate_facets(raw)
    plc = PLC(raw.points, tris, ids, holes=raw.holes, regions=raw.regions, source=raw.source)
    plc = validate_plc(plc, require_manifold=surface, fix_orientation=fix_orientation)
    if surface:
        plc = merge_coplanar_facets(plc)
    segs = facet_boundary_segments(plc.triangles, plc.facet_ids)
    if len(dangling):
        segs = np.unique(np.concatenate([segs, np.sort(dangling, axis=1)]), axis=0)
    return replace(plc, segments=segs)


def load_plc(path: str | Path, *, fix_orientation: bool = False) -> PLC:
    """Read and validate a PLC from `path` (format by suffix, see the module docstring).

    Returns a PLC with the file's vertices in file order (STL: distinct vertices in order of first
    occurrence), triangulated facets, facet ids, segments, holes and regions. Surfaces must be closed,
    manifold (edges and vertices), consistently oriented (or `fix_orientation=True`: reoriented by BFS, each
    component outward), without degenerate, duplicate or self-intersecting faces. Raises InvalidInputError
    naming the problem and where. Cost: O(m log m) for m triangles plus the self-intersection sweep.
    """
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in READERS:
        raise InvalidInputError(f"{path}: unknown 3D format {suffix!r}; expected one of {sorted(READERS)}")
    if not path.exists():
        raise InvalidInputError(f"{path}: no such file")
    raw = READERS[suffix](path)
    return build_plc(raw, surface=suffix in SURFACE_SUFFIXES, fix_orientation=fix_orientation)
